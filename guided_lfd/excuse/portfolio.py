"""The default excuse search: the landmark search, the hitting-set search in turns with it and the symbolic search
beside them; the first exact answer wins.

The landmark search answers small and most IPC tasks in well under a second;
the symbolic search answers at once for every candidate where the landmark
search would have to check candidates one by one, each a proof that the robot
cannot (depot under the consistent semantics).  The landmark search starts
alone; only a run still going after :data:`SYMBOLIC_AFTER_S` starts the
symbolic search, in a forked worker (:mod:`guided_lfd.symbolic.worker`), so a
short run never pays for a process or the diagram library.  From then on the
landmark search asks, between its steps, whether the worker has answered;
whichever finishes first with an exact answer (an excuse set, or a proof of
none) ends the other.  ``statistics.answered_by`` says which.  A task with
more relevant atoms than :data:`guided_lfd.symbolic.encoding.DEFAULT_MAX_VARIABLES`
never starts the worker.

On a monotone task (:func:`guided_lfd.excuse.hitting.monotone`: STRIPS with
positive conditions) the hitting-set search takes turns with the landmark
search in the same process, first after :data:`HITTING_AFTER_S`: where LM-cut's
bound stalls on a plateau of equally cheap change sets (a truck "at" both
ends of a road, a crate put straight into a hoist), its program's bound rises
to the delete-relaxed optimum in a few rounds; where candidates fail the
robot's check one after another (depot under the consistent semantics), the
landmark search's branching is the quicker.

Under the consistent semantics the portfolio first asks the same question
without the invariants, for a short while (:data:`WITHOUT_INVARIANTS_SHARE`
of the time left): dropping an excuse's changes to atoms the goal does not
depend on keeps it an excuse, never makes it heavier, and may break only
invariants, so the lightest excuse without them weighs no more than the
lightest one with them.  Hence no excuse without the invariants means none
with them (depot without ``drop``: a few expansions instead of hundreds of
thousands of change sets), and a lightest one that happens to keep every
invariant is a lightest consistent excuse.
"""

from __future__ import annotations

import time
from dataclasses import replace
from typing import Any

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse import outcome as search_outcome
from guided_lfd.excuse import symbolic
from guided_lfd.excuse.hitting import HittingRun, monotone
from guided_lfd.excuse.landmark import LandmarkSearch
from guided_lfd.excuse.lmcut import RelaxedExcuseTask
from guided_lfd.excuse.outcome import SearchLimits, SearchStopped
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace, Semantics
from guided_lfd.excuse.status import ExcuseStatus

#: Seconds the landmark search runs alone before the symbolic search starts beside it.
SYMBOLIC_AFTER_S = 0.5

#: Seconds the landmark search runs alone before the hitting-set search's first turn (monotone tasks).
HITTING_AFTER_S = 1.0

#: The symbolic worker's niceness: on a machine whose cores are all busy (``bench --jobs 2`` on two cores) it
#: takes the time the landmark search leaves, instead of half of it; on an idle core it runs at full speed.
WORKER_NICENESS = 10

#: Share of the time left the portfolio gives its search without the invariants (consistent semantics; at least
#: :data:`WITHOUT_INVARIANTS_LEAST_S` seconds).
WITHOUT_INVARIANTS_SHARE = 0.05
WITHOUT_INVARIANTS_LEAST_S = 1.0
#: What a run without a time limit counts as its time left for that share.
WITHOUT_INVARIANTS_UNLIMITED_S = 60.0

#: ``statistics.answered_by`` of an answer the search without the invariants settled.
WITHOUT_INVARIANTS = "landmark-literal"

#: Outcomes that settle the question (a timed-out search settles nothing).
_EXACT = (ExcuseStatus.FOUND, ExcuseStatus.NONE, ExcuseStatus.NONE_WITHIN_SIZE)


