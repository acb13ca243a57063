"""The hand's facts in the robot's own words: a demonstration's vocabulary binding.

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

__all__ = ["HandVocabulary", "KITCHEN", "NO_HAND", "infer_vocabulary", "vocabulary_of", "parse_vocabulary_row", "bind_arms", "vocabulary_defect", "ARM_WORDS",
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

        def name(key: str) -> str | None:
            value = data.get(key)
            return value.lower() if isinstance(value, str) else None  # names are case-insensitive, as in PDDL

        return cls(name("held"), name("free"), hands, origin, by_arm=bool(hands))


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
    """The binding declared by a state file's ``vocabulary`` rows (keys not given: none); ValueError for rows
    that contradict each other (see :func:`vocabulary_defect`)."""
    why = vocabulary_defect(rows)
    if why:
        raise ValueError(why)
    bound = dict(rows)
    if "none" in bound:
        return HandVocabulary(None, None, origin=origin)
    hands = tuple(sorted((h, bound[h]) for h in ("left", "right") if bound.get(h)))
    return HandVocabulary(bound.get("held"), bound.get("free"), hands, origin, by_arm=bool(hands))  # type: ignore[arg-type]


def vocabulary_defect(rows: list[tuple[str, str | None]], complete: bool = True) -> str | None:
    """What makes a list of vocabulary bindings (in row order) contradictory, or None: a key bound twice,
    ``none`` beside other bindings, one predicate for both held and free, one arm for both hands, and (when
    the list is ``complete``) arms without a held or free predicate to apply to."""
    seen: dict[str, str | None] = {}
    for key, value in rows:
        if key in seen:
            return f"{key} is bound twice ({seen[key] or 'none'}, then {value or 'none'}); expected one binding"
        if ("none" in seen) != (key == "none") and seen:
            return "vocabulary(none) beside other vocabulary rows; expected either"
        seen[key] = value
        if seen.get("held") and seen.get("held") == seen.get("free"):
            return f"held and free are both {value}; expected two predicates"
        if seen.get("left") and seen.get("left") == seen.get("right"):
            return f"left and right are both {value}; expected two arms"
    if complete and (seen.get("left") or seen.get("right")) and not (seen.get("held") or seen.get("free")):
        return "arms bound without held or free predicates for them; expected vocabulary(held=...) too"
    return None


#: Words that name a robot's arm in a type (``arm``, ``gripper``...): an arm-indexed hand fact is only read off
#: a domain whose arms' type says so (a car parked in a spot toggles like an arm holding a cup).
ARM_WORDS = ("arm", "hand", "gripper", "manipulator", "effector")


def _pairs(domain: Domain) -> tuple[set[tuple[str, str, bool]], set[tuple[str, str, bool]]]:
    """(grasp, release): (held, free, by_arm) pairs some action toggles one way (adds a held fact and deletes a
    free one, with the same arm where free takes one), and the other way."""
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
    return grasp, release


def _together(action, h: str, f: str, by_arm: bool) -> bool:
    """Whether ``action`` makes a held and a free fact (of one arm) both true or both false: they are then no
    hand state and its opposite (put-down makes the table's block clear and the hand empty)."""
    for side in (action.add, action.delete):
        for a in side:
            for b in side:
                if a.predicate == h and b.predicate == f and (not by_arm or a.args[:1] == b.args[:1]):
                    return True
    return False


def _strict(domain: Domain, h: str, f: str) -> bool:
    """Whether every action that changes ``h`` or ``f`` changes the other the opposite way: a hand state and
    its opposite always move together (in a blocksworld where a held block stays clear, unstacking makes the
    block below clear and the hand busy, but putting down makes the hand empty without a clear fact going)."""
    for action in domain.actions:
        adds = {a.predicate for a in action.add}
        dels = {a.predicate for a in action.delete}
        if (h in adds) != (f in dels) or (h in dels) != (f in adds):
            return False
    return True


def _arm_type(domain: Domain, free: str) -> str | None:
    predicate = domain.predicates.get(free)
    return predicate.params[0][1] if predicate is not None and predicate.params else None


def _toggles(domain: Domain) -> list[tuple[str, str, bool]]:
    """The (held, free, by_arm) pairs that are ``domain``'s hand facts, best evidence first: pairs its actions
    toggle both ways, else (a robot that lacks its putting or taking skill) one way; never a pair one action
    makes both true or both false; arm-indexed ones only on a type named like an arm (:data:`ARM_WORDS`);
    among several, those that always change together (:func:`_strict`)."""
    grasp, release = _pairs(domain)

    def fit(pairs: set[tuple[str, str, bool]]) -> list[tuple[str, str, bool]]:
        out = sorted(p for p in pairs if not any(_together(a, *p) for a in domain.actions))
        out = [p for p in out if not p[2] or any(w in (_arm_type(domain, p[1]) or "") for w in ARM_WORDS)]
        # A hand without arm objects first: putting an item on a surface also "toggles" (on_top ?i ?s)
        # against (in_hand ?i), which reads like an arm-indexed pair.
        out = [p for p in out if not p[2]] or out
        return [p for p in out if _strict(domain, p[0], p[1])] or out if len(out) > 1 else out

    return fit(grasp & release) or fit(grasp | release)


def infer_vocabulary(*domains: Domain | None) -> HandVocabulary | None:
    """The hand facts of the first of ``domains`` whose grasping actions show them (see :func:`_toggles`), None
    when none shows any; ValueError naming the candidates when one shows several."""
    for domain in domains:
        if domain is None:
            continue
        pairs = _toggles(domain)
        if len(pairs) > 1:
            shown = "; ".join(f"held={h}, free={f}" for h, f, _ in pairs)
            raise ValueError(f"{domain.path}: its grasping actions toggle more than one pair of hand facts ({shown}); "
                             "declare the demonstration's with vocabulary(held=...) and vocabulary(free=...) rows")
        if pairs:
            held, free, by_arm = pairs[0]
            arm_type = _arm_type(domain, free) if by_arm else None
            return HandVocabulary(held, free, (), f"the grasping actions of {domain.path}", by_arm, arm_type)
    return None


def _side(name: str) -> str | None:
    """``left``/``right`` where an arm's name says which (``left-arm``, ``robot_right``, ``arm-l``, ``rarm``)."""
    words = [w for w in name.replace("_", "-").split("-") if w]
    for side in ("left", "right"):
        if any(w == side or w == side[0] or w.startswith(side) or w.endswith(side) for w in words):
            return side
    if len(words) == 1 and words[0][:1] in "lr" and any(w in words[0][1:] for w in ARM_WORDS):
        return "left" if words[0][0] == "l" else "right"  # larm, rgripper
    return None


def bind_arms(vocabulary: HandVocabulary, objects: dict[str, str], arm_type: str | None = None,
              choose: bool = False) -> HandVocabulary:
    """Tie an arm-indexed binding to the trace's hands by the arms' names (``left-arm``, ``rarm``, ``arm-r``); a
    single arm is the right hand.  With ``choose`` (a simulated demonstrator, who can use either hand), two
    arms the names do not tell apart are the left and right in name order.  ValueError otherwise."""
    if not vocabulary.by_arm or vocabulary.hands:
        return vocabulary
    arm_type = arm_type or vocabulary.arm_type
    arms = sorted(o for o, t in objects.items() if arm_type is None or t == arm_type)
    if len(arms) == 1:
        return replace(vocabulary, hands=(("right", arms[0]),))
    sides = {a: _side(a) for a in arms}
    if len(arms) == 2 and sorted(sides.values(), key=str) == ["left", "right"]:
        return replace(vocabulary, hands=tuple(sorted((side, a) for a, side in sides.items())))  # type: ignore[misc]
    if len(arms) == 2 and choose:
        return replace(vocabulary, hands=(("left", arms[0]), ("right", arms[1])))
    raise ValueError(f"cannot tell which of the arms ({', '.join(arms) or 'none'}) is the left and which the "
                     "right hand; declare them with vocabulary(left=...) and vocabulary(right=...) rows")
