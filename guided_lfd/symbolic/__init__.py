"""Symbolic search: sets of states as binary decision diagrams.

The excuse question "from which states can the robot reach the goal?" is
answered once, for every state at the same time, by backward reachability
over the robot's ground actions (:mod:`guided_lfd.symbolic.reach`); the
minimal excuses are then the members of that set nearest to the initial state
(:mod:`guided_lfd.symbolic.nearest`).  The same search proves a planning task
unsolvable.  The decision-diagram library is imported only when a symbolic
search runs (:mod:`guided_lfd.symbolic.diagrams`), so runs that never use it
start as fast as before.
"""
