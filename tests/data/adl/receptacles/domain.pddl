; ALFRED-style receptacles, written for guided-lfd's tests: an agent walks
; between receptacles, takes objects out (an openable receptacle must be
; open), puts them in, and heats whatever is inside the microwave at once.
(define (domain receptacles)
  (:requirements :adl)
  (:types agent receptacle thing - object)
  (:predicates (agent-at ?a - agent ?r - receptacle)
               (in ?t - thing ?r - receptacle)
               (holds ?a - agent ?t - thing)
               (openable ?r - receptacle)
               (opened ?r - receptacle)
               (microwave ?r - receptacle)
               (hot ?t - thing))

  (:action goto
    :parameters (?a - agent ?from ?to - receptacle)
    :precondition (and (agent-at ?a ?from) (not (= ?from ?to)))
    :effect (and (agent-at ?a ?to) (not (agent-at ?a ?from))))

  (:action open
    :parameters (?a - agent ?r - receptacle)
    :precondition (and (agent-at ?a ?r) (openable ?r) (not (opened ?r)))
    :effect (opened ?r))

  (:action close
    :parameters (?a - agent ?r - receptacle)
    :precondition (and (agent-at ?a ?r) (opened ?r))
    :effect (not (opened ?r)))

  (:action take
    :parameters (?a - agent ?t - thing ?r - receptacle)
    :precondition (and (agent-at ?a ?r) (in ?t ?r)
                       (forall (?u - thing) (not (holds ?a ?u)))
                       (imply (openable ?r) (opened ?r)))
    :effect (and (holds ?a ?t) (not (in ?t ?r))))

  (:action put
    :parameters (?a - agent ?t - thing ?r - receptacle)
    :precondition (and (agent-at ?a ?r) (holds ?a ?t) (or (not (openable ?r)) (opened ?r)))
    :effect (and (in ?t ?r) (not (holds ?a ?t))))

  (:action heat
    :parameters (?a - agent ?r - receptacle)
    :precondition (and (agent-at ?a ?r) (microwave ?r) (not (opened ?r)))
    :effect (forall (?t - thing) (when (in ?t ?r) (hot ?t)))))
