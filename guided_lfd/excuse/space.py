"""The space of excuses: which atoms may change, at what cost, under which constraints.

An excuse (paper, Definition 2) is a set of atom changes E = I Δ I'.  A
change set is a bit set over the ground task's atom index; the excuse state
is ``I ^ E``.  This module holds everything the search strategies share:

* the changeable atoms (all typed ground atoms, minus ``--fixed`` predicates);
* backward relevance (atoms and robot actions that can matter for the goal):
  a minimal excuse under literal semantics only changes relevant atoms;
* change costs (``--cost``) folded with the size into one integer weight, so
  that minimising the weight minimises total cost and breaks ties by size;
* the state invariants of the ``consistent`` semantics (mutex groups).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import Enum

from guided_lfd.errors import OptionError
from guided_lfd.planning.relevance import relevance
from guided_lfd.planning.task import GroundAction, GroundTask, bits
from guided_lfd.pddl.model import Atom, Domain


class Semantics(str, Enum):
    """Which initial states count as excuse states."""

    LITERAL = "literal"  # the paper's Definition 2, over all typed ground atoms
    CONSISTENT = "consistent"  # ... that also keep the state invariants


@dataclass(frozen=True)
class MutexGroup:
    """Ground atoms of which at most one (or exactly one) may be true."""

    mask: int
    exactly_one: bool
    invariant: str

    def need(self, state: int) -> int:
        """How many changes inside the group ``state`` needs at least (0 = satisfied)."""
        count = (state & self.mask).bit_count()
        if count > 1:
            return count - 1
        if count == 0 and self.exactly_one:
            return 1
        return 0


@dataclass
class ChangeSpace:
    """What an excuse may change in one ground task, and what it costs."""

    task: GroundTask
    semantics: Semantics
    changeable: int
    relevant_atoms: int
    relevant_actions: list[GroundAction]
    negation_needed: int
    costs: dict[int, int]
    groups: list[MutexGroup] = field(default_factory=list)
    groups_of: dict[int, list[int]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # Weight = cost * M + 1 with M above any possible size: minimising the
        # summed weight minimises cost first and size second.
        self.size_factor = self.changeable.bit_count() + 1
        self.weights = {i: self.costs.get(i, 1) * self.size_factor + 1 for i in bits(self.changeable)}
        self.min_weight = min(self.weights.values(), default=1)

    # -- measures of a change set ---------------------------------------------
    def cost(self, changes: int) -> int:
        """User-facing cost of a change set (sum of ``--cost`` values, default 1 each)."""
        return sum(self.costs.get(i, 1) for i in bits(changes))

    def weight(self, changes: int) -> int:
        """The weight the searches minimise: cost x ``size_factor`` + size."""
        return sum(self.weights[i] for i in bits(changes))

    def cost_bound(self, weight: int) -> int:
        """The least cost of a change set of at least ``weight`` (a lower bound on weights as one on costs).

        Its size is below ``size_factor``, so its cost is at least
        ``weight // size_factor``; when no change is free, its size is at most
        its cost and the cost is at least ``weight / (size_factor + 1)``.
        """
        least = weight // self.size_factor
        if all(c > 0 for c in self.costs.values()):
            least = max(least, -(-weight // (self.size_factor + 1)))
        return least

    def state(self, changes: int) -> int:
        """The excuse state I' = I Δ E (its derived atoms recomputed, for ADL tasks)."""
        return self.task.close(self.task.init ^ changes)

    # -- consistency -------------------------------------------------------------
    def violated(self, state: int) -> list[MutexGroup]:
        """Groups the state violates (empty under literal semantics)."""
        return [g for g in self.groups if g.need(state)]

    def consistent(self, state: int) -> bool:
        """Whether ``state`` keeps every state invariant."""
        return not any(g.need(state) for g in self.groups)

    def consistency_bound(self, state: int) -> int:
        """A lower bound on the weight still needed to repair the violated groups."""
        return max((g.need(state) for g in self.groups), default=0) * self.min_weight


_COST = re.compile(r"^\s*(\(.*\)|[^=\s]+)\s*=\s*(\S+)\s*$")


