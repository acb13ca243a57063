"""Generalising repeated demonstrations of a skill (paper, section III-D-1).

Repeats are grouped by what they *do*: two demonstrations of an activity are
one skill when their lifted effects are equal under some renaming of their
parameters (taking a block from the table and from another block are two
skills, both labelled Take).  A skill's preconditions are the intersection of
its repeats' (aligned) preconditions, each recorded with its evidence (held in
all n demonstrations), beside the literals some repeat varied (held in fewer:
not required); parameters no longer used are dropped;
differing parameter types become their closest common supertype.

A demonstration whose effects are a strict part or a strict extension of a
skill's that more demonstrations agree on is a bad observation (a change
given to the wrong segment), not a skill: it is left out and reported.  With
as many demonstrations on each side the learner cannot tell which is right
and keeps what both show (the intersection), reported too.  Either way no
near-duplicate skill is made.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from guided_lfd.pddl.model import ActionSchema, Atom, Evidence, Literal, common_supertype

Effects = frozenset[tuple[str, Atom]]


def _effects(action: ActionSchema, mapping: dict[str, str]) -> Effects:
    return frozenset({("+", a.substitute(mapping)) for a in action.add}
                     | {("-", a.substitute(mapping)) for a in action.delete})


@dataclass
class Skill:
    """Demonstrations generalised into one skill so far."""

    first: ActionSchema
    types: dict[str, str]
    precondition: set[Literal]
    effects: Effects
    demonstrations: list[ActionSchema] = field(default_factory=list)
    shown: Counter[Literal] = field(default_factory=Counter)  # in how many demonstrations each literal held

    @classmethod
    def of(cls, action: ActionSchema) -> "Skill":
        return cls(action, dict(action.params), set(action.precondition), _effects(action, {}), [action],
                   Counter(action.precondition))

    def absorb(self, other: ActionSchema, mapping: dict[str, str], parents: dict[str, str | None]) -> None:
        """Add a repeat (renamed by ``mapping``): intersect preconditions and effects, widen types."""
        for var, typ in other.params:
            target = mapping[var]
            if target in self.types:
                self.types[target] = common_supertype(parents, self.types[target], typ)
        renamed = {lit.substitute(mapping) for lit in other.precondition}
        self.precondition &= renamed
        self.shown.update(renamed)
        self.effects &= _effects(other, mapping)
        self.demonstrations.append(other)

    def schema(self, name: str) -> ActionSchema:
        """The generalised action under ``name``, without parameters nothing mentions any more."""
        used = {x for lit in self.precondition for x in lit.atom.args} | {x for _, a in self.effects for x in a.args}
        params = tuple((v, self.types[v]) for v, _ in self.first.params if v in used)
        acts = self.demonstrations
        origin = f"learned from {len(acts)} demonstration(s): " + "; ".join(a.origin or "" for a in acts[:3])
        return ActionSchema(name, params, tuple(sorted(self.precondition)),
                            tuple(sorted(a for s, a in self.effects if s == "+")),
                            tuple(sorted(a for s, a in self.effects if s == "-")), origin,
                            evidence=self.evidence({v for v, _ in params}))

    def evidence(self, params: set[str]) -> tuple[Evidence, ...]:
        """What the demonstrations showed of each literal over ``params`` that held in any of them: the
        preconditions (held in all), then those some demonstration varied."""
        n = len(self.demonstrations)
        known = [lit for lit in self.shown if all(x in params for x in lit.atom.args)]
        return tuple(Evidence(lit, self.shown[lit], n) for lit in sorted(known, key=lambda l: (self.shown[l] < n, l)))


#: Renamings tried at most in each phase of an alignment (beyond, the best found so far).
MAX_ALIGNMENTS = 20_000
#: Effect renamings (of the best score) whose precondition-only parameters are then filled in.
TOP_EFFECT_RENAMINGS = 8


def _signature(action: ActionSchema, var: str) -> set[tuple[str, str, int]]:
    """Where ``var`` occurs: (effect sign or "pre", predicate, argument position)."""
    out = {(s, a.predicate, i) for s, a in _effects(action, {}) for i, x in enumerate(a.args) if x == var}
    return out | {("pre", l.atom.predicate, i) for l in action.precondition for i, x in enumerate(l.atom.args)
                  if x == var}


def _search(names: list[str], options: list[list[str]], fixed: dict[str, str], score, limit: int,
            keep: int) -> list[tuple[tuple, dict[str, str]]]:
    """The ``keep`` best injective renamings of ``names`` (each from its options) extending ``fixed``, by
    ``score``, trying at most ``limit`` complete ones; stops early at a perfect score (``score.perfect``)."""
    found: list[tuple[tuple, dict[str, str]]] = []
    tried = 0

    def extend(i: int, mapping: dict[str, str], used: set[str]) -> None:
        nonlocal tried
        if tried >= limit or (found and found[0][0] == score.perfect):
            return
        if i == len(names):
            tried += 1
            found.append((score(mapping), dict(mapping)))
            found.sort(key=lambda x: x[0], reverse=True)
            del found[keep:]
            return
        for target in options[i]:
            if target not in used:
                mapping[names[i]] = target
                extend(i + 1, mapping, used | {target})
        mapping.pop(names[i], None)

    extend(0, dict(fixed), set(fixed.values()))
    return found


def aligned(base: ActionSchema, other: ActionSchema) -> dict[str, str]:
    """The renaming of ``other``'s parameters onto ``base``'s that agrees best with it (effects first,
    then preconditions); a parameter ``base`` has no counterpart for gets a fresh name.

    Each parameter is tried only on ``base``'s parameters that occur somewhere alike (same predicate
    and position), the same name first; the parameters the effects mention are aligned first, then the
    precondition-only ones for the best few of those renamings, so the search stays small."""
    base_eff, base_pre = _effects(base, {}), set(base.precondition)
    base_sigs = {v: _signature(base, v) for v, _ in base.params}
    names = [v for v, _ in other.params]
    options = {v: sorted((b for b, sig in base_sigs.items() if sig & _signature(other, v)), key=lambda b: b != v)
               + [f"?unmatched{i}"] for i, v in enumerate(names)}
    in_effects = {x for _, a in _effects(other, {}) for x in a.args}
    first = [v for v in names if v in in_effects]
    rest = [v for v in names if v not in in_effects]

    def effect_score(mapping: dict[str, str]) -> tuple[int]:
        return (len(_effects(other, mapping) & base_eff),)

    def pre_score(mapping: dict[str, str]) -> tuple[int]:
        return (len({l.substitute(mapping) for l in other.precondition} & base_pre),)

    effect_score.perfect = (min(len(other.add) + len(other.delete), len(base_eff)),)  # type: ignore[attr-defined]
    pre_score.perfect = (min(len(other.precondition), len(base_pre)),)  # type: ignore[attr-defined]
    best: tuple | None = None
    mapping_best = {v: f"?unmatched{i}" for i, v in enumerate(names)}
    renamings = _search(first, [options[v] for v in first], {}, effect_score, MAX_ALIGNMENTS, TOP_EFFECT_RENAMINGS)
    for eff, partial in (r for r in renamings if r[0] == renamings[0][0]):  # the best effect renamings only
        for pre, full in _search(rest, [options[v] for v in rest], partial, pre_score, MAX_ALIGNMENTS, 1):
            if best is None or (eff + pre) > best:
                best, mapping_best = eff + pre, full
    return mapping_best


def _shape(action: ActionSchema) -> list[tuple[str, str]]:
    """The effects' (sign, predicate) multiset: equal for any two actions whose effects can be equal."""
    return sorted([("+", a.predicate) for a in action.add] + [("-", a.predicate) for a in action.delete])


