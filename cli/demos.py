"""``guided-lfd demos``: render the study's demonstrations (the shipped data/demos) again."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command, ui


@command
def demos(
    out: Annotated[Path, typer.Argument(metavar="OUT", help="Where the traces go.")] = Path("data/demos"),
    domains: Annotated[Path, typer.Option("--domains", metavar="DIR",
                                          help="The kitchens' domains and problems.")] = Path("data/domains"),
    quiet: QuietOption = False,
) -> None:
    """Render the study's demonstrations (Kitchen I/II x P1-P5, excuse and complete) as hand traces."""
    from guided_lfd.demonstration.study_data import render_study

    rendered = render_study(domains, out)
    ui.info(f"rendered {len(rendered)} demonstrations into {out}")
