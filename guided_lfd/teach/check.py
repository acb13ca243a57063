"""Each demonstration checked against its request before anything learned from it is kept (issue #52).

What it reached of the request and what not, what else it changed (the facts the request said to keep
above all), whether a demonstrated step contradicts the robot's own skills or the human model, and whether
the skills learned from it let the robot reach the request itself.  The outcome:

* ``accepted``: the request met; or, where it was not, the skills learned from it let the robot make the
  rest (or the whole request) itself (opening the blue drawer teaches ``open``, which opens the pink one);
* ``partial``: part of the request met, the skills learned from it kept; the next request names the facts
  still missing;
* ``misdirected``: a fact the request said to keep was changed, or the robot cannot reach its goal from the
  state the demonstration left though the request holds there (the paper's misdirected guidance: the same
  :func:`~guided_lfd.demonstration.judgement.misdirected_culprit` as ``evaluate``'s); its skills are kept
  only where they let the robot reach the request itself;
* ``unhelpful``: nothing requested reached and nothing learned that reaches it: nothing is kept, and the
  request is asked again, reworded with what was seen;
* ``inconsistent``: a demonstrated step contradicts an action of the human model (or one of the robot's
  own skills): nothing learned from the demonstration is kept, and both are named.

The world stays as the demonstration left it, whatever the outcome: the next round starts there.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

from guided_lfd.demonstration.judgement import contradiction, differences, known_skill, misdirected_culprit
from guided_lfd.demonstration.learn import DemonstratedAction
from guided_lfd.excuse.change import Change, describe_change, excuse_state
from guided_lfd.pddl.model import Atom, Domain, Problem, pretty_atom

__all__ = ["OUTCOMES", "DemonstrationCheck", "check_demonstration", "still_missing", "asked_again"]

#: The outcomes of a demonstration's check, in the order they are judged.
OUTCOMES = ("inconsistent", "unhelpful", "misdirected", "partial", "accepted")


@dataclass
class DemonstrationCheck:
    """A demonstration against its request: what it reached, changed and broke, and its outcome."""

    outcome: str
    reason: str
    reached: list[Change]
    missing: list[Change]
    other_changes: list[Change]  # changes beside the request's (the hand's own facts left out)
    kept_changed: list[Atom]  # facts the request said to keep that it changed
    contradictions: list[str] = field(default_factory=list)
    misdirected: list[Change] | None = None  # the culprit when the robot cannot reach its goal from the end state
    keep_skills: bool = True  # whether the skills learned from it stay in the robot's domain

    def to_dict(self) -> dict[str, Any]:
        """The check as ``session.json``'s round has it (``check``)."""
        return {"outcome": self.outcome, "reason": self.reason, "reached": [str(c) for c in self.reached],
                "missing": [str(c) for c in self.missing], "other_changes": [str(c) for c in self.other_changes],
                "kept_changed": [str(a) for a in self.kept_changed], "contradictions": self.contradictions,
                "misdirected": None if self.misdirected is None else [str(c) for c in self.misdirected]}


def _words(changes, spellings) -> str:
    return ", ".join(describe_change(c, spellings) for c in changes)


def still_missing(change: Change, spellings: dict[str, str]) -> str:
    """A requested change not made, in the domain's words: ``Open PinkDrawer is still false: demonstrate Open
    PinkDrawer``."""
    return (f"{pretty_atom(change.atom, spellings)} is still {'false' if change.added else 'true'}: "
            f"demonstrate {describe_change(change, spellings)}")


def asked_again(previous: Any, request: list[Change], spellings: dict[str, str]) -> list[str]:
    """The next request reworded after a ``partial`` or ``unhelpful`` demonstration (``previous``: its round):
    the facts still missing in the domain's words, and what the last demonstration did instead."""
    check = previous.check
    if check is None or check.outcome not in ("partial", "unhelpful", "misdirected"):
        return []
    out = [f"round {previous.index} left this undone: {still_missing(c, spellings)}"
           for c in check.missing if c in request]
    if check.outcome == "unhelpful":
        seen = _words(check.other_changes, spellings) or "nothing the robot could see"
        out.append(f"round {previous.index}'s demonstration made {seen} instead")
    return out


def _contradictions(steps: list[DemonstratedAction], types: dict[str, str], robot: Domain, human: Domain | None,
                    hand: set[str], spellings: dict[str, str]) -> list[str]:
    """Each demonstrated step the robot does not already have that contradicts an action of the human model
    (any overlap) or of the robot (the step does what that skill does, and more), one line naming both."""
    found = []
    for step in steps:
        for model, whose, strict in ((human, "the human model's", True), (robot, "the robot's", False)):
            if model is None or known_skill(step, robot, types) is not None:
                continue
            hit = contradiction(step, model, types, strict, hand)
            if hit is not None:
                made = _words([c for c in differences(step.delete, step.add) if c.atom.predicate not in hand],
                              spellings)
                found.append(f"the demonstrated {step.name} ({' '.join(step.objects)}) makes {made}; "
                             f"{whose} {hit[0]} makes {_words(hit[1], spellings)}")
                break
    return found


