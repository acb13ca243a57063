"""``guided-lfd demos``: render the study's demonstrations (the shipped data/demos) again."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command, help_footer, ui
from guided_lfd import errors


@help_footer(
    example="guided-lfd demos data/demos",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_OUTPUT),
    success="demonstrations rendered",
)
@command
def demos(
    out: Annotated[Path, typer.Argument(metavar="OUT", help="Where the traces go.")] = Path("data/demos"),
    domains: Annotated[Path, typer.Option("--domains", metavar="DIR",
                                          help="The kitchens' domains and problems.")] = Path("data/domains"),
    quiet: QuietOption = False,
) -> None:
    """Render the study's demonstrations as hand traces.

    Kitchen I and II x participants P1-P5, each an excuse and a complete
    demonstration: TRACE.csv and TRACE.state.csv per demonstration, byte for
    byte the shipped data/demos.
    """
    from guided_lfd.demonstration.study_data import render_study

    rendered = render_study(domains, out)
    ui.info(f"rendered {len(rendered)} demonstrations into {out}")
