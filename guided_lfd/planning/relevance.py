"""Backward relevance from the goal: the atoms and actions that can matter for reaching it.

The planner keeps only relevant actions; the excuse search changes only
relevant atoms (changing any other cannot turn a non-excuse into an excuse).
"""

from __future__ import annotations

from guided_lfd.planning.task import GroundAction, GroundTask, bits, mask_of


def relevance(task: GroundTask, actions: list[GroundAction] | None = None) -> tuple[int, list[GroundAction], int]:
    """Backward relevance from the goal.

    Returns (relevant atoms, relevant actions, atoms whose *negation* matters).
    An action is relevant if it changes a relevant atom; its preconditions are
    then relevant too.  Reachability of the goal only depends on the relevant
    atoms, so changing any other atom cannot turn a non-excuse into an excuse.
    """
    actions = task.actions if actions is None else actions
    by_atom: dict[int, list[int]] = {}
    for ai, act in enumerate(actions):
        for i in act.add_ids:
            by_atom.setdefault(i, []).append(ai)
        for i in act.delete_ids:
            by_atom.setdefault(i, []).append(ai)
    # Sets of indices while growing (one big-integer update per atom would
    # cost as much as the atom index is wide), one mask at the end.
    goal = list(bits(task.goal_pos | task.goal_neg))
    seen = set(goal)
    chosen: set[int] = set()
    frontier = goal
    while frontier:
        atom = frontier.pop()
        for ai in by_atom.get(atom, ()):
            if ai in chosen:
                continue
            chosen.add(ai)
            for i in (*actions[ai].pre_pos_ids, *actions[ai].pre_neg_ids):
                if i not in seen:
                    seen.add(i)
                    frontier.append(i)
    relevant = mask_of(seen)
    rel_actions = [actions[ai] for ai in sorted(chosen)]
    negation = set(bits(task.goal_neg))
    for act in rel_actions:
        negation.update(act.pre_neg_ids)
    return relevant, rel_actions, mask_of(negation)
