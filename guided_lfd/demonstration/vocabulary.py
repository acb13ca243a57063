"""The hand's facts in the robot's own words: a demonstration's vocabulary binding (issue #23).

A hand trace says what each hand holds (its ``in_hand`` column); the robot's
domain says it in its own predicates: ``(in_hand ?i)``/``(hand_free)`` in the
kitchens, ``(holding ?b)``/``(handempty)`` in blocksworld,
``(grasped ?a ?o)``/``(free ?a)`` for a robot with arms as objects, nothing
at all for a domain without a hand (switches).  A :class:`HandVocabulary`
binds the two:

* ``held``: the predicate true of what a hand holds (one argument, or two
  with the arm first when ``hands`` names the arms);
* ``free``: the predicate true when a hand holds nothing (no argument, or
  the arm);
* ``hands``: which object of the world each trace hand is (``right=rarm``),
  for predicates that take the arm.

A state file may declare it (rows ``vocabulary(held=holding)``,
``vocabulary(free=hand-empty)``, ``vocabulary(right=rarm)``,
``vocabulary(none)`` for no hand facts); otherwise :func:`infer_vocabulary`
reads it off the robot's domain: the predicates its grasping actions toggle
against each other (one adds ``held`` and deletes ``free``, another the
reverse).  Without either, the kitchens' ``in_hand``/``hand_free``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from guided_lfd.pddl.model import Atom, Domain

__all__ = ["HandVocabulary", "KITCHEN", "NO_HAND", "infer_vocabulary", "vocabulary_of", "parse_vocabulary_row", "bind_arms",
           "VOCABULARY_KEYS"]

#: The keys a ``vocabulary(key=value)`` row may bind.
VOCABULARY_KEYS = ("held", "free", "left", "right")


@dataclass(frozen=True)
class HandVocabulary:
    """How the hand's state is written in a domain (see the module docstring)."""

    held: str | None = "in_hand"
    free: str | None = "hand_free"
    hands: tuple[tuple[str, str], ...] = ()  # (trace hand, the arm object it is), sorted
    origin: str = field(default="the kitchens' default", compare=False)
    by_arm: bool = False  # the hand predicates take the arm as their first argument
    arm_type: str | None = None  # the arms' type, where read off a domain

    @property
    def predicates(self) -> frozenset[str]:
        """The predicates of the hand: read from the trace, never from the environment state."""
        return frozenset(p for p in (self.held, self.free) if p)

    def arm(self, hand: str) -> str | None:
        """The object trace hand ``hand`` is, where the predicates take the arm."""
        return dict(self.hands).get(hand)

    def fluents(self, hand: str, held: str) -> set[Atom]:
        """The hand facts of trace hand ``hand`` holding ``held`` ('' for nothing)."""
        arm: tuple[str, ...] = ()
        if self.by_arm:
            name = self.arm(hand)
            if name is None:
                return set()  # a hand that is no arm of the robot
            arm = (name,)
        if held:
            return {Atom(self.held, (*arm, held))} if self.held else set()
        return {Atom(self.free, arm)} if self.free else set()

    def held_object(self, atom: Atom) -> str | None:
        """The object a ``held`` fact says is held (its last argument), None for another fact."""
        if atom.predicate != self.held or len(atom.args) != (2 if self.by_arm else 1):
            return None
        return atom.args[-1]

    def hand_of(self, atom: Atom) -> str:
        """The trace hand a hand fact is about ('right' where the predicates take no arm)."""
        if self.by_arm and atom.args:
            return next((h for h, a in self.hands if a == atom.args[0]), "right")
        return "right"

    def describe(self) -> str:
        """``held=holding, free=handempty`` (``none`` without hand facts), as messages print it."""
        if not self.predicates:
            return "none"
        parts = [f"held={self.held or 'none'}", f"free={self.free or 'none'}"]
        parts += [f"{hand}={arm}" for hand, arm in self.hands]
        return ", ".join(parts)

    def to_dict(self) -> dict:
        """The binding as the segments document keeps it."""
        return {"held": self.held, "free": self.free, "hands": dict(self.hands)}

    @classmethod
    def from_dict(cls, data: dict, origin: str = "the segments document") -> "HandVocabulary":
        """The inverse of :meth:`to_dict`."""
        hands = tuple(sorted((data.get("hands") or {}).items()))
        return cls(data.get("held"), data.get("free"), hands, origin, by_arm=bool(hands))


KITCHEN = HandVocabulary()
NO_HAND = HandVocabulary(None, None, origin="no hand")


