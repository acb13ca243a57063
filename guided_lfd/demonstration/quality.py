"""How well demonstrations are segmented and learned: the #4 quality report.

``guided-lfd quality`` prints, for the shipped
demonstrations, the frame-level activity F1 against the rendered ground truth,
whether the segment count matches exactly, and the precision and recall of
the learned actions' preconditions and effects against the human domain (the
measures of action-model-learning benchmarks).
"""

from __future__ import annotations

import csv
import itertools
from dataclasses import dataclass
from pathlib import Path

from guided_lfd.demonstration.learn import learn_domain
from guided_lfd.demonstration.render import frame_f1
from guided_lfd.demonstration.segment import Segment, segment, segments_document
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.pddl.model import ActionSchema, Domain
from guided_lfd.pddl.reader import parse_domain


@dataclass
class SegmentationQuality:
    """Segmentation of one rendered demonstration against its labels."""

    name: str
    f1: float
    truth_segments: int
    segments: int


def segmentation_quality(trace: Path) -> SegmentationQuality:
    """Frame F1 and segment counts of one demonstration with a ``.labels.csv``."""
    demo = load_demonstration(str(trace))
    segments = segment(demo)
    with open(str(trace).replace(".csv", ".labels.csv"), encoding="utf-8", newline="") as fh:
        labels = list(csv.DictReader(fh))
    truth, predicted = [], []
    for row in labels:
        t, hand = float(row["time"]), row["hand"]
        match = [s for s in segments if s.hand == hand and s.start - 1e-6 <= t <= s.end + 1e-6]
        truth.append(row["activity"])
        predicted.append(match[0].activity if match else "Idle")
    count = 0
    for hand in ("left", "right"):
        seq = [r["activity"] for r in labels if r["hand"] == hand]
        count += sum(1 for i, a in enumerate(seq) if a != "Idle" and (i == 0 or seq[i - 1] != a))
    return SegmentationQuality(f"{trace.parent.name}/{trace.stem}", frame_f1(truth, predicted), count,
                               sum(1 for s in segments if s.activity != "Idle"))


def _sets(action: ActionSchema, mapping: dict[str, str]):
    pre = {l.substitute(mapping) for l in action.precondition}
    eff = {("+", a.substitute(mapping)) for a in action.add} | {("-", a.substitute(mapping)) for a in action.delete}
    return pre, eff


def compare_actions(learned: ActionSchema, reference: ActionSchema) -> tuple[int, int, int, int, int, int] | None:
    """(pre TP, FP, FN, effect TP, FP, FN) under the best parameter mapping, None if no effect matches."""
    ref_pre, ref_eff = _sets(reference, {})
    best = None
    params = [v for v, _ in learned.params]
    for target in itertools.permutations([v for v, _ in reference.params] + [f"?free{i}" for i in range(len(params))],
                                         len(params)):
        pre, eff = _sets(learned, dict(zip(params, target)))
        score = (len(eff & ref_eff), len(pre & ref_pre))
        if best is None or score > best[0]:
            best = (score, pre, eff)
    if best is None or best[0][0] == 0:
        return None
    _, pre, eff = best
    return (len(pre & ref_pre), len(pre - ref_pre), len(ref_pre - pre),
            len(eff & ref_eff), len(eff - ref_eff), len(ref_eff - eff))


def learning_quality(learned: Domain, reference: Domain) -> dict[str, float | list[str]]:
    """Pooled precision and recall of preconditions and effects over matched actions."""
    totals = [0] * 6
    matched: list[str] = []
    for act in learned.actions:
        scores = [(compare_actions(act, ref), ref.name) for ref in reference.actions]
        scores = [(s, n) for s, n in scores if s is not None]
        if not scores:
            continue
        (s, name) = max(scores, key=lambda x: (x[0][3] - x[0][4] - x[0][5], x[0][0] - x[0][1] - x[0][2]))
        matched.append(f"{act.name} ~ {name}")
        totals = [a + b for a, b in zip(totals, s)]
    tp, fp, fn, etp, efp, efn = totals

    def ratio(a: int, b: int) -> float:
        return a / b if b else 1.0

    return {"pre_precision": ratio(tp, tp + fp), "pre_recall": ratio(tp, tp + fn),
            "eff_precision": ratio(etp, etp + efp), "eff_recall": ratio(etp, etp + efn), "matched": matched}


@dataclass
class QualityReport:
    """Segmentation of every shipped demonstration and learning per kitchen."""

    segmentation: list[SegmentationQuality]
    learning: dict[str, dict[str, float | list[str]]]

    @property
    def exact_fraction(self) -> float:
        """Share of demonstrations whose segment count matches the ground truth exactly."""
        return sum(q.truth_segments == q.segments for q in self.segmentation) / len(self.segmentation)

    @property
    def min_f1(self) -> float:
        """The lowest frame F1 over the demonstrations."""
        return min(q.f1 for q in self.segmentation)


def _traces(folder: Path) -> list[Path]:
    return sorted(p for p in folder.glob("*.csv") if not p.name.endswith((".state.csv", ".labels.csv")))


def quality_report(demos: Path = Path("data/demos"), domains: Path = Path("data/domains")) -> QualityReport:
    """Measure every demonstration under ``demos/<kitchen>/`` against its labels and ``domains/<kitchen>/human.pddl``.

    All demonstrations are learned from, P3's complete ones too: the paper's
    tool could not process their two hands at once, per-hand segmentation can.
    """
    kitchens = sorted(p for p in demos.iterdir() if p.is_dir() and _traces(p))
    segmentation = [segmentation_quality(trace) for kitchen in kitchens for trace in _traces(kitchen)]
    learning = {}
    for kitchen in kitchens:
        documents = []
        for trace in _traces(kitchen):
            demo = load_demonstration(str(trace))
            documents.append((trace.name, segments_document(demo, segment(demo), "")))
        learning[kitchen.name] = learning_quality(learn_domain(documents), parse_domain(domains / kitchen.name / "human.pddl"))
    return QualityReport(segmentation, learning)


def quality_markdown(report: QualityReport) -> str:
    """The report as ``guided-lfd quality`` prints it: the segmentation table, then learning per kitchen."""
    lines = ["| demonstration | frame F1 | segments (truth / found) |", "|---|---|---|"]
    for q in report.segmentation:
        lines.append(f"| {q.name} | {q.f1:.3f} | {q.truth_segments} / {q.segments} |")
    exact = sum(q.truth_segments == q.segments for q in report.segmentation)
    lines += ["", f"segment counts exact: {exact} / {len(report.segmentation)}; minimum frame F1 {report.min_f1:.3f}", ""]
    for kitchen, learned in report.learning.items():
        lines.append(f"{kitchen}: preconditions precision {learned['pre_precision']:.2f} recall "
                     f"{learned['pre_recall']:.2f}; effects precision {learned['eff_precision']:.2f} recall "
                     f"{learned['eff_recall']:.2f}; {', '.join(learned['matched'])}")  # type: ignore[arg-type]
    return "\n".join(lines) + "\n"


__all__ = ["Segment", "segmentation_quality", "learning_quality", "compare_actions", "quality_report", "QualityReport",
           "quality_markdown"]
