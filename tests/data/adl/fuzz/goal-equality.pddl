; Found by tests/test_fuzz_adl.py: a STRIPS domain with :equality whose problem's goal compares objects.
(define (domain goal-equality)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types thing)
  (:constants a b - thing)
  (:predicates (done ?x - thing))
  (:action finish
    :parameters (?x - thing)
    :precondition (not (= ?x a))
    :effect (done ?x)))