class PortfolioSearch:
    """The landmark search; after :data:`HITTING_AFTER_S` the hitting-set search in turns with it (monotone tasks),
    after :data:`SYMBOLIC_AFTER_S` the symbolic search beside them."""

    name = "portfolio"
    description = ("the landmark search, with the hitting-set search in turns and the symbolic search beside it "
                   "once a run takes longer (default)")
    lists_slack = True

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: Any = None, relaxed: Any = None) -> Any:
        """The first exact outcome of the searches (no hitting-set turns on a task that is not monotone; no symbolic
        worker on one that is no STRIPS task or is wider than the symbolic engine's default limit,
        :data:`~guided_lfd.symbolic.encoding.DEFAULT_MAX_VARIABLES`)."""
        from guided_lfd.symbolic.encoding import supports, worth_running

        # One oracle (and its memory of dead states) and one compiled relaxed task for every search here.
        oracle = oracle or ReachabilityOracle(space, limits.deadline)
        relaxed = relaxed or RelaxedExcuseTask(space)
        settled, first = without_invariants(space, limits, oracle, relaxed)
        if settled is not None:
            return settled
        turns = _HittingTurns(space, limits, oracle, relaxed) if monotone(space) else None
        if not supports(space.task) or not worth_running(space.relevant_atoms.bit_count()):
            race = None
        else:
            race = _Race(space, limits)
        try:
            try:
                outcome = LandmarkSearch().search(space, _members(limits, race, turns), progress, oracle, relaxed)
            except SearchStopped:
                return turns.answer if turns is not None and turns.answer is not None else race.outcome()
            if outcome.status is ExcuseStatus.TIMEOUT and race is not None and race.settled(start=False):
                return race.outcome()  # answered as the time ran out
            if turns is not None and outcome.status is ExcuseStatus.TIMEOUT:
                outcome = with_turns(outcome, turns)
            return _with_first(outcome if outcome.answered_by else _answered(outcome, "landmark"), first)
        finally:
            if race is not None:
                race.end()


def with_turns(outcome: Any, turns: _HittingTurns) -> Any:
    """A timed-out landmark search's ``outcome`` with what the hitting-set search's turns proved: the excuses it
    had found (each minimal: ``--all`` or ``--slack`` ran out of time listing them) where the landmark search has
    fewer, else its bound where that is the higher (it bounds the same minimum while it has found none)."""
    run = turns.run
    if run is not None and len(run.solutions) > len(outcome.solutions):
        return _answered(run.outcome(timed_out=True), "hitting-set")
    if run is not None and not run.solutions:
        outcome.lower_bound = max(outcome.lower_bound, run.bound)
    outcome.extra.update(turns.counters())
    return outcome


def _members(limits: SearchLimits, race: _Race | None, turns: _HittingTurns | None) -> Any:
    """The landmark search's limits: stopped once the symbolic worker (``race``) or the hitting-set search
    (``turns``) has answered, and giving the latter its turns."""
    if race is None and turns is None:
        return limits

    def settled() -> bool:
        return (turns is not None and turns.answer is not None) or (race is not None and race.settled())

    return replace(limits, stop=settled, turn=turns.turn if turns is not None else None)


class _HittingTurns:
    """The hitting-set search (:mod:`guided_lfd.excuse.hitting`) in turns with the landmark search, in its
    process and with its oracle: first after :data:`HITTING_AFTER_S`, then each turn as long as the landmark
    search's turn before it, both doubling, so each has about half the time.  Its program, landmarks and bound
    carry over from turn to turn."""

    def __init__(self, space: ChangeSpace, limits: SearchLimits, oracle: Any, relaxed: Any) -> None:
        self.space, self.limits, self.oracle, self.relaxed = space, limits, oracle, relaxed
        self.run: Any = None  # built at its first turn: a run that ends sooner never pays for it
        self.slice = HITTING_AFTER_S
        self.next_at = search_outcome.clock() + HITTING_AFTER_S
        self.answer: Any = None

    def counters(self) -> dict[str, int]:
        """Its effort, once it has had a turn."""
        return {} if self.run is None else self.run.counters()

    def turn(self) -> None:
        """The hitting-set search's turn, if its time has come (its answer in :attr:`answer` once it has one)."""
        now = search_outcome.clock()
        if self.answer is not None or now < self.next_at:
            return
        if self.run is None:
            self.run = HittingRun(self.space, replace(self.limits, probe=None, stop=None, turn=None), self.relaxed,
                                  self.oracle)
        deadline = self.limits.deadline
        until = now + self.slice if deadline is None else min(deadline, now + self.slice)
        self.run.limits = replace(self.run.limits, deadline=until)
        try:
            with search_outcome.oracle_until(self.oracle, until):
                self.run.loop(None)
            self.answer = _answered(self.run.outcome(), "hitting-set")
        except SearchTimeout:
            pass  # its turn is over: the next one goes on from its program
        self.slice *= 2
        self.next_at = search_outcome.clock() + self.slice


