"""``guided-lfd learn-domain``: demonstration segments -> a PDDL domain of the demonstrated skills."""

from __future__ import annotations

from typing import Annotated

import typer

from cli.common import OutputOption, QuietOption, check_files, command, help_footer, ui
from guided_lfd import errors
from guided_lfd.demonstration.learn import learn_domain as learn
from guided_lfd.demonstration.segments_document import load_segments
from guided_lfd.errors import OptionError
from guided_lfd.io import write_text
from guided_lfd.pddl.model import pddl_name_defect
from guided_lfd.pddl.reader import parse_domain
from guided_lfd.pddl.writer import domain_to_pddl


@help_footer(
    example="guided-lfd learn-domain p1.segments.json -o p1.learned.pddl",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_TRACE, errors.EXIT_OUTPUT),
    success="domain written",
)
@command
def learn_domain(
    segments: Annotated[list[str], typer.Argument(metavar="SEGMENTS",
                                                  help="Segments JSON files from 'guided-lfd segment' "
                                                       "('-' = stdin).")],
    prior: Annotated[
        str | None, typer.Option("--prior", metavar="DOMAIN", help="Keep this domain's types, predicates and actions.")
    ] = None,
    human: Annotated[
        str | None, typer.Option("--human", metavar="DOMAIN",
                                 help="The demonstrator's domain: skills with a human action's effects take its "
                                      "name and parameter order.")
    ] = None,
    name: Annotated[str, typer.Option("--name", metavar="NAME", help="Name of the learned domain.")] = "learned",
    output: OutputOption = "-",
    quiet: QuietOption = False,
) -> None:
    """Turn demonstrated hand activities into PDDL actions.

    Each demonstrated skill becomes a lifted action: its preconditions are the
    nodes of interest of the demonstrated states, generalised over repeats.
    With --prior the domain keeps the prior's types, predicates and actions,
    the hand's facts are the prior's own (unless the demonstration's state
    file declares them), steps the prior already makes are not learned again,
    and a skill that could never run beside the prior's is refused.
    """
    why = pddl_name_defect(name.lower())
    if why:
        raise OptionError(f"--name {name!r}: expected {why}")
    check_files([*segments, prior, human], {"--output": output})
    documents = [(path, load_segments(path)) for path in segments]
    prior_domain = parse_domain(prior) if prior else None
    ui.reading_warnings(prior_domain)
    human_domain = parse_domain(human) if human else None
    domain = learn(documents, prior_domain, name=name.lower(), human=human_domain, skip_known=prior is not None)
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
    write_text(output, domain_to_pddl(domain, header=header))
    # With --prior the result keeps the prior's actions under their names; the rest were demonstrated.
    known = {a.name for a in prior_domain.actions} if prior_domain is not None else set()
    learned = [a for a in domain.actions if a.name not in known]
    ui.info(f"[dim]{len(learned)} demonstrated skill(s): {', '.join(a.name for a in learned)}[/]")
