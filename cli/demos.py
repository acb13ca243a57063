"""``guided-lfd demos``: render the study's demonstrations (the shipped data/demos) again."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, check_apart, check_output_folder, command, help_footer, ui, path_name
from guided_lfd import errors


@help_footer(
    example="guided-lfd demos data/demos",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_OUTPUT),
    success="demonstrations rendered",
)
@command
def demos(
    out: Annotated[Path | None, typer.Argument(parser=path_name, metavar="OUT", help="Where the traces go (default: the shipped "
                                                                  "data/demos).")] = None,
    domains: Annotated[Path | None, typer.Option("--domains", parser=path_name, metavar="DIR",
                                                 help="The kitchens' domains and problems (default: the shipped "
                                                      "data/domains).")] = None,
    quiet: QuietOption = False,
) -> None:
    """Render the study's demonstrations as hand traces.

    Kitchen I and II x participants P1-P5, each an excuse and a complete
    demonstration: TRACE.csv and TRACE.state.csv per demonstration, byte for
    byte the shipped data/demos.
    """
    from guided_lfd.demonstration.study_data import render_study
    from guided_lfd.io import staged_folder
    from guided_lfd.paths import data_root, require

    root = data_root(None, "data/domains")
    domains = domains or root / "data" / "domains"
    out = out or root / "data" / "demos"
    require(domains, hint="run from the checkout, or give --domains")
    check_output_folder(out, "OUT")
    check_apart(out, "OUT", [domains])
    with staged_folder(out) as stage:  # an interrupted run leaves OUT as it was
        rendered = render_study(domains, stage)
    ui.info(f"rendered {len(rendered)} demonstrations into {out}")
