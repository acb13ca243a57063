; Taking an image uses up a camera's calibration and nothing calibrates: two
; calibrated cameras take at most two images.  Every pair of images is
; reachable (h^2 cannot refute three); the operator-counting program can.
(define (domain cameras)
  (:requirements :strips :typing)
  (:types camera target)
  (:predicates (calibrated ?c - camera) (have-image ?t - target))
  (:action take-image
    :parameters (?c - camera ?t - target)
    :precondition (calibrated ?c)
    :effect (and (have-image ?t) (not (calibrated ?c)))))
