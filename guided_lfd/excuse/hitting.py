"""Excuse search by implicit hitting sets: the lightest change set that meets every landmark found so far.

A *landmark* here is a set of atoms of which every excuse state holds one:
"the excuse state is no subset of G" for a set of atoms G from which the robot
cannot reach the goal.  In a STRIPS task with positive preconditions and goals
(no derived atoms, no conditional effects) reachability is monotone in the
state: a state inside G has fewer atoms, so it fails as well.  Each round asks
a mixed-integer program (HiGHS, through scipy) for the lightest change set
whose state meets every landmark, keeps the invariants (consistent semantics)
and misses the goal, then checks it:

* the delete relaxation cannot reach the goal from its state: LM-cut's
  landmarks there are added (each a set of atoms without all of which the
  relaxation still fails), and the state is grown, atom by atom, as far as
  the relaxation still fails (Haslum, Slaney and Thiébaux's minimal landmarks
  for h+, 2012); the atoms left outside are one more landmark;
* the relaxation reaches the goal but the robot cannot (the reachability
  oracle): the state itself bounds a landmark;
* the robot can: no lighter change set is left, so it is a minimal excuse.

Each program's optimum is a proven lower bound on every excuse not found yet,
and the bound reaches the delete-relaxed optimum (h+) without enumerating the
change sets that LM-cut's bound cannot tell apart (transport without drive: a
package carried by a truck "at" both ends, or put at its goal).  Tasks outside
the monotone case go to the landmark search.
"""

from __future__ import annotations

from typing import Any

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse import outcome as search_outcome
from guided_lfd.excuse.landmark import LandmarkSearch
from guided_lfd.excuse.lmcut import RelaxedClosure, RelaxedExcuseTask
from guided_lfd.excuse.outcome import SearchLimits, SearchOutcome, SearchStopped, run_to_outcome
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.planning.task import GroundAction

__all__ = ["HittingSetSearch", "monotone"]


def monotone(space: ChangeSpace) -> bool:
    """Whether reachability of the goal only grows with the state's atoms (what the landmarks here rest on):
    STRIPS, no derived atoms, no negative goal or relevant negative precondition."""
    task = space.task
    return not task.is_adl and not task.derived and not task.goal_neg and not space.negation_needed


class HittingSetSearch:
    """Implicit hitting sets over change sets (monotone tasks; the landmark search on the others)."""

    name = "hitting-set"
    description = "the lightest change set meeting every landmark found so far (a MILP), checked; a failure adds one"
    lists_slack = True

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> Any:
        """Minimal change sets for ``space``; ``oracle`` and ``relaxed`` are reused when given."""
        if not monotone(space):
            outcome = LandmarkSearch().search(space, limits, progress, oracle, relaxed)
            outcome.answered_by = "landmark"  # the search that answered, not the one asked for
            return outcome
        run = HittingRun(space, limits, relaxed or RelaxedExcuseTask(space),
                         oracle or ReachabilityOracle(space, limits.deadline))
        return run_to_outcome(run, limits, progress)


