"""``guided-lfd study``: the paper's user study, reproduced from the shipped data."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, check_apart, check_output_folder, command, help_footer, ui, path_name
from guided_lfd import errors


@help_footer(
    example="guided-lfd study --root . --out results",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_TRACE, errors.EXIT_OUTPUT),
    success="study reproduced",
)
@command
def study(
    root: Annotated[Path | None, typer.Option("--root", parser=path_name, metavar="DIR", help="Repository root (with data/; default: "
                                                                        "the working folder if it has the data, "
                                                                        "else the installed checkout).")] = None,
    out: Annotated[Path, typer.Option("--out", parser=path_name, metavar="DIR", help="Where the results go.")] = Path("results"),
    quiet: QuietOption = False,
) -> None:
    """Reproduce the paper's user study from the shipped data.

    Runs segment, learn-domain, merge, excuse and evaluate on every rendered
    demonstration and writes study.md, CSVs, plots, study.json and each
    demonstration's artefacts into --out; prints the headline figures beside
    the paper's.
    """
    from guided_lfd.reporting import PLOTS_HINT
    from guided_lfd.io import staged_folder, write_text
    from guided_lfd.paths import data_root, require
    from guided_lfd.study import run_study, side_by_side, write_artefacts, write_report

    root = data_root(root, "data/study")
    study_data = root / "data" / "study"
    require(*(study_data / f"{name}.csv" for name in ("table1-demonstration-time", "table1-ratio",
                                                       "table2-demonstration-size")),
            root / "data" / "demos", root / "data" / "domains")
    check_output_folder(out, "--out")
    check_apart(out, "--out", [root / "data"], root)
    # What guided_lfd.study.reproduce does, keeping write_report's answer: were the plots drawn?
    paper, kitchens = run_study(root, lambda message: ui.info(f"  {message}"))
    with staged_folder(out) as stage:  # an interrupted run leaves --out as it was
        write_artefacts(stage, kitchens)
        drawn = write_report(stage, paper, kitchens)
    if drawn is None:
        ui.info_plain(f"plots skipped: {PLOTS_HINT}")
    write_text("-", side_by_side(paper, kitchens))
    ui.info(f"wrote {out / 'study.md'}")
