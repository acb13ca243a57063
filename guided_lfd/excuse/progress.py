"""How far an excuse search is, for a display: a plain callable gets a :class:`Progress` a few times a second.

The library prints nothing itself; the command line turns the reports into a
status line on a terminal (``cli/excuse.py``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import Callable

__all__ = ["Progress", "ProgressCallback", "ProgressMeter", "REPORTS_PER_SECOND"]


@dataclass(frozen=True)
class Progress:
    """One report: the phase, and once the search runs, its proven lower bound and effort so far."""

    phase: str
    elapsed_s: float
    #: Proven: every excuse (within ``max_size``) costs at least this; None before the search starts.
    lower_bound: int | None = None
    nodes: int = 0
    #: Reachability checks (the baseline: planner calls).
    oracle_calls: int = 0
    candidates: int = 0
    #: The cost of the cheapest excuse found so far that is not proven minimal, if any.
    best_cost: int | None = None


ProgressCallback = Callable[[Progress], None]

#: While a search runs, at most this many reports a second (a new phase is reported at once).
REPORTS_PER_SECOND = 4


class ProgressMeter:
    """Hands one run's progress to a callback: every phase, and the search's numbers when a report is due."""

    def __init__(self, callback: ProgressCallback, started: float) -> None:
        self.callback, self.started = callback, started
        self.current = Progress("grounding", 0.0)
        self.next_at = 0.0

    def due(self) -> bool:
        """Whether a search report is due (checked per node: one clock reading)."""
        return time.monotonic() >= self.next_at

    def phase(self, name: str) -> None:
        """Report that the run entered phase ``name`` (the search's numbers so far are kept)."""
        self._send(phase=name)

    def search(self, nodes: int, oracle_calls: int, candidates: int, lower_bound: int | None) -> None:
        """Report the search's effort and proven lower bound (the caller checked :meth:`due`)."""
        self._send(nodes=nodes, oracle_calls=oracle_calls, candidates=candidates, lower_bound=lower_bound)

    def found(self, cost: int) -> None:
        """Report an excuse found at ``cost`` that is not proven minimal."""
        self._send(best_cost=cost)

    def _send(self, **changed: object) -> None:
        now = time.monotonic()
        self.current = replace(self.current, **changed, elapsed_s=round(now - self.started, 3))  # type: ignore
        self.next_at = now + 1.0 / REPORTS_PER_SECOND
        self.callback(self.current)
