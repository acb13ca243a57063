"""What every excuse search shares: its limits, its outcome, its clock and the protocol a strategy follows.

The strategies (:mod:`~guided_lfd.excuse.landmark`, :mod:`~guided_lfd.excuse.baseline`,
:mod:`~guided_lfd.excuse.hitting`, :mod:`~guided_lfd.excuse.symbolic`,
:mod:`~guided_lfd.excuse.portfolio`) import this module; the registry
(:mod:`~guided_lfd.excuse.strategies`) alone imports the strategies.  Searches
read the time as ``outcome.clock()`` (an attribute, not an imported name), so
that a test that replaces :func:`clock` here replaces it for all of them.
"""

from __future__ import annotations

import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator, Protocol

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.lmcut import RelaxedExcuseTask
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.statistics import ExcuseStatistics
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.planning.search import SearchStopped
from guided_lfd.planning.task import GroundAction

__all__ = ["MAX_EXCUSES", "Probe", "SearchLimits", "SearchOutcome", "SearchStopped", "Strategy", "cap_excuses", "clock",
           "oracle_until", "run_to_outcome", "timed_out"]


def clock() -> float:
    """The searches' clock, ``time.monotonic()``: what deadlines and :class:`Probe` times are compared with.

    A test replaces it (one tick per reading) to end a search after a set
    number of checks, whatever the machine's speed.
    """
    return time.monotonic()


@contextmanager
def oracle_until(oracle: ReachabilityOracle, until: float) -> Iterator[None]:
    """Within the block, ``oracle`` gives up by ``until`` (a :func:`clock` value) or its own deadline, the
    earlier; its own deadline again after."""
    hard = oracle.deadline
    # The oracle reads time.monotonic(): the time left, in its terms (a test's clock() may tick otherwise).
    soft = time.monotonic() + max(0.0, until - clock())
    oracle.deadline = soft if hard is None else min(hard, soft)
    try:
        yield
    finally:
        oracle.deadline = hard


@dataclass
class Probe:
    """A pause of the landmark search, once, for a greedy search for any excuse.

    A run that may time out then still has an answer: an excuse that passed
    the reachability check, not proven minimal.  The greedy search shares the
    oracle and its memory; the A* search resumes where it paused.
    """

    start: float  # clock() time: pause when no excuse is found by then
    until: float  # clock() time the greedy search ends by, found or not
    #: Gets what the greedy search found: (change set, plan from its state).
    accept: Callable[[int, list[GroundAction]], None]


@dataclass
class SearchLimits:
    """What a search may spend and must return."""

    all_minimal: bool = False
    max_size: int | None = None
    deadline: float | None = None  # a clock() value
    max_solutions: int = 1000
    #: With ``all_minimal``: also the excuses up to this much costlier than the minimum (none of them a
    #: superset of another: adding changes to an excuse is no other choice).
    slack: int = 0
    probe: Probe | None = None
    #: Asked between steps: True ends the search with :class:`SearchStopped` (a portfolio's other member answered).
    stop: Callable[[], bool] | None = None
    #: Called between the landmark search's steps (never inside a check): another search's turn in the same
    #: process, when its time has come (the portfolio's hitting-set search); it ends this one through ``stop``.
    turn: Callable[[], None] | None = None


@dataclass
class SearchOutcome:
    """Change sets found (all of minimum weight) and how the search ended.

    ``status`` is ``FOUND``, ``NONE`` (proved: no excuse exists),
    ``NONE_WITHIN_SIZE`` (none within ``max_size``) or ``TIMEOUT``.
    """

    solutions: list[int]
    plans: dict[int, list[GroundAction]]
    status: ExcuseStatus
    candidates: int = 0
    planner_calls: int = 0
    expanded: int = 0
    extra: dict[str, int] = field(default_factory=dict)
    #: Proven: every excuse within ``max_size`` weighs at least this (the weight of the lightest change set
    #: the search had not ruled out when it ended).
    lower_bound: int = 0
    #: Which search answered, where a strategy runs several (the portfolio); empty: the strategy itself.
    answered_by: str = ""


class Strategy(Protocol):
    """A minimal-excuse search."""

    name: str
    description: str

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """Minimal change sets for ``space``.

        ``oracle`` (with its memory of earlier calls) and ``relaxed`` (the
        compiled relaxed task) may be passed in when the caller built them.
        """
        ...


def timed_out(limits: SearchLimits) -> bool:
    """Whether ``limits``' deadline has passed on the searches' :func:`clock`."""
    return limits.deadline is not None and clock() > limits.deadline


def run_to_outcome(run: Any, limits: SearchLimits, progress: ProgressMeter | None) -> SearchOutcome:
    """Run a search's ``loop`` to its outcome (a timed-out one at the deadline); its oracle's checks stop when
    ``limits.stop`` says so."""
    run.oracle.interrupt = limits.stop
    try:
        run.loop(progress)
    except SearchTimeout:
        return run.outcome(timed_out=True)
    finally:
        run.oracle.interrupt = None
    return run.outcome()


#: ``--all`` lists at most this many excuses (and says so in ``statistics.truncated`` when it stops there).
MAX_EXCUSES = 1000


def cap_excuses(outcome: SearchOutcome, stats: ExcuseStatistics) -> None:
    """At most :data:`MAX_EXCUSES`: the search looks for one more, so that a list of exactly that many is not
    called cut; one beyond it is dropped and the statistics say the list was cut there."""
    if len(outcome.solutions) > MAX_EXCUSES:
        del outcome.solutions[MAX_EXCUSES:]
        stats.truncated, stats.max_excuses = True, MAX_EXCUSES