def _with_first(outcome: Any, first: Any) -> Any:
    """``outcome`` with the effort of the search without the invariants (``first``, None: it did not run) in its
    counters and, on a timeout, that search's lower bound where it is the higher (it bounds both questions)."""
    if first is None:
        return outcome
    outcome.extra.update(literal_expanded=first.expanded, literal_candidates=first.candidates)
    if outcome.status is ExcuseStatus.TIMEOUT:
        outcome.lower_bound = max(outcome.lower_bound, first.lower_bound)
    return outcome


def without_invariants(space: ChangeSpace, limits: SearchLimits, oracle: Any,
                       relaxed: Any) -> tuple[Any | None, Any | None]:
    """(the answer, None) when the search without the invariants settles the consistent question (see the
    module docstring), else (None, that search's outcome, or None where it did not run: no invariants to
    drop, or ``--all`` / ``--slack`` want more than one lightest excuse).  ``oracle`` and ``relaxed`` are the
    consistent search's (the relaxed task is copied without its invariants).

    It settles it by proving that no excuse exists at all (none within ``--max-size`` would answer less than
    the consistent search may) or by a lightest excuse that keeps every invariant.
    """
    if not space.groups or limits.all_minimal or limits.slack:
        return None, None
    literal = replace(space, semantics=Semantics.LITERAL, groups=[], groups_of={})
    now = search_outcome.clock()
    left = WITHOUT_INVARIANTS_UNLIMITED_S if limits.deadline is None else limits.deadline - now
    # Its share, at least a second, but never most of a short run.
    until = now + min(max(WITHOUT_INVARIANTS_LEAST_S, WITHOUT_INVARIANTS_SHARE * left), left / 4)
    with search_outcome.oracle_until(oracle, until):
        outcome = LandmarkSearch().search(literal, replace(limits, deadline=until, probe=None, stop=None),
                                          oracle=oracle, relaxed=relaxed.without_invariants(literal))
    if outcome.status is ExcuseStatus.NONE:
        return _answered(outcome, WITHOUT_INVARIANTS), None
    if outcome.status is ExcuseStatus.FOUND and space.consistent(space.task.init ^ outcome.solutions[0]):
        outcome.solutions = outcome.solutions[:1]
        return _answered(outcome, WITHOUT_INVARIANTS), None
    return None, outcome


class _Race:
    """The symbolic worker of one portfolio run: started late, polled, ended."""

    def __init__(self, space: ChangeSpace, limits: SearchLimits) -> None:
        self.space = space
        self.limits = replace(limits, probe=None, stop=None)
        self.start_at = time.monotonic() + SYMBOLIC_AFTER_S
        self.worker: Any = None

    def settled(self, start: bool = True) -> bool:
        """Whether the worker has an exact answer (``start``: starting it once its time has come)."""
        if self.worker is None:
            if not start or time.monotonic() < self.start_at:
                return False
            from guided_lfd.symbolic.worker import Forked

            self.worker = Forked(symbolic.symbolic_outcome, self.space, self.limits, niceness=WORKER_NICENESS)
            return False
        if not self.worker.poll():
            return False
        value = self.worker.value()
        return value is not None and ExcuseStatus(value[0]) in _EXACT

    def outcome(self) -> Any:
        """The worker's answer as the searches' outcome."""
        return symbolic.outcome_of(self.space, self.worker.value(), "symbolic")

    def end(self) -> None:
        """Stop the worker, if it was started."""
        if self.worker is not None:
            self.worker.stop()


def _answered(outcome: Any, by: str) -> Any:
    outcome.answered_by = by
    return outcome
