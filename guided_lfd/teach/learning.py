"""A round's demonstration learned: segmented, checked to start where the task is, its skills learned in the
robot's hand facts and merged into the robot's domain, and the state it left read off its end."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from guided_lfd.demonstration.vocabulary import KITCHEN, HandVocabulary
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.teach.check import check_demonstration
from guided_lfd.teach.session import Round

__all__ = ["learn_round"]


def learn_round(rnd: Round, folder: Path, out: Path, robot: Domain, task: Problem,
                 given: tuple[Path, Path], human: Domain | None = None, original: Domain | None = None,
                 history: list[tuple[str, dict]] | None = None,
                 time_limit: float | None = None, checks: bool = True) -> tuple[Domain, frozenset[Atom]]:
    """Segment the demonstration, learn its skills (in the robot's hand facts, named after the ``human``
    model's actions), merge them into the robot; (new domain, state it left).  A skill that could never run
    beside the robot's is a MismatchError.

    With the ``original`` robot and the ``history`` of earlier rounds' demonstrations, the skills are learned
    from all of them and merged into the original: a skill shown again from another situation (unstacking off
    a block, not the table) is generalised, not learned twice.

    The demonstration is checked against the round's request first (:mod:`guided_lfd.teach.check`,
    ``rnd.check``): skills from a demonstration that is ``inconsistent`` or ``unhelpful``, or that do not reach
    what was asked, are not merged (the robot's domain stays as it was); the world stays as it left it.
    ``checks`` False keeps whatever was learned, whatever the check says (the loop without checks, for
    measuring what they prevent)."""
    from guided_lfd.demonstration.learn import (check_usable, document_vocabulary, ground_actions, learn_domain,
                                                robot_declarations, within_declarations)
    from guided_lfd.demonstration.segment import segment, segments_document
    from guided_lfd.demonstration.trace import load_demonstration
    from guided_lfd.merge import merge_domains

    trace, states = given
    demo = load_demonstration(str(trace), str(states))
    acting = [s for s in segment(demo) if s.activity != "Idle"]
    doc = segments_document(demo, acting, str(states))
    doc["trace"] = str(trace)
    write_text(folder / "segments.json", json_document("segments", doc))
    rnd.files.update(trace=str(trace), state=str(states), segments=str(folder / "segments.json"))
    from guided_lfd.evaluate import usefulness

    _check_start(demo, task, trace)  # a demonstration of another world is refused before anything is learned
    base = original if original is not None else robot
    vocabulary = document_vocabulary(doc, base, human, source=str(trace))
    rnd.vocabulary = f"{vocabulary.describe()} (from {vocabulary.origin})"
    demonstrated = ground_actions(doc, str(trace), vocabulary=vocabulary)
    rnd.demonstration_length = len(demonstrated)
    types = doc.get("objects", {})
    rnd.new_actions = usefulness(demonstrated, robot, types).useful
    documents = [*(history or []), (str(trace), doc)]
    learned = learn_domain(documents, name=f"learned-round-{rnd.index}", context=base, human=human, skip_known=True)
    # The robot's declaration of a predicate stands: merging a learned one would widen its argument types.
    learned = replace(learned, predicates=robot_declarations(learned.predicates, base),
                      actions=within_declarations(learned.actions, base))
    write_text(folder / "learned.pddl", domain_to_pddl(learned, header=f"Learned from {trace}"))
    merged = merge_domains([base, learned], name=robot.name).domain
    # New skills, and skills this demonstration generalised (the same name, another body).
    known = {a.name: (a.params, a.precondition, a.add, a.delete) for a in robot.actions}
    changed = [a.name for a in merged.actions if known.get(a.name) != (a.params, a.precondition, a.add, a.delete)]
    check_usable(merged, base, {a.name for a in merged.actions} - {a.name for a in base.actions}, str(trace))
    state = _state_after(demo, task, merged, vocabulary)
    rnd.unmet = [c for c in rnd.request if (c.atom in state) != c.added]
    rnd.request_met = not rnd.unmet
    # Checked against the request before anything learned from it is kept (#52).
    rnd.check = check_demonstration(rnd, task.init, state, demonstrated, types, robot, merged, changed, task,
                                    set(vocabulary.predicates), human, time_limit=time_limit)
    if not rnd.check.keep_skills and checks:
        merged = robot
    else:
        rnd.learned_actions = changed
        if history is not None:
            history.append((str(trace), doc))
    write_text(folder / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    write_text(out / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    rnd.files.update(learned=str(folder / "learned.pddl"), robot=str(folder / "robot.pddl"))
    return merged, state


def _traced_predicates(demo) -> set[str]:
    """The predicates the demonstration's state file records (its fluents' vocabulary)."""
    return {a.predicate for a in demo.initial} | {a.predicate for _, a, _ in demo.events}


def _check_start(demo, task: Problem, trace: Path) -> None:
    """The demonstration starts where the task is now: its objects are the task's, its first state is the
    task's current one on the fluents the trace records (a trace of another world is refused, exit 34)."""
    from guided_lfd.errors import Location, MismatchError

    unknown = sorted(set(demo.objects) - set(task.objects))
    if unknown:
        raise MismatchError(f"the demonstration has object(s) the task does not: {', '.join(unknown)} "
                            "(expected a demonstration of this task)", Location(str(trace)))
    traced = _traced_predicates(demo)
    here = {a for a in task.init if a.predicate in traced}
    differ = sorted(here ^ set(demo.initial))
    if differ:
        which = differ[0]
        side = "true now but not at the demonstration's start" if which in here else "true at its start, not now"
        raise MismatchError(f"the demonstration starts from another state: {which} is {side} "
                            f"({len(differ)} fact(s) differ; expected a demonstration from the task's current "
                            "state)", Location(str(trace)))


def _state_after(demo, task: Problem, robot: Domain, vocabulary: HandVocabulary = KITCHEN) -> frozenset[Atom]:
    """The world as the demonstration left it: the state file's fluents after its last change, the hand facts
    (in the robot's ``vocabulary``) as the trace's last frames say, the rest as it was."""
    # Every change the state file records, those after the trace's last frame too (the tracker may lose the
    # hand's last frames; the world still changed).
    observed = demo.state_at(float("inf"))
    traced = _traced_predicates(demo)
    state = {a for a in task.init if a.predicate not in traced and a.predicate not in vocabulary.predicates}
    state |= set(observed)
    last = demo.frames.groupby("hand")["in_hand"].last()
    held = {str(hand): str(v).strip().lower() for hand, v in last.items() if str(v).strip() and str(v) != "nan"}
    if vocabulary.by_arm:
        for hand in ("left", "right"):
            state |= vocabulary.fluents(hand, held.get(hand, ""))
    else:  # one hand in the robot's words: it holds what either trace hand holds, free when neither holds
        for obj in held.values():
            state |= vocabulary.fluents("right", obj)
        if not held:
            state |= vocabulary.fluents("right", "")
    return frozenset(a for a in state if a.predicate in robot.predicates or a.predicate not in vocabulary.predicates)

