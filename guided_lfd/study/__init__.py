"""The paper's user study, reproduced end to end (``guided-lfd study``, ``make reproduce-study``).

For Kitchen I and II and demonstrators P1-P5 the whole chain runs on the
shipped demonstrations (``data/demos``): segment -> learn-domain -> merge ->
excuse -> evaluate.  Its results are put beside the paper's own measurements
(``data/study``: Table I demonstration times, Table II sizes).

Everything written is deterministic (no timings, sorted output, plots without
date metadata), so two runs give byte-identical files.  One stage per module:
:mod:`~guided_lfd.study.paper` (the paper's data) and
:mod:`~guided_lfd.study.run` (the chain: computes, writes nothing) feed
:mod:`~guided_lfd.study.artefacts` (segments, learned and merged domains) and
:mod:`~guided_lfd.study.report` (tables, plots, markdown, JSON).
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from guided_lfd.study.artefacts import write_artefacts
from guided_lfd.study.paper import (
    DEMONSTRATORS, KITCHEN_NAMES, KITCHENS, PaperData, headline, load_paper_data, size_reduction, time_ratios,
)
from guided_lfd.study.report import side_by_side, study_markdown, write_report
from guided_lfd.study.run import DemoResult, DemonstratorResult, KitchenResult, run_kitchen, run_study

__all__ = [
    "DEMONSTRATORS", "KITCHEN_NAMES", "KITCHENS", "PaperData", "headline", "load_paper_data", "size_reduction",
    "time_ratios", "side_by_side", "study_markdown", "write_report", "DemoResult", "DemonstratorResult",
    "KitchenResult", "run_kitchen", "run_study", "write_artefacts", "reproduce",
]


def reproduce(root: Path, out: Path,
              progress: Callable[[str], None] | None = None) -> tuple[PaperData, list[KitchenResult]]:
    """Run the study and write ``out/study.md``, CSVs, plots and per-demonstration artefacts.

    Without matplotlib the plots are skipped and ``study.md`` says so (:func:`write_report`).
    """
    paper, kitchens = run_study(root, progress)
    write_artefacts(out, kitchens)
    write_report(out, paper, kitchens)
    return paper, kitchens
