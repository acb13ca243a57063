"""``guided-lfd learn-domain``: demonstration segments -> a PDDL domain of the demonstrated skills."""

from __future__ import annotations

from dataclasses import replace
from typing import Annotated

import typer

from cli.common import (JsonOption, MemoryLimitOption, OutputOption, QuietOption, TimeLimitOption, apply_memory_limit,
                        check_files, check_time_limit, command, help_footer, output_format, started_at, ui)
from guided_lfd import errors
from guided_lfd.deadline import deadline_after, watchdog
from guided_lfd.demonstration.learn import learn_domain as learn
from guided_lfd.demonstration.action_model import MODELS
from guided_lfd.demonstration.segments_document import load_segments
from guided_lfd.demonstration.trajectory import is_trajectory, learn_from_trajectories, read_trajectory
from guided_lfd.pddl.fit import check_model_fits
from guided_lfd.errors import Location, MismatchError, OptionError
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.model import pddl_name_defect
from guided_lfd.pddl.reader import parse_domain, parse_problem_for
from guided_lfd.io import read_text
from guided_lfd.pddl.writer import domain_to_pddl


@help_footer(
    example="guided-lfd learn-domain p1.segments.json -o p1.learned.pddl",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_TRACE, errors.EXIT_BAD_OPTION, errors.EXIT_TOO_LARGE, errors.EXIT_OUTPUT,
                errors.EXIT_TIME_LIMIT, errors.EXIT_MEMORY),
    success="domain written",
)
@command
def learn_domain(
    segments: Annotated[list[str], typer.Argument(metavar="DEMONSTRATIONS",
                                                  help="Segments JSON files from 'guided-lfd segment', or PDDL "
                                                       "trajectory files '(:trajectory (:state ...) (:action ...) "
                                                       "...)' with --prior; told apart by content ('-' = stdin).")],
    prior: Annotated[
        str | None, typer.Option("--prior", metavar="DOMAIN", help="Keep this domain's types, predicates and actions.")
    ] = None,
    human: Annotated[
        str | None, typer.Option("--human", metavar="DOMAIN",
                                 help="The demonstrator's domain: skills with a human action's effects take its "
                                      "name and parameter order.")
    ] = None,
    name: Annotated[str | None, typer.Option("--name", metavar="NAME",
                                             help="Name of the learned domain (default: 'learned'; from "
                                                  "trajectories, the prior's).")] = None,
    problem: Annotated[
        list[str] | None, typer.Option("--problem", metavar="FILE",
                                       help="Trajectories: a problem whose objects' types the trajectories use "
                                            "(repeatable; default: inferred from the operators and predicates).")
    ] = None,
    model: Annotated[
        str, typer.Option("--model", metavar="MODEL",
                          help="Trajectories: 'safe' (every plan it finds is valid in the true domain) or "
                               "'general' (what the steps show, guarded where an action clears whatever is there; "
                               "fewer conditions, no such guarantee).")
    ] = "safe",
    output: OutputOption = "-",
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    memory_limit: MemoryLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Learn PDDL actions from demonstrations or trajectories.

    Each demonstrated skill becomes a lifted action: its preconditions are the
    nodes of interest of the demonstrated states, generalised over repeats.
    Trajectories teach the --prior's operators that have empty bodies, under
    their names and parameters (see --model).
    With --prior the domain keeps the prior's types, predicates and actions,
    the hand's facts are the prior's own (unless the demonstration's state
    file declares them), steps the prior already makes are not learned again,
    and a skill that could never run beside the prior's is refused.
    Each learned precondition's evidence (in how many demonstrations it
    held) is a comment above its action; --json writes a document holding
    the domain and each skill's evidence.
    """
    why = pddl_name_defect(name.lower()) if name is not None else None
    if why:
        raise OptionError(f"--name {name!r}: expected {why}")
    time_limit = check_time_limit(time_limit)
    apply_memory_limit(memory_limit)
    check_files([*segments, prior, human, *(problem or [])], {"--output": output})
    json_out = output_format(output, json_out, default="pddl") == "json"
    if model not in MODELS:
        raise OptionError(f"--model {model!r}: expected one of {', '.join(MODELS)}")
    # The time limit bounds the whole run, reading included; nothing is written when it strikes.
    with watchdog(deadline_after(time_limit, started_at()), "learn-domain", grace=0.0):
        _learn(segments, prior, human, name, problem, model, output, json_out)


def _learn(segments: list[str], prior: str | None, human: str | None, name: str | None, problem: list[str] | None,
           model: str, output: str, json_out: bool) -> None:
    """Read the demonstrations or trajectories, learn, write (see :func:`learn_domain`)."""
    texts = [(path, read_text(path, "segments JSON or a PDDL trajectory")) for path in segments]
    trajectories = [path for path, text in texts if is_trajectory(text)]
    if trajectories:
        kept = [path for path, _ in texts if path not in trajectories]
        if kept:
            raise OptionError(f"{kept[0]} holds segments and {trajectories[0]} a trajectory; expected one kind "
                              "per run")
        return _from_trajectories(texts, prior, problem or [], model, human, name, output, json_out)
    if problem or model != "safe":
        raise OptionError(f"{'--problem' if problem else '--model'} is for trajectories; "
                          f"{segments[0]} holds segments")
    documents = [(path, load_segments(path, text)) for path, text in texts]
    prior_domain = parse_domain(prior) if prior else None
    ui.reading_warnings(prior_domain)
    human_domain = parse_domain(human) if human else None
    if prior_domain is not None and human_domain is not None:
        check_model_fits(prior_domain, human_domain, "--human")  # as excuse, teach, evaluate: exit 34
    domain = learn(documents, prior_domain, name=(name or "learned").lower(), human=human_domain, skip_known=prior is not None)
    if prior_domain is not None:
        from guided_lfd.demonstration.learn import check_usable, document_vocabulary

        check_usable(domain, prior_domain, {a.name for a in domain.actions} - {a.name for a in prior_domain.actions},
                     ", ".join(segments))
        for path, doc in documents:
            if "vocabulary" not in doc:
                vocabulary = document_vocabulary(doc, prior_domain, human_domain, source=path)
                ui.info(f"[dim]{path}: hand facts: {vocabulary.describe()} (from {vocabulary.origin})[/]")
    # Demonstrations the learner left out or reconciled (their effects disagree with the others').
    ui.reading_warnings(domain)
    header = "Learned by guided-lfd learn-domain from: " + ", ".join(segments)
    # With --prior the result keeps the prior's actions under their names; the rest were demonstrated.
    known = {a.name for a in prior_domain.actions} if prior_domain is not None else set()
    _write(output, domain, header, known, segments, json_out)
    learned = [a for a in domain.actions if a.name not in known]
    ui.info(f"[dim]{len(learned)} demonstrated skill(s): {', '.join(a.name for a in learned)}[/]")


def _write(output: str, domain, header: str, known: set[str], inputs: list[str], json_out: bool) -> None:
    """The learned domain as PDDL, or with ``json_out`` a ``guided-lfd/learned`` document holding it and the
    evidence of each skill not in ``known``."""
    from guided_lfd.demonstration.learn import learned_skills

    text = domain_to_pddl(domain, header=header)
    if json_out:
        text = json_document("learned", {"inputs": inputs, "domain": text, "skills": learned_skills(domain, known)})
    write_text(output, text)


def _from_trajectories(texts: list[tuple[str, str]], prior: str | None, problems: list[str], model: str,
                       human: str | None, name: str | None, output: str, json_out: bool = False) -> None:
    """learn-domain on PDDL trajectories: the prior's empty-bodied operators learned (``--model``)."""
    if prior is None:
        raise OptionError(f"{texts[0][0]} is a trajectory: expected --prior DOMAIN with the operators' signatures")
    if human is not None:
        raise OptionError("--human is for segments: a trajectory names its operators already")
    prior_domain = parse_domain(prior)
    ui.reading_warnings(prior_domain)
    objects: dict[str, str] | None = {} if problems else None
    for path in problems:
        for obj, t in parse_problem_for(prior_domain, path).objects.items():
            if objects.setdefault(obj, t) != t:
                raise MismatchError(f"object '{obj}' is a {t} in {path} and a {objects[obj]} in an earlier "
                                    "--problem; expected one type", Location(path))
    trajectories = [read_trajectory(path, text, prior_domain, objects) for path, text in texts]
    domain = learn_from_trajectories(prior_domain, trajectories, model)
    if name is not None:
        domain = replace(domain, name=name.lower())
    ui.reading_warnings(domain)
    header = f"Learned by guided-lfd learn-domain (--model {model}) from: " + ", ".join(p for p, _ in texts)
    steps = sum(len(t.steps) for t in trajectories)
    learned = [a.name for a in domain.actions if a.origin and a.origin.startswith("learned from")]
    _write(output, domain, header, {a.name for a in domain.actions} - set(learned), [p for p, _ in texts], json_out)
    ui.info(f"[dim]{len(learned)} operator(s) learned from {steps} step(s) of {len(trajectories)} "
            f"trajectory(ies), {model} model: {', '.join(learned)}[/]")
