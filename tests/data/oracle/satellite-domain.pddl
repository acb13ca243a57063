; A one-satellite cut of IPC satellite, without the robot's calibrate skill:
; switch_on deletes calibrated, so an instrument calibrated but not powered on
; can never take an image (the h^2 pair check proves it without a search).
(define (domain satellite-mini)
  (:requirements :strips :typing)
  (:types satellite instrument direction mode)
  (:predicates (on_board ?i - instrument ?s - satellite) (supports ?i - instrument ?m - mode)
               (pointing ?s - satellite ?d - direction) (power_avail ?s - satellite)
               (power_on ?i - instrument) (calibrated ?i - instrument)
               (have_image ?d - direction ?m - mode))
  (:action turn_to
    :parameters (?s - satellite ?to - direction ?from - direction)
    :precondition (pointing ?s ?from)
    :effect (and (pointing ?s ?to) (not (pointing ?s ?from))))
  (:action switch_on
    :parameters (?i - instrument ?s - satellite)
    :precondition (and (on_board ?i ?s) (power_avail ?s))
    :effect (and (power_on ?i) (not (calibrated ?i)) (not (power_avail ?s))))
  (:action take_image
    :parameters (?s - satellite ?d - direction ?i - instrument ?m - mode)
    :precondition (and (calibrated ?i) (on_board ?i ?s) (supports ?i ?m) (power_on ?i) (pointing ?s ?d))
    :effect (have_image ?d ?m)))
