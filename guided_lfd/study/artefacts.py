"""The study's per-demonstration artefacts: segments JSON, learned and merged PDDL domains."""

from __future__ import annotations

from pathlib import Path

from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.study.run import KitchenResult


def write_artefacts(out: Path, kitchens: list[KitchenResult]) -> None:
    """Write each demonstration's segments and learned domain, and each merged domain, under ``out/study/``."""
    for k in kitchens:
        folder = out / "study" / k.kitchen
        folder.mkdir(parents=True, exist_ok=True)
        for d in k.demonstrators:
            for kind in ("excuse", "complete"):
                demo = d.demos[kind]
                write_text(folder / f"{d.demonstrator}-{kind}.segments.json",
                           json_document("segments", demo.segments_document))
                write_text(folder / f"{d.demonstrator}-{kind}.learned.pddl",
                           domain_to_pddl(demo.learned, header=f"Learned by guided-lfd from data/demos/{k.kitchen}/"
                                                               f"{demo.trace_name}"))
            if d.merged is not None:
                write_text(folder / f"{d.demonstrator}.merged.pddl",
                           domain_to_pddl(d.merged, header=f"Merged by guided-lfd: {k.kitchen}/robot.pddl + "
                                                           f"{d.demonstrator}-excuse"))