def _same_types(skill: "Skill", other: ActionSchema, mapping: dict[str, str]) -> bool:
    return all(skill.types.get(mapping[v], t) == t for v, t in other.params)


def _cluster(group: list[ActionSchema], parents: dict[str, str | None]) -> list[Skill]:
    """Repeats with equal lifted effects (under the best renaming) as one skill each."""
    skills: list[Skill] = []
    for other in group:
        for skill in skills:
            if _shape(skill.first) != _shape(other):
                continue
            mapping = aligned(skill.first, other)
            if _effects(other, mapping) == skill.effects:
                skill.absorb(other, mapping, parents)
                break
        else:
            skills.append(Skill.of(other))
    return skills


def _show(effects: Effects) -> str:
    return " ".join(str(a) if s == "+" else f"(not {a})" for s, a in sorted(effects)) or "nothing"


def _reconcile(skills: list[Skill], parents: dict[str, str | None], name: str,
               notes: list[str], spans: dict[str, str]) -> list[Skill]:
    """Skills whose effects are a strict part or extension of a better-supported one's are bad
    observations of it: left out (fewer demonstrations) or intersected with it (as many), and noted."""
    kept: list[Skill] = []
    for skill in sorted(skills, key=lambda s: -len(s.demonstrations)):
        for good in kept:
            mapping = aligned(good.first, skill.first)
            theirs = _effects(skill.first, mapping)
            # Only a demonstration of the same kinds of objects can be a bad observation of a skill
            # (taking a block from another block is not taking it badly from the table).
            if not (theirs < good.effects or theirs > good.effects) or not _same_types(good, skill.first, mapping):
                continue
            where = "; ".join(f"{a.origin}{spans.get(a.origin or '', '')}" for a in skill.demonstrations)
            what = (f"its effects ({_show(theirs)}) disagree with {len(good.demonstrations)} other "
                    f"demonstration(s) of {name} ({_show(good.effects)})")
            if len(skill.demonstrations) < len(good.demonstrations):
                notes.append(f"{where}: warning: {what}; left out")
            else:
                _absorb_all(good, skill, mapping, parents)
                notes.append(f"{where}: warning: {what}; kept what both show")
            break
        else:
            kept.append(skill)
    return kept