def parse_vocabulary_row(inside: str) -> tuple[str, str | None]:
    """``held=holding`` -> ("held", "holding"); ``none`` -> ("none", None); ValueError for anything else.

    ``held,holding`` (comma) is accepted too; the value ``none`` binds nothing."""
    text = inside.strip().lower()
    if text == "none":
        return "none", None
    sep = "=" if "=" in text else ","
    key, _, value = (part.strip() for part in text.partition(sep))
    if key not in VOCABULARY_KEYS or not value:
        raise ValueError(inside)
    return key, None if value == "none" else value


def vocabulary_of(rows: list[tuple[str, str | None]], origin: str) -> HandVocabulary:
    """The binding declared by a state file's ``vocabulary`` rows (keys not given: none)."""
    bound = dict(rows)
    if "none" in bound:
        return HandVocabulary(None, None, origin=origin)
    hands = tuple(sorted((h, bound[h]) for h in ("left", "right") if bound.get(h)))
    return HandVocabulary(bound.get("held"), bound.get("free"), hands, origin, by_arm=bool(hands))  # type: ignore[arg-type]


def _toggles(domain: Domain) -> list[tuple[str, str, bool]]:
    """(held, free, by_arm) predicate pairs ``domain``'s actions toggle against each other: one action adds a
    ``held`` fact and deletes a ``free`` one, another deletes a ``held`` fact and adds a ``free`` one (with the
    same arm, where ``free`` takes one), and none adds or deletes both."""
    grasp: set[tuple[str, str, bool]] = set()
    release: set[tuple[str, str, bool]] = set()
    for action in domain.actions:
        for side, gains, loses in ((grasp, action.add, action.delete), (release, action.delete, action.add)):
            for h in gains:
                for f in loses:
                    if len(h.args) == 1 and not f.args:
                        side.add((h.predicate, f.predicate, False))
                    elif len(h.args) == 2 and len(f.args) == 1 and h.args[0] == f.args[0]:
                        side.add((h.predicate, f.predicate, True))
    def together(action, h: str, f: str, by_arm: bool) -> bool:
        # An action that makes both true (put-down: the table's block clear, the hand empty) or both false
        # shows they are no hand state and its opposite.
        for side in (action.add, action.delete):
            for a in side:
                for b in side:
                    if a.predicate == h and b.predicate == f and (not by_arm or a.args[:1] == b.args[:1]):
                        return True
        return False

    return sorted(p for p in grasp & release if not any(together(a, *p) for a in domain.actions))


def infer_vocabulary(*domains: Domain | None) -> HandVocabulary | None:
    """The hand facts of the first of ``domains`` whose grasping actions show them unambiguously (see
    :func:`_toggles`), None when none shows any; ValueError naming the candidates when one shows several."""
    for domain in domains:
        if domain is None:
            continue
        pairs = _toggles(domain)
        # A hand without arm objects first: putting an item on a surface also "toggles" (on_top ?i ?s)
        # against (in_hand ?i), which reads like an arm-indexed pair.
        pairs = [p for p in pairs if not p[2]] or pairs
        if len(pairs) > 1:
            shown = "; ".join(f"held={h}, free={f}" for h, f, _ in pairs)
            raise ValueError(f"{domain.path}: its grasping actions toggle more than one pair of hand facts ({shown}); "
                             "declare the demonstration's with vocabulary(held=...) and vocabulary(free=...) rows")
        if pairs:
            held, free, by_arm = pairs[0]
            predicate = domain.predicates.get(free)
            arm_type = predicate.params[0][1] if by_arm and predicate is not None and predicate.params else None
            return HandVocabulary(held, free, (), f"the grasping actions of {domain.path}", by_arm, arm_type)
    return None


def bind_arms(vocabulary: HandVocabulary, objects: dict[str, str], arm_type: str | None = None) -> HandVocabulary:
    """Tie an arm-indexed binding to the trace's hands by the arms' names (``left_arm``, ``rarm``...): an arm
    named with ``left``/``l`` is the left hand, ``right``/``r`` the right; a single arm is the right hand.
    ValueError when the names do not tell."""
    if not vocabulary.by_arm or vocabulary.hands:
        return vocabulary
    arm_type = arm_type or vocabulary.arm_type
    arms = sorted(o for o, t in objects.items() if arm_type is None or t == arm_type)
    if len(arms) == 1:
        hands = (("right", arms[0]),)
    else:
        left = [a for a in arms if "left" in a or a.startswith("l")]
        right = [a for a in arms if "right" in a or a.startswith("r")]
        if len(arms) != 2 or len(left) != 1 or len(right) != 1 or left == right:
            raise ValueError(f"cannot tell which of the arms ({', '.join(arms) or 'none'}) is the left and which the "
                             "right hand; declare them with vocabulary(left=...) and vocabulary(right=...) rows")
        hands = (("left", left[0]), ("right", right[0]))
    return replace(vocabulary, hands=hands)
