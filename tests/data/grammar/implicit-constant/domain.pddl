; An object the actions use that the domain does not declare (older IPC
; tyreworld's 'wrench'): only the problem declares it.
(define (domain garage)
  (:requirements :strips :typing)
  (:types tool wheel - object)
  (:predicates (have ?t - tool) (in-boot ?t - tool) (loose ?w - wheel) (tight ?w - wheel))

  (:action fetch
    :parameters ()
    :precondition (in-boot wrench)
    :effect (and (have wrench) (not (in-boot wrench))))

  (:action undo
    :parameters (?w - wheel)
    :precondition (and (have wrench) (tight ?w))
    :effect (and (loose ?w) (not (tight ?w)))))