def _stranded(rnd, before: frozenset[Atom], after: frozenset[Atom], task: Problem, robot: Domain, merged: Domain,
              agrees: bool) -> tuple[list[Change] | None, bool]:
    """The paper's misdirected guidance, measured as ``evaluate`` measures it (the robot that asked, the excuse
    state intended): the changes to blame when that robot cannot reach its goal from where the demonstration
    ended (None when it can); and whether the robot with the skills it keeps (``merged`` if ``agrees``) cannot
    either."""
    from guided_lfd.evaluate import RobotReachability, excuse_goal

    intended, excuse = excuse_state(before, rnd.excuse), excuse_goal(rnd.request)
    culprit = misdirected_culprit(after, excuse, task.goal, intended, RobotReachability(robot, task))
    stranded = culprit is not None and (not agrees or misdirected_culprit(
        after, excuse, task.goal, intended, RobotReachability(merged, task)) is not None)
    return culprit, stranded


def check_demonstration(rnd, before: frozenset[Atom], after: frozenset[Atom], steps: list[DemonstratedAction],
                        types: dict[str, str], robot: Domain, merged: Domain, learned: list[str], task: Problem,
                        hand: set[str], human: Domain | None = None, spellings: dict[str, str] | None = None,
                        time_limit: float | None = None) -> DemonstrationCheck:
    """Check the demonstration (its ``steps``, the state ``after`` it left from ``before``) against ``rnd``'s
    request and keep-facts; ``merged``: the robot with the ``learned`` skills, ``hand``: the hand's own
    predicates (the demonstrator's business, never a change of note).  See the module docstring."""
    from guided_lfd.evaluate import excuse_goal, optimal_plan

    spellings = spellings if spellings is not None else {**task.spellings, **robot.spellings}
    request = list(rnd.request)
    reached = [c for c in request if (c.atom in after) == c.added]
    missing = [c for c in request if c not in reached]
    other = [c for c in differences(before, after) if c not in request and c.atom.predicate not in hand]
    kept_changed = [a for a in rnd.keep if a not in after]

    def reaches(domain: Domain, state: frozenset[Atom], changes: list[Change]) -> bool:
        if not changes:
            return True
        return optimal_plan(domain, replace(task, init=state), goal=excuse_goal(changes),
                            time_limit=time_limit) is not None

    def check(outcome: str, reason: str, keep: bool = True, **extra) -> DemonstrationCheck:
        return DemonstrationCheck(outcome, reason, reached, missing, other, kept_changed, keep_skills=keep, **extra)

    found = _contradictions(steps, types, robot, human, hand, spellings)
    if found:
        return check("inconsistent", "a demonstrated step contradicts a skill: " + "; ".join(found)
                     + "; nothing learned from this demonstration is kept", keep=False, contradictions=found)
    # The skills learned are kept only where they let the robot reach, from where the demonstration started,
    # what it reached of the request (all of it when it reached none).
    agrees = bool(learned) and reaches(merged, before, reached or request)
    taught = f"the robot learned {', '.join(learned)}" if learned else "nothing new was learned"
    if not reached and not agrees:
        seen = _words(other, spellings) or "no change the robot could see"
        return check("unhelpful", f"it made none of the request ({_words(request, spellings)}) but {seen}, and "
                     f"{taught}{' that reaches it' if not learned else ', which does not reach it'}; nothing is "
                     "kept, the request is asked again", keep=False)
    culprit, stranded = _stranded(rnd, before, after, task, robot, merged, agrees) if not missing else (None, False)
    if kept_changed:
        changed = ", ".join(pretty_atom(a, spellings) for a in kept_changed)
        kept = f"{taught} (kept: it reaches the request)" if agrees else (
            f"{taught}, not kept (it does not reach the request)" if learned else taught)
        return check("misdirected", f"it changed what the request said to keep: {changed} no longer holds; {kept}",
                     keep=agrees or not learned, misdirected=culprit)
    if not missing:
        if stranded:
            return check("misdirected", f"the request holds, but from the state it left the robot cannot reach "
                         f"its goal (to blame: {' '.join(str(c) for c in culprit)}); {taught}",
                         keep=agrees, misdirected=culprit)
        return check("accepted", f"it made the request; {taught}", keep=agrees or not learned, misdirected=culprit)
    if reached:
        if agrees and reaches(merged, after, missing):
            return check("accepted", f"it made {_words(reached, spellings)}; {taught}, with which the robot "
                         f"makes the rest itself ({_words(missing, spellings)})")
        return check("partial", f"it made {_words(reached, spellings)}, not {_words(missing, spellings)}; "
                     f"{taught}{' (kept)' if agrees else ''}; the next request asks for the rest", keep=agrees)
    return check("accepted", f"it made none of the request but {_words(other, spellings) or 'nothing visible'}; "
                 f"{taught}, with which the robot makes the request ({_words(request, spellings)}) itself",
                 keep=True)
