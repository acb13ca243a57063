"""What an excuse search did: the task's size, the search's effort and times (the document's ``statistics``)."""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

__all__ = ["ExcuseStatistics"]


@dataclass
class ExcuseStatistics:
    """The statistics of one :func:`~guided_lfd.excuse.engine.find_excuses` run.

    A field is None until the run gets there (a run that timed out while
    grounding has only ``phase`` and ``time_s``); :meth:`to_dict` leaves
    those out, in the order docs/formats.md documents.
    """

    ground_atoms: int | None = None
    ground_actions: int | None = None
    changeable_atoms: int | None = None
    relevant_atoms: int | None = None
    relevant_actions: int | None = None
    invariant_groups: int | None = None
    fixed_predicates: list[str] | None = None
    #: The world's structure held fixed by default (in ``fixed_predicates`` too), each predicate with why.
    structure_held: dict[str, str] | None = None
    #: Invariants left out of the consistent semantics because the task's goal breaks them (no law of the world).
    invariants_refuted_by_goal: list[str] | None = None
    #: Placing predicates no robot action changes whose objects the consistent semantics keeps in one place.
    kept_in_one_place: list[str] | None = None
    #: No excuse keeps the invariants, but the literal semantics has one (``literal_excuse``): those it breaks.
    invariants_in_the_way: list[str] | None = None
    literal_excuse: list[str] | None = None
    #: No excuse keeps the world's structure (``structure_held``), but this one, which changes it, exists.
    structural_excuse: list[str] | None = None
    #: Which search answered (the portfolio: ``landmark`` or ``symbolic``; otherwise the strategy's name).
    answered_by: str | None = None
    setup_time_s: float | None = None  # from the run's start to the search's
    search_time_s: float | None = None
    candidates: int | None = None  # change sets that reached the reachability check
    planner_calls: int | None = None  # reachability checks (the baseline: planner calls)
    nodes_expanded: int | None = None
    #: Strategy-specific counters (``evaluations``, ``oracle_expanded``, ``oracle_pair_proofs``, ...), in their order.
    counters: dict[str, int] = field(default_factory=dict)
    phase: str | None = None  # where a timed-out run was
    #: A timed-out search: proven, every excuse (within --max-size) costs at least this (with unit costs: has at
    #: least this many changes).
    lower_bound: int | None = None
    incomplete: bool | None = None  # --all ran out of time: the excuses listed are minimal, maybe not all
    truncated: bool | None = None  # --all stopped at ``max_excuses``: more minimal excuses may exist
    max_excuses: int | None = None  # the cap --all stopped at (set with ``truncated``)
    #: --verify: 'verified' (every cheaper change set enumerated and refused), 'too-many' or 'timeout'.
    minimality: str | None = None
    minimality_sets: int | None = None  # the cheaper change sets --verify counted
    #: Learned preconditions a skill excuse could drop (none: the field is left out), and the state-excuse
    #: searches the enumeration over them ran (:mod:`guided_lfd.excuse.skills`).
    skill_changes_relaxable: int | None = None
    skill_searches: int | None = None
    time_s: float | None = None  # the whole run

    def to_dict(self) -> dict[str, Any]:
        """The document's ``statistics``: the fields that are set, the counters after ``nodes_expanded``."""
        out: dict[str, Any] = {}
        for f in fields(self):
            if f.name == "counters":
                out.update(self.counters)
                continue
            value = getattr(self, f.name)
            if value is not None:
                out[f.name] = value
        return out
