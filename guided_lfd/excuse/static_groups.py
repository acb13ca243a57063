"""Static groups: mutex groups no robot action changes, which the landmark search decides before it branches.

A truck that cannot drive, a hoist, a pallet: the group's true atom stays
where it is for good, so an excuse only ever moves it to another of the
group's atoms (see :func:`static_groups`).
"""

from __future__ import annotations

from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.planning.task import bits


def static_groups(space: ChangeSpace) -> list[tuple[int, int]]:
    """The mutex groups of the consistent semantics whose atom in the excuse state is there for good, and whose
    true atom q an excuse only removes to put another in its place: (group mask, the atoms worth moving to).

    No relevant robot action adds an atom of the group; one atom q is true initially, in no other group,
    no goal, no negative precondition or goal.  Without negative conditions on q, removing it only
    disables actions (STRIPS is monotone), and q's only group stays consistent with q: an excuse that
    removes q and adds no atom of the group weighs more than the same excuse keeping q.  Nor does adding
    an irrelevant atom g in its place help, unless g also fills another exactly-one group (dropping both
    changes then breaks that group).  Tasks with conditional effects or derived atoms have none.
    """
    task = space.task
    if task.is_adl or not space.groups:
        return []
    candidates = []
    for k, group in enumerate(space.groups):
        present = task.init & group.mask
        if present.bit_count() != 1 or not group.mask & space.relevant_atoms:
            continue
        q = present.bit_length() - 1
        if len(space.groups_of.get(q, ())) == 1 and not present & (space.negation_needed | task.goal_pos):
            candidates.append((k, group))
    if not candidates:
        return []
    # Indices, not a mask: OR-ing every action's atoms into one wide integer costs 0.1 s on a house.
    added = {i for act in space.relevant_actions for i in act.add_ids}
    out = []
    for k, group in candidates:
        if any(i in added for i in bits(group.mask)):
            continue
        targets = group.mask & space.relevant_atoms
        for i in bits(group.mask & ~space.relevant_atoms):
            if any(_fills_usefully(space, j, k) for j in space.groups_of.get(i, ())):
                targets |= 1 << i
        out.append((group.mask, targets))
    return out


def _fills_usefully(space: ChangeSpace, j: int, k: int) -> bool:
    """Whether an atom of group ``j`` (not the static group ``k``) may be worth adding to fill that group: it is an
    exactly-one group whose initial atom h0 an excuse may want gone (h0 under a negative condition, a goal, or
    in another group where it makes room).  Otherwise an excuse removing h0 and adding the atom weighs more than
    the same excuse with both undone (the other group then holds h0 alone)."""
    group, task = space.groups[j], space.task
    if j == k or not group.exactly_one:
        return False
    initial = task.init & group.mask
    if initial.bit_count() != 1:
        return True  # not the case the argument covers: keep the atom
    h0 = initial.bit_length() - 1
    return bool(initial & (space.negation_needed | task.goal_pos | task.goal_neg)) or len(space.groups_of[h0]) > 1
