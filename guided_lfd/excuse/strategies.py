"""The registry of excuse search strategies: the only module that imports them all.

Every strategy finds change sets E of minimum weight (cost first, size second)
such that I Δ E does not satisfy the goal, keeps the invariants (consistent
semantics) and lets the robot reach the goal.  New strategies register in
:data:`STRATEGIES`; the test suite runs every registered strategy against
brute force, so a registration is all a new strategy needs to be checked.
"""

from __future__ import annotations

from guided_lfd.excuse.baseline import BaselineSearch
from guided_lfd.excuse.hitting import HittingSetSearch
from guided_lfd.excuse.landmark import LandmarkSearch
from guided_lfd.excuse.outcome import Strategy
from guided_lfd.excuse.portfolio import PortfolioSearch
from guided_lfd.excuse.symbolic import SymbolicSearch

__all__ = ["STRATEGIES", "DEFAULT_STRATEGY"]


#: Registered strategies by name; the first is the default.
STRATEGIES: dict[str, Strategy] = {s.name: s for s in (PortfolioSearch(), LandmarkSearch(), BaselineSearch(),
                                                        SymbolicSearch(), HittingSetSearch())}
DEFAULT_STRATEGY = "portfolio"
