"""Naming learned skills as the robot's domain would.

A skill is learned under its activity's name (``push_door``, ``take_block``);
with a human model (the demonstrator's domain) a skill whose lifted effects
are those of a human action, under some renaming of its parameters onto the
action's whose types admit them, takes that action's name and parameter
order: ``open-door ?d ?r``, ``unstack ?x ?y``.  Parameters the human action
does not have keep their place after the matched ones.  Two skills matching
one action get ``_2``... so names stay unique.
"""

from __future__ import annotations

from guided_lfd.demonstration.generalise import _effects, _shape, aligned
from guided_lfd.pddl.model import ActionSchema, Domain

__all__ = ["name_after", "human_counterpart"]


def human_counterpart(skill: ActionSchema, human: Domain) -> tuple[ActionSchema, dict[str, str]] | None:
    """The human action whose effects ``skill``'s are under a renaming its types admit, with the renaming
    (skill variable -> human variable); among several (kicking a door open, unlocking it), the one whose
    precondition agrees best with the skill's; None when no action matches."""
    subtypes = human.subtypes()
    types = dict(skill.params)
    found: list[tuple[int, int, ActionSchema, dict[str, str]]] = []
    for k, action in enumerate(human.actions):
        if _shape(action) != _shape(skill):
            continue
        mapping = aligned(action, skill)
        if _effects(skill, mapping) != _effects(action, {}):
            continue
        theirs = dict(action.params)
        if all(types[v] in subtypes.get(theirs[h], {theirs[h]}) or theirs[h] in subtypes.get(types[v], {types[v]})
               for v, h in mapping.items() if h in theirs):
            mine = {l.substitute(mapping) for l in skill.precondition}
            agree = len(mine & set(action.precondition)) - len(set(action.precondition) - mine)
            found.append((agree, -k, action, mapping))
    if not found:
        return None
    _, _, action, mapping = max(found, key=lambda f: (f[0], f[1]))
    return action, mapping


def name_after(skills: list[ActionSchema], human: Domain) -> list[ActionSchema]:
    """``skills`` with each one that has a human counterpart renamed after it (see the module docstring)."""
    out: list[ActionSchema] = []
    taken = {s.name for s in skills if human_counterpart(s, human) is None}
    for skill in skills:
        found = human_counterpart(skill, human)
        if found is None:
            out.append(skill)
            continue
        action, mapping = found
        matched = {h: v for v, h in mapping.items() if h in dict(action.params)}
        order = [matched[h] for h, _ in action.params if h in matched]
        order += [v for v, _ in skill.params if v not in order]
        # The human's variable names where matched; others keep theirs unless that would clash.
        names = {v: mapping[v] if v in matched.values() else v for v in order}
        used = set(matched)
        for v in order:
            if v not in matched.values() and v in used:
                k = 1
                while f"{v}{k}" in used:
                    k += 1
                names[v] = f"{v}{k}"
            used.add(names[v])
        types = dict(skill.params)
        name, k = action.name, 1
        while name in taken:
            k += 1
            name = f"{action.name}_{k}"
        taken.add(name)
        out.append(ActionSchema(
            name, tuple((names[v], types[v]) for v in order),
            tuple(sorted(l.substitute(names) for l in skill.precondition)),
            tuple(sorted(a.substitute(names) for a in skill.add)),
            tuple(sorted(a.substitute(names) for a in skill.delete)),
            skill.origin, evidence=tuple(e.substitute(names) for e in skill.evidence)))
    return out
