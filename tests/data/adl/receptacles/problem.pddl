(define (problem hot-potato)
  (:domain receptacles)
  (:objects robot - agent
            fridge microwave1 countertop - receptacle
            potato apple - thing)
  (:init (agent-at robot countertop)
         (openable fridge) (openable microwave1) (microwave microwave1)
         (in potato fridge) (in apple countertop))
  (:goal (exists (?t - thing) (and (hot ?t) (in ?t countertop)))))
