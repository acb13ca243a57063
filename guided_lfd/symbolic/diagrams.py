"""The decision-diagram library behind the symbolic engine, behind one small interface.

The engine needs few operations: conjunction, disjunction, negation, the
relational product ``exists vars (f and g)`` (one call per action and image,
the engine's hot path), node counts, and a walk over a diagram's nodes (the
distance pass of :mod:`guided_lfd.symbolic.nearest`).  Two libraries provide
them and install from the package registry as wheels: CUDD through ``dd``
(``dd.cudd``) and OxiDD (``oxidd``, its complement-edge BDDs).  The project
depends on the first; ``benchmarks/bdd_choice.py`` measures both on the same
reachability questions (README, "Proving the robot cannot").

Variables are numbered 0..n-1 and created in that order, which is their
order in every diagram (level = number): the encoding chooses the order
(:mod:`guided_lfd.symbolic.encoding`); dynamic reordering stays off, so
levels keep meaning atoms.

Memory: each manager is given a cap derived from the process's address-space
limit (``--memory-limit``, :data:`MEMORY_SHARE` of it); a diagram operation that
would pass it fails there instead of growing on (in a worker, the run goes on
with the search beside it).
"""

from __future__ import annotations

import contextlib
from typing import Any, Iterator, Protocol, Sequence

#: The library the engine uses unless told otherwise.
DEFAULT_LIBRARY = "cudd"

#: The part of the address-space limit the diagrams may take: a forked worker (:mod:`guided_lfd.symbolic.worker`)
#: sets a half.  The limit is per process: the worker and the search beside it each keep ``--memory-limit``,
#: so together they may hold up to twice it.
MEMORY_SHARE = 1.0


class Diagrams(Protocol):
    """A diagram manager over variables 0..n-1 (level = variable number)."""

    name: str
    true: Any
    false: Any

    def var(self, i: int) -> Any:
        """The function "variable ``i`` is true"."""
        ...

    def cube(self, values: dict[int, bool]) -> Any:
        """The conjunction of the literals ``values`` (variable -> value)."""
        ...

    def varset(self, indices: Sequence[int]) -> Any:
        """A handle on a set of variables, for :meth:`and_exists` and :meth:`exists`."""
        ...

    def and_exists(self, f: Any, g: Any, variables: Any) -> Any:
        """``exists variables (f and g)`` (``variables`` from :meth:`varset`)."""
        ...

    def exists(self, f: Any, variables: Any) -> Any:
        """``exists variables f``."""
        ...

    def size(self, f: Any) -> int:
        """The number of nodes of ``f``'s diagram."""
        ...

    def top(self, f: Any) -> tuple[int, Any, Any] | None:
        """``(level, high, low)`` of ``f``'s root (cofactors on its variable), or None for a constant."""
        ...


@contextlib.contextmanager
def memory_as_memout() -> Iterator[None]:
    """Turn a library's "out of memory" inside the block into :class:`MemoryError` (the documented memout).

    CUDD past its cap returns a null node, which ``dd.cudd`` raises as a ValueError naming the null pointer;
    OxiDD raises its ``DDMemoryError``.
    """
    try:
        yield
    except ValueError as exc:
        if "NULL" not in str(exc):
            raise
        raise MemoryError("the decision diagrams outgrew their memory cap") from None
    except Exception as exc:
        if type(exc).__name__ != "DDMemoryError":
            raise
        raise MemoryError("the decision diagrams outgrew their memory cap") from None


def open_diagrams(variables: int, library: str = DEFAULT_LIBRARY) -> Diagrams:
    """A manager over ``variables`` variables from ``library`` (``cudd`` or ``oxidd``), its memory capped."""
    if library == "cudd":
        return CuddDiagrams(variables, _memory_cap())
    if library == "oxidd":
        return OxiddDiagrams(variables, _memory_cap())
    raise ValueError(f"unknown diagram library {library!r} (expected cudd or oxidd)")


