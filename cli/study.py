"""``guided-lfd study``: the paper's user study, reproduced from the shipped data."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command, ui


@command
def study(
    root: Annotated[Path, typer.Option("--root", metavar="DIR", help="Repository root (with data/).")] = Path("."),
    out: Annotated[Path, typer.Option("--out", metavar="DIR", help="Where the results go.")] = Path("results"),
    quiet: QuietOption = False,
) -> None:
    """Reproduce the paper's user study: study.md, CSVs, plots and per-demonstration artefacts in --out."""
    from guided_lfd.reporting import PLOTS_HINT
    from guided_lfd.study import run_study, side_by_side, write_artefacts, write_report

    # What guided_lfd.study.reproduce does, keeping write_report's answer: were the plots drawn?
    paper, kitchens = run_study(root, lambda message: ui.info(f"  {message}"))
    write_artefacts(out, kitchens)
    if write_report(out, paper, kitchens) is None:
        ui.info_plain(f"plots skipped: {PLOTS_HINT}")
    sys.stdout.write(side_by_side(paper, kitchens))
    ui.info(f"wrote {out / 'study.md'}")
