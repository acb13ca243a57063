"""``guided-lfd quality``: how well segmentation and domain learning do on labelled demonstrations."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command


@command
def quality(
    demos: Annotated[Path, typer.Option("--demos", metavar="DIR",
                                        help="Labelled demonstrations, one folder per kitchen.")] = Path("data/demos"),
    domains: Annotated[Path, typer.Option("--domains", metavar="DIR",
                                          help="Each kitchen's human.pddl, the reference for learning.")]
    = Path("data/domains"),
    quiet: QuietOption = False,
) -> None:
    """Segmentation frame F1 and segment counts per demonstration, learned-domain precision and recall per kitchen."""
    from guided_lfd.demonstration.quality import quality_markdown, quality_report

    sys.stdout.write(quality_markdown(quality_report(demos, domains)))