def _memory_cap() -> int:
    """Bytes the diagram library may hold: most of the address-space limit if one is set, else 8 GiB.

    The rest of the process (the ground task, the Python heap) needs the remainder.
    """
    import resource

    soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    if soft == resource.RLIM_INFINITY:
        return int(8 * 1024**3 * MEMORY_SHARE)
    return max(64 * 1024**2, int(soft * MEMORY_SHARE) * 3 // 4 - 512 * 1024**2)


class CuddDiagrams:
    """CUDD through ``dd.cudd`` (complement edges; variables named ``v<number>``)."""

    name = "cudd"

    def __init__(self, variables: int, memory: int) -> None:
        import dd.cudd

        self._dd = dd.cudd
        # CUDD sizes its tables from the memory estimate; max_memory makes it fail
        # (an exception here) instead of growing past the cap.
        self.bdd = dd.cudd.BDD(memory_estimate=min(memory, 1024**3))
        self.bdd.configure(reordering=False, max_memory=memory)
        self.names = [f"v{i}" for i in range(variables)]
        if self.names:
            self.bdd.declare(*self.names)
        self.true, self.false = self.bdd.true, self.bdd.false
        self._vars = [self.bdd.var(n) for n in self.names]

    def var(self, i: int) -> Any:
        """The function "variable ``i`` is true"."""
        return self._vars[i]

    def cube(self, values: dict[int, bool]) -> Any:
        """The conjunction of the literals ``values``."""
        out = self.true
        for i in sorted(values, reverse=True):  # bottom-up: each step adds one node
            out = out & (self._vars[i] if values[i] else ~self._vars[i])
        return out

    def varset(self, indices: Sequence[int]) -> Any:
        """The variables' names (what ``dd.cudd`` quantifies over)."""
        return [self.names[i] for i in indices]

    def and_exists(self, f: Any, g: Any, variables: Any) -> Any:
        """``exists variables (f and g)`` in one CUDD call."""
        return self._dd.and_exists(f, g, variables)

    def exists(self, f: Any, variables: Any) -> Any:
        """``exists variables f``."""
        return self.bdd.exist(variables, f) if variables else f

    def size(self, f: Any) -> int:
        """Nodes of ``f``."""
        return len(f)

    def top(self, f: Any) -> tuple[int, Any, Any] | None:
        """Root level and cofactors (``dd.cudd`` gives the children of the regular node: a complemented root's
        cofactors are their negations)."""
        if f == self.true or f == self.false:
            return None
        if f.negated:
            return f.level, ~f.high, ~f.low
        return f.level, f.high, f.low


class OxiddDiagrams:
    """OxiDD's BDDs with complement edges (``oxidd.bcdd``)."""

    name = "oxidd"

    def __init__(self, variables: int, memory: int) -> None:
        import oxidd.bcdd

        # About 32 bytes per inner node and as much again for the apply cache.
        nodes = max(1 << 16, memory // 64)
        self.manager = oxidd.bcdd.BCDDManager(nodes, nodes, 1)
        self._vars = [self.manager.var(v) for v in self.manager.add_vars(variables)] if variables else []
        self.true, self.false = self.manager.true(), self.manager.false()
        import oxidd.util

        self._and = oxidd.util.BooleanOperator.AND

    def var(self, i: int) -> Any:
        """The function "variable ``i`` is true"."""
        return self._vars[i]

    def cube(self, values: dict[int, bool]) -> Any:
        """The conjunction of the literals ``values``."""
        out = self.true
        for i in sorted(values, reverse=True):
            out = out & (self._vars[i] if values[i] else ~self._vars[i])
        return out

    def varset(self, indices: Sequence[int]) -> Any:
        """The variables as their conjunction (OxiDD's form of a variable set)."""
        return self.cube({i: True for i in indices})

    def and_exists(self, f: Any, g: Any, variables: Any) -> Any:
        """``exists variables (f and g)`` in one OxiDD call."""
        return f.apply_exists(self._and, g, variables)

    def exists(self, f: Any, variables: Any) -> Any:
        """``exists variables f``."""
        return f.exists(variables)

    def size(self, f: Any) -> int:
        """Nodes of ``f``."""
        return f.node_count()

    def top(self, f: Any) -> tuple[int, Any, Any] | None:
        """Root level and cofactors."""
        level = f.node_level()
        if level is None:
            return None
        high, low = f.cofactors()
        return level, high, low
