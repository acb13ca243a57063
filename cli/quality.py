"""``guided-lfd quality``: how well segmentation and domain learning do on labelled demonstrations."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command, help_footer, path_name
from guided_lfd import errors


@help_footer(
    example="guided-lfd quality --demos data/demos --domains data/domains",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_TRACE),
    success="report printed",
)
@command
def quality(
    demos: Annotated[Path | None, typer.Option("--demos", parser=path_name, metavar="DIR",
                                               help="Labelled demonstrations, one folder per kitchen (default: "
                                                    "data/demos of the working folder or the installed checkout).")]
    = None,
    domains: Annotated[Path | None, typer.Option("--domains", parser=path_name, metavar="DIR",
                                                 help="Each kitchen's human.pddl, the reference for learning "
                                                      "(default: the domains folder beside --demos).")] = None,
    traces: Annotated[list[Path] | None, typer.Option("--traces", parser=path_name, metavar="DIR",
                                                       help="Also every source and scenario: an independent trace "
                                                            "source DIR/SCENARIO/CONDITION/*.csv (repeatable), "
                                                            "one row per condition.")] = None,
    quiet: QuietOption = False,
) -> None:
    """Score segmentation and learning on labelled demos.

    Segmentation: frame-level activity F1 and segment counts per
    demonstration. Learning: precision and recall of the learned domain's
    preconditions and effects against each kitchen's human.pddl. Markdown on
    stdout. With --traces, a second table follows: per source, scenario
    and recording condition, frame macro-F1, segment counts, learning
    against the scenario's human.pddl, and the quality targets each row
    misses (the table's last line lists them).
    """
    from guided_lfd.demonstration.quality import quality_markdown, quality_report, sources_markdown, sources_report
    from guided_lfd.io import write_text
    from guided_lfd.paths import data_root, require, require_folder

    root = data_root(None, "data/demos")
    domains = domains or (demos.parent / "domains" if demos is not None else root / "data" / "domains")
    demos = demos or root / "data" / "demos"
    require(demos, domains, *(traces or []), hint="run from the checkout, or give --demos and --domains")
    require_folder(demos, "a folder of labelled demonstrations (one folder per kitchen)")
    require_folder(domains, "a folder of the kitchens' domains (one folder per kitchen, with human.pddl)")
    for folder in traces or []:
        require_folder(folder, "a folder of trace sources (SCENARIO/CONDITION/*.csv)")
    text = quality_markdown(quality_report(demos, domains))
    if traces:
        text += "\n## All sources\n\n" + sources_markdown(sources_report(demos, domains, traces))
    write_text("-", text)