def _absorb_all(home: Skill, skill: Skill, first_mapping: dict[str, str], parents: dict[str, str | None]) -> None:
    """Every demonstration of ``skill`` into ``home``; ``first_mapping`` (already found) aligns ``skill.first``."""
    for other in skill.demonstrations:
        home.absorb(other, first_mapping if other is skill.first else aligned(home.first, other), parents)


def _distinct_names(name: str, skills: list[Skill]) -> list[str]:
    """``name`` for one skill; for several (different effects), the types of the parameters the name does not
    already say (``take_block_surface``, ``take_block_block``)."""
    if len(skills) == 1:
        return [name]
    named = len(name.split("_")) - 1  # the activity, then one type per role
    out: list[str] = []
    for skill in skills:
        used = {x for _, a in skill.effects for x in a.args} | {x for l in skill.precondition for x in l.atom.args}
        params = [skill.types[v] for v, _ in skill.first.params if v in used]
        out.append("_".join([name, *params[named:]]) if len(params) > named else name)
    return out


def _home(candidates: list[Skill], skill: Skill) -> tuple[Skill, dict[str, str]] | None:
    """The first of ``candidates`` whose effects ``skill`` has on the same kinds of objects, with the renaming."""
    for c in candidates:
        if _shape(c.first) != _shape(skill.first):
            continue
        mapping = aligned(c.first, skill.first)
        if _effects(skill.first, mapping) == c.effects and _same_types(c, skill.first, mapping):
            return c, mapping
    return None


def _join_missing_roles(clusters: dict[str, list[Skill]], parents: dict[str, str | None]) -> None:
    """A skill named without a role (``put_block``: the detector never named the target) joins a skill of a
    name that extends it (``put_block_surface``) when their effects are equal on the same kinds of objects."""
    for name in sorted(clusters, key=len):
        for skill in list(clusters[name]):
            for longer in (n for n in clusters if n.startswith(name + "_")):
                found = _home(clusters[longer], skill)
                if found is not None:
                    _absorb_all(found[0], skill, found[1], parents)
                    clusters[name].remove(skill)
                    break


def generalise(actions: list[ActionSchema], parents: dict[str, str | None] | None = None,
               notes: list[str] | None = None, spans: dict[str, str] | None = None) -> list[ActionSchema]:
    """One schema per skill: repeats of an activity grouped by their lifted effects, aligned and intersected.

    ``notes`` collects one line per demonstration left out or reconciled (see the module docstring);
    ``spans`` maps a demonstration's origin to the frames it covers, for those lines.  Names are unique
    across all skills (``_2`` ... where two would clash).
    """
    parents, notes, spans = parents or {}, notes if notes is not None else [], spans or {}
    groups: dict[str, list[ActionSchema]] = {}
    for act in actions:
        groups.setdefault(act.name, []).append(act)
    clusters = {name: _cluster(group, parents) for name, group in groups.items()}
    _join_missing_roles(clusters, parents)
    order = {id(a): i for i, a in enumerate(actions)}
    named: list[tuple[int, Skill, str]] = []
    for name, skills in clusters.items():
        skills = _reconcile(skills, parents, name, notes, spans)
        named += [(min(order[id(a)] for a in s.demonstrations), s, n)
                  for s, n in zip(skills, _distinct_names(name, skills))]
    out: list[ActionSchema] = []
    taken: set[str] = set()
    for _, skill, candidate in sorted(named, key=lambda x: x[0]):  # in order of first demonstration
        unique, n = candidate, 1
        while unique in taken:
            n += 1
            unique = f"{candidate}_{n}"
        taken.add(unique)
        out.append(skill.schema(unique))
    return out
