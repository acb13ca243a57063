"""h^2 reachability: is the goal reachable when pairs of facts must be reachable together?

The delete relaxation (h^1) only asks whether each fact can be made true on
its own.  h^2 (Haslum and Geffner 2000) asks the same of every *pair* of
facts, so it sees that two facts can never hold at once: in satellite, an
instrument calibrated in the excuse state but not powered on can never be
both (``switch_on`` deletes ``calibrated``), so ``take_image`` is never
applicable and the goal is unreachable.  h^1 calls that task solvable and
only an exhaustive search of the real state space would refute it; h^2 does
it in one fixpoint over the pairs, in milliseconds on IPC tasks.

Unreachable under h^2 implies unreachable (h^2 is admissible), so a "no"
proves the goal unreachable; a "yes" proves nothing.

The pairs are kept as one bit set per fact: ``partners[x]`` has bit ``y``
when the pair ``{x, y}`` is reachable (bit ``x`` when ``x`` is), so an
action's compatible facts are the AND of its preconditions' sets.  It runs
on the fact table of a :class:`~guided_lfd.planning.relaxation.RelaxedTask`
(complement facts for negative preconditions and goals included).
"""

from __future__ import annotations

from typing import Generator

from guided_lfd.planning.relaxation import RelaxedTask

#: Actions a pass processes between two yields (so a caller can stop it).
ACTIONS_PER_STEP = 512


class PairReachability:
    """h^2 goal reachability over the facts and actions of one relaxed task."""

    def __init__(self, relaxed: RelaxedTask) -> None:
        self.relaxed = relaxed
        self.pre_masks: list[int] = []
        self.add_masks: list[int] = []
        # What an action makes false, as facts: its deletes, and the
        # complement facts of its adds.
        self.del_masks: list[int] = []

    def estimated_bytes(self) -> int:
        """About what the check holds once built: a mask of facts per action (three) and per fact (its partners).

        Each is a Python int as wide as its highest fact, so this grows with actions times facts: a
        house of hundreds of items needs gigabytes, an IPC task a few megabytes.
        """
        n_facts, n_actions = self.relaxed.n_facts, len(self.relaxed.pre)
        return (n_facts * n_facts + 3 * n_actions * n_facts // 2) // 8

    def build(self) -> Generator[None, None, None]:
        """Build the action masks, yielding now and then; a build stopped early goes on where it stopped.

        :meth:`steps` builds what is missing first, so the cost of a wide task is paid only when its
        check runs (a candidate that a search confirms first never pays it).  Several builds may be
        under way at once (checks paused and resumed): each goes on from where the lists stand after its
        yield, never from where it stood before it.
        """
        relaxed = self.relaxed
        pos_id, neg_id = relaxed.pos_id, relaxed.neg_id
        n_real = len(relaxed.actions)
        while len(self.del_masks) < len(relaxed.pre):
            ai = len(self.del_masks)
            if not ai % ACTIONS_PER_STEP:
                yield
                if len(self.del_masks) != ai:
                    continue  # another build went on meanwhile
            # The three lists grow together, between two yields.
            self.pre_masks.append(_mask(relaxed.pre[ai]))
            self.add_masks.append(_mask(relaxed.add[ai]))
            if ai < n_real:
                act = relaxed.actions[ai]
                dels = [pos_id[i] for i in act.delete_ids if i in pos_id]
                dels += [neg_id[i] for i in act.add_ids if i in neg_id]
                self.del_masks.append(_mask(dels))
            else:
                self.del_masks.append(0)  # the artificial goal action

    def steps(self, state: int, to_fixpoint: bool = False) -> Generator[None, None, bool]:
        """Decide h^2 goal reachability from ``state``, yielding now and then; the return value is the answer.

        ``to_fixpoint``: go on past the goal until no pair is added; ``partners`` and ``reached`` then hold
        every pair and fact h^2 reaches (:meth:`mutex_pairs`).
        """
        yield from self.build()
        relaxed = self.relaxed
        true = relaxed._true_facts(state)
        true_mask = _mask(true)
        partners = [0] * relaxed.n_facts
        for f in true:
            partners[f] = true_mask
        reached = true_mask
        self.partners, goal_reached = partners, False
        pre, add = relaxed.pre, relaxed.add
        pre_masks, add_masks, del_masks = self.pre_masks, self.add_masks, self.del_masks
        goal_action = len(pre) - 1
        changed = True
        while changed:
            changed = False
            for ai, facts in enumerate(pre):
                if not ai % ACTIONS_PER_STEP:
                    yield
                need = pre_masks[ai]
                if reached & need != need:
                    continue
                compatible = -1
                for x in facts:
                    compatible &= partners[x]
                if compatible & need != need:
                    continue  # two preconditions never hold together
                if ai == goal_action:
                    if not to_fixpoint:
                        return True
                    goal_reached = True
                    continue
                adds = add_masks[ai]
                # After the action: its adds, with each other and with every
                # fact that held beside all its preconditions and survives it.
                after = (compatible & ~del_masks[ai] & ~adds) | adds
                for q in add[ai]:
                    new = after & ~partners[q]
                    if not new:
                        continue
                    changed = True
                    partners[q] |= new
                    reached |= 1 << q
                    others = new & ~(1 << q)
                    while others:  # keep the pair sets symmetric
                        low = others & -others
                        others ^= low
                        partners[low.bit_length() - 1] |= 1 << q
        self.reached = reached
        return goal_reached

    def mutex_pairs(self, state: int) -> list[tuple[int, int]]:
        """Pairs of atoms (task atom indices) that each can hold but never together in a state reachable from
        ``state`` (h^2 to its fixpoint; unreachable under h^2 implies unreachable)."""
        run = self.steps(state, to_fixpoint=True)
        for _ in run:
            pass
        atom_of = {f: i for i, f in self.relaxed.pos_id.items()}
        facts = sorted(f for f in atom_of if self.reached >> f & 1)
        out = []
        for k, x in enumerate(facts):
            partners = self.partners[x]
            for y in facts[k + 1:]:
                if not partners >> y & 1:
                    out.append((atom_of[x], atom_of[y]))
        return out

    def reachable(self, state: int) -> bool:
        """True unless h^2 proves the goal unreachable from ``state``."""
        run = self.steps(state)
        while True:
            try:
                next(run)
            except StopIteration as done:
                return bool(done.value)


def _mask(facts: list[int]) -> int:
    out = 0
    for f in facts:
        out |= 1 << f
    return out