def parse_costs(specs: list[str], task: GroundTask) -> dict[int, int]:
    """Per-atom change costs from ``PRED=N`` and ``(atom args)=N`` specifications.

    Atom specifications override predicate ones; everything else costs 1.
    """
    pred_costs: dict[str, int] = {}
    atom_costs: dict[int, int] = {}
    for spec in specs:
        match = _COST.match(spec)
        if not match:
            raise OptionError(f"--cost '{spec}': expected PRED=N or '(pred arg ...)=N'")
        target, value = match.group(1), match.group(2)
        if not re.fullmatch(r"[0-9]+", value, flags=re.ASCII):
            if re.fullmatch(r"-[0-9]+", value, flags=re.ASCII):
                raise OptionError(f"--cost '{spec}': cost must be 0 or more")
            raise OptionError(f"--cost '{spec}': cost '{value}' is not a whole number")
        number = int(value)
        if target.startswith("("):
            inner = target[1:-1] if target.endswith(")") else ""
            if "(" in inner or ")" in inner:
                raise OptionError(f"--cost '{spec}': expected one atom '(pred arg ...)'")
            words = inner.lower().split()
            atom = Atom(words[0], tuple(words[1:])) if words else None
            if atom is None or atom not in task.index:
                raise OptionError(f"--cost '{spec}': {target} is not a ground atom of this task")
            atom_costs[task.index[atom]] = number
        else:
            _check_cost_predicate(spec, target, task.domain)
            pred_costs[target.lower()] = number
    costs: dict[int, int] = {}
    for i, atom in enumerate(task.atoms):
        if atom.predicate in pred_costs:
            costs[i] = pred_costs[atom.predicate]
    costs.update(atom_costs)
    return {i: c for i, c in costs.items() if c != 1}


def _check_cost_predicate(spec: str, target: str, domain: Domain) -> None:
    if target.lower() not in domain.predicates:
        raise OptionError(
            f"--cost '{spec}': unknown predicate '{target}' (expected one of: {', '.join(sorted(domain.predicates))})"
        )


def check_cost_predicates(specs: list[str], domain: Domain) -> None:
    """Reject ``--cost PRED=N`` naming an unknown predicate (cheap: no grounding needed)."""
    for spec in specs:
        match = _COST.match(spec)
        if match and not match.group(1).startswith("("):
            _check_cost_predicate(spec, match.group(1), domain)


def cost_predicates(specs: Sequence[str]) -> set[str]:
    """The predicates ``--cost`` specifications price, each atom specification's included."""
    out = set()
    for spec in specs:
        match = _COST.match(spec)
        if match:
            target = match.group(1).lower()
            words = target.strip("()").split() if target.startswith("(") else [target]
            out.update(words[:1])
    return out


def check_fixed(fixed: list[str], domain: Domain) -> list[str]:
    """Validate ``--fixed`` predicate names; returns them lower-cased."""
    out = []
    for pred in fixed:
        name = pred.lower()
        if name not in domain.predicates:
            raise OptionError(
                f"--fixed '{pred}': unknown predicate (expected one of: {', '.join(sorted(domain.predicates))})"
            )
        out.append(name)
    return out


def build_space(
    task: GroundTask,
    semantics: Semantics,
    fixed: list[str] = (),  # type: ignore[assignment]
    costs: list[str] = (),  # type: ignore[assignment]
    groups: list[MutexGroup] | None = None,
) -> ChangeSpace:
    """Assemble the change space of a ground task."""
    fixed_preds = set(check_fixed(list(fixed), task.domain))
    changeable = 0
    for i, atom in enumerate(task.atoms):
        if atom.predicate not in fixed_preds and atom.predicate in task.domain.predicates:
            changeable |= 1 << i
    changeable &= ~task.derived  # derived atoms follow from the basic ones
    if task.is_adl:  # backward relevance reads plain effects only: every atom and action may matter
        relevant, rel_actions, negation = (1 << len(task.atoms)) - 1, list(task.actions), (1 << len(task.atoms)) - 1
    else:
        relevant, rel_actions, negation = relevance(task)
    space = ChangeSpace(
        task=task,
        semantics=semantics,
        changeable=changeable,
        relevant_atoms=relevant,
        relevant_actions=rel_actions,
        negation_needed=negation,
        costs=parse_costs(list(costs), task),
        groups=list(groups or []) if semantics is Semantics.CONSISTENT else [],
    )
    for gi, group in enumerate(space.groups):
        for i in bits(group.mask):
            space.groups_of.setdefault(i, []).append(gi)
    return space