class HittingRun:
    """One hitting-set search: the program, the landmarks in it, and what was found."""

    def __init__(self, space: ChangeSpace, limits: SearchLimits, relaxed: RelaxedExcuseTask,
                 oracle: ReachabilityOracle) -> None:
        from guided_lfd.excuse.milp import ChangeProgram

        self.space, self.limits, self.relaxed, self.oracle = space, limits, relaxed, oracle
        self.program = ChangeProgram(space, limits.max_size)
        self.bound = 0
        self.solutions: list[int] = []
        self.plans: dict[int, list[GroundAction]] = {}
        self.limit: int | None = None  # the heaviest excuse still listed, once one is found
        self.candidates = self.relaxed_cuts = self.real_cuts = self.rounds = 0
        self.size_pruned = False

    def loop(self, progress: ProgressMeter | None) -> None:
        """Solve, check, cut, until the minimal excuses are found or the program has no solution."""
        space, task = self.space, self.space.task
        while True:
            if search_outcome.timed_out(self.limits):
                raise SearchTimeout("excuse search exceeded its time limit")
            if self.limits.stop is not None and self.limits.stop():
                raise SearchStopped()
            solved = self.program.lightest(self.time_left())
            self.rounds += 1
            if solved is None:
                self.size_pruned = not self.solutions and self.program.feasible_without_size(self.time_left())
                return
            weight, changes = solved
            if not self.solutions:  # a bound on the lightest excuse (later programs list heavier ones: --slack)
                self.bound = max(self.bound, weight)
            if self.limit is not None and weight > self.limit:
                return
            if progress is not None and progress.due():
                progress.search(self.rounds, self.oracle.stats.calls, self.candidates, space.cost_bound(self.bound))
            state = task.init ^ changes
            if task.satisfies_goal(state) or not space.consistent(state):
                raise RuntimeError("internal check failed: the change program gave a state it excludes")
            if not self.relaxed.reaches_goal_unchanged(state):
                self.relaxed_cuts += 1
                self.add_landmarks(state)
                continue
            self.candidates += 1
            plan = self.oracle.solve(state)
            if plan is None:
                self.real_cuts += 1
                self.program.exclude_within(state)
                continue
            if self.found(weight, changes, plan):
                return

    def found(self, weight: int, changes: int, plan: list[GroundAction]) -> bool:
        """Record an excuse; whether the search is over."""
        space, limits = self.space, self.limits
        if self.limit is None:
            slack = limits.slack
            self.limit = weight if not slack else (space.cost(changes) + slack + 1) * space.size_factor - 1
        self.solutions.append(changes)
        self.plans[changes] = plan
        self.program.exclude_supersets(changes)  # an excuse with changes added is no other choice
        return not limits.all_minimal or len(self.solutions) >= limits.max_solutions

    def add_landmarks(self, state: int) -> None:
        """Landmarks of the relaxed robot from ``state``, a state it cannot reach the goal from: LM-cut's (each
        a set of atoms false in ``state`` without all of which it still cannot, so every excuse state holds one)
        and the atoms left outside :meth:`grown`."""
        bound = self.relaxed.bound(state, 0)
        for atoms in bound.landmarks:
            self.program.require_one_of(atoms)
        self.program.exclude_within(self.grown(state))

    def grown(self, state: int) -> int:
        """``state`` with every atom added that keeps the relaxed goal unreachable, one after another (tried
        in halving blocks: most atoms join in a block that still fails); the atoms left out each reach it."""
        relaxed = self.relaxed
        closure = RelaxedClosure(relaxed, state)
        pos_id = relaxed._pos_id
        reached = closure.reached
        blocks = [[pos_id[a] for a in self.program.relevant_atoms if not reached[pos_id[a]]]]
        while blocks:
            block = [f for f in blocks.pop() if not closure.reached[f]]
            if not block:
                continue
            trial = closure.copy()
            if not trial.add(block):
                closure = trial
            elif len(block) > 1:
                half = len(block) // 2
                blocks += [block[half:], block[:half]]  # the first half next
        atoms = relaxed.fact_atom_list
        inside = state
        for f, r in enumerate(closure.reached):
            if r:
                inside |= 1 << atoms[f]
        return inside

    def time_left(self) -> float | None:
        """Seconds to the deadline (None: none)."""
        return None if self.limits.deadline is None else max(0.0, self.limits.deadline - search_outcome.clock())

    def counters(self) -> dict[str, int]:
        """Its effort: programs solved, landmarks from the relaxation and from the robot's checks."""
        return {"hitting_rounds": self.rounds, "relaxed_landmarks": self.relaxed_cuts, "real_landmarks": self.real_cuts}

    def outcome(self, timed_out: bool = False) -> Any:
        """What the search found, with its effort."""
        stats = self.oracle.stats
        extra = self.counters()
        if timed_out:
            status = ExcuseStatus.TIMEOUT
        else:
            status = (ExcuseStatus.FOUND if self.solutions
                      else ExcuseStatus.NONE_WITHIN_SIZE if self.size_pruned else ExcuseStatus.NONE)
        return SearchOutcome(sorted(self.solutions) if not timed_out else self.solutions, self.plans, status,
                             self.candidates, stats.calls, self.rounds, extra, self.bound)
