"""How well demonstrations are segmented and learned: the quality report.

``guided-lfd quality`` prints, for the shipped
demonstrations, the frame-level activity F1 against the rendered ground truth,
whether the segment count matches exactly, and the precision and recall of
the learned actions' preconditions and effects against the human domain (the
measures of action-model-learning benchmarks).

With ``--traces DIR`` it also measures every source and scenario:
the shipped rendered demonstrations and an independent trace source laid out
as ``DIR/<scenario>/<condition>/*.csv`` (``tests/data/traces``, made by its
own generator), one row per source, scenario and recording condition, with
learning scored against the scenario's ``human.pddl`` (``DIR/<scenario>/``,
else ``--domains``/<scenario>/), and the quality targets (``TARGET_*``) each row misses.
"""

from __future__ import annotations

import csv
import itertools
import re
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
    labels = _labels(Path(str(trace).replace(".csv", ".labels.csv")))
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


def _labels(path: Path) -> list[dict[str, str]]:
    """The rows of a ``.labels.csv`` (time, hand, activity); a file missing or not of that shape is an
    :class:`~guided_lfd.errors.InputFileError` naming it."""
    from guided_lfd.errors import InputFileError, Location

    try:
        with open(path, encoding="utf-8", newline="") as fh:
            reader = csv.DictReader(fh)
            rows = list(reader)
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise InputFileError(f"cannot read the labels ({getattr(exc, 'strerror', None) or exc}); expected a "
                             ".labels.csv beside each trace", Location(str(path))) from None
    missing = [c for c in ("time", "hand", "activity") if c not in (reader.fieldnames or [])]
    if missing:
        raise InputFileError(f"missing column(s) {', '.join(missing)}; expected time,hand,activity",
                             Location(str(path), 1))
    for number, row in enumerate(rows, start=2):
        try:
            float(row["time"])
        except (TypeError, ValueError):
            raise InputFileError(f"column 'time': {row['time']!r} is not a number", Location(str(path), number)) \
                from None
    return rows


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


def skill_quality(learned: list[ActionSchema], reference: Domain) -> dict[str, float]:
    """Pooled precision and recall of ``learned`` skills against ``reference``'s actions: each skill against the
    action of its name (skills named after a human model's action), else the best-matching one; a skill no
    action matches counts its effects as wrong."""
    totals = [0] * 6
    for action in learned:
        same = [a for a in reference.actions if a.name == action.name]
        scores = [s for s in (compare_actions(action, ref) for ref in same or reference.actions) if s is not None]
        if not scores:
            totals[4] += len(action.add) + len(action.delete)
            continue
        best = max(scores, key=lambda s: (s[3] - s[4] - s[5], s[0] - s[1] - s[2]))
        totals = [a + b for a, b in zip(totals, best)]
    tp, fp, fn, etp, efp, efn = totals

    def ratio(a: int, b: int) -> float:
        return round(a / b, 3) if b else 1.0

    return {"pre_precision": ratio(tp, tp + fp), "pre_recall": ratio(tp, tp + fn),
            "eff_precision": ratio(etp, etp + efp), "eff_recall": ratio(etp, etp + efn)}


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
    if not kitchens:
        from guided_lfd.errors import InputFileError, Location

        raise InputFileError("holds no labelled demonstrations (expected KITCHEN/TRACE.csv with TRACE.labels.csv "
                             "beside it, as data/demos has)", Location(str(demos)))
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


#: The quality targets a row of ``--traces`` must meet: segment counts exact from 20 Hz up, the lowest frame
#: F1 and the learned skills' precision and recall at least these (the table's last line prints them).
TARGET_F1 = 0.95
TARGET_F1_LOW_RATE = 0.9  # at 15 Hz (below 20 Hz)
TARGET_LEARNING = 0.9
_LEARNING_KEYS = (("pre_precision", "pre P"), ("pre_recall", "pre R"), ("eff_precision", "eff P"),
                  ("eff_recall", "eff R"))


@dataclass
class ConditionQuality:
    """Segmentation and learning of the demonstrations of one source, scenario and recording condition."""

    source: str
    scenario: str
    condition: str
    rate_hz: float  # the lowest frame rate among the demonstrations
    segmentation: list[SegmentationQuality]
    learning: dict[str, float | list[str]]
    skills: list[str]
    max_rate_hz: float = 0.0

    @property
    def min_f1(self) -> float:
        return min(q.f1 for q in self.segmentation)

    @property
    def truth_segments(self) -> int:
        return sum(q.truth_segments for q in self.segmentation)

    @property
    def segments(self) -> int:
        return sum(q.segments for q in self.segmentation)

    @property
    def exact(self) -> int:
        """Demonstrations whose segment count matches the ground truth exactly."""
        return sum(q.truth_segments == q.segments for q in self.segmentation)

    @property
    def near_duplicates(self) -> list[str]:
        """Learned skills renamed ``name_2`` ...: repeats the learner could not reconcile with a skill."""
        return [s for s in self.skills if re.search(r"_\d+$", s)]

    def misses(self) -> list[str]:
        """The quality targets this row does not meet (short labels, as the table's last column has them)."""
        out = []
        if self.rate_hz >= 19.5 and self.exact < len(self.segmentation):
            out.append("counts")
        if self.min_f1 < (TARGET_F1 if self.rate_hz >= 19.5 else TARGET_F1_LOW_RATE):
            out.append("F1")
        out += [label for key, label in _LEARNING_KEYS if float(self.learning[key]) < TARGET_LEARNING]  # type: ignore[arg-type]
        if self.near_duplicates:
            out.append("duplicates")
        return out


def frame_rate(trace: Path) -> float:
    """The trace's frame rate (Hz): one over the median time step of a hand (duplicated frames aside)."""
    with open(trace, encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    steps = []
    for hand in {r["hand"].strip().lower() for r in rows}:
        times = sorted({float(r["time"]) for r in rows if r["hand"].strip().lower() == hand})
        steps += [b - a for a, b in zip(times, times[1:])]
    steps.sort()
    return float(round(1.0 / steps[len(steps) // 2])) if steps else 0.0


def _learned(traces: list[Path]) -> Domain:
    documents = []
    for trace in traces:
        demo = load_demonstration(str(trace))
        documents.append((trace.name, segments_document(demo, segment(demo), "")))
    return learn_domain(documents)


def condition_quality(source: str, scenario: str, condition: str, traces: list[Path],
                      reference: Domain) -> ConditionQuality:
    """Measure ``traces`` (one condition) and the domain learned from them all against ``reference``."""
    learned = _learned(traces)
    rates = sorted(frame_rate(t) for t in traces)
    return ConditionQuality(source, scenario, condition, rates[0], [segmentation_quality(t) for t in traces],
                            learning_quality(learned, reference), [a.name for a in learned.actions])


def _reference(folder: Path, domains: Path) -> Domain:
    own = folder / "human.pddl"
    return parse_domain(own if own.exists() else domains / folder.name / "human.pddl")


def _conditions(scenario: Path) -> list[Path]:
    """The condition folders of a scenario, in the manifest's order when there is one, else by name."""
    folders = [p for p in scenario.iterdir() if p.is_dir() and _traces(p)]
    manifest = scenario.parent / "manifest.csv"
    order: dict[str, int] = {}
    if manifest.exists():
        with open(manifest, encoding="utf-8", newline="") as fh:
            for row in csv.DictReader(fh):
                order.setdefault(row["condition"], len(order))
    return sorted(folders, key=lambda p: (order.get(p.name, len(order)), p.name))


def sources_report(demos: Path = Path("data/demos"), domains: Path = Path("data/domains"),
                   traces: list[Path] | tuple[Path, ...] = ()) -> list[ConditionQuality]:
    """Every source and scenario: ``demos/<kitchen>/`` (one condition, ``rendered``) and each trace root's
    ``<scenario>/<condition>/`` folders, plus an ``all`` row per scenario learning from all its conditions."""
    rows: list[ConditionQuality] = []
    for kitchen in sorted(p for p in demos.iterdir() if p.is_dir() and _traces(p)):
        rows.append(condition_quality(str(demos), kitchen.name, "rendered", _traces(kitchen),
                                      _reference(kitchen, domains)))
    for root in traces:
        for scenario in sorted(p for p in root.iterdir() if p.is_dir()):
            folders = _conditions(scenario)
            if not folders:
                continue
            reference = _reference(scenario, domains)
            here = [condition_quality(str(root), scenario.name, f.name, _traces(f), reference) for f in folders]
            everything = [t for f in folders for t in _traces(f)]
            learned = _learned(everything)
            rows += here + [ConditionQuality(str(root), scenario.name, "all", min(r.rate_hz for r in here),
                                             [q for r in here for q in r.segmentation],
                                             learning_quality(learned, reference), [a.name for a in learned.actions],
                                             max(r.rate_hz for r in here))]
    return rows


def sources_markdown(rows: list[ConditionQuality]) -> str:
    """The all-sources table ``guided-lfd quality --traces DIR`` prints after the shipped demonstrations' report."""
    lines = ["| source | scenario | condition | Hz | demos | frame macro-F1 (lowest) | segments (truth / found) "
             "| counts exact | preconditions P / R | effects P / R | skills (near-duplicates) | targets missed |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lq = r.learning
        dupes = f" ({', '.join(r.near_duplicates)})" if r.near_duplicates else ""
        rate = f"{r.rate_hz:g}-{r.max_rate_hz:g}" if r.max_rate_hz > r.rate_hz else f"{r.rate_hz:g}"
        lines.append(f"| {r.source} | {r.scenario} | {r.condition} | {rate} | {len(r.segmentation)} | {r.min_f1:.3f} "
                     f"| {r.truth_segments} / {r.segments} | {r.exact} / {len(r.segmentation)} "
                     f"| {lq['pre_precision']:.2f} / {lq['pre_recall']:.2f} "
                     f"| {lq['eff_precision']:.2f} / {lq['eff_recall']:.2f} | {len(r.skills)}{dupes} "
                     f"| {', '.join(r.misses()) or '-'} |")
    meets = sum(not r.misses() for r in rows)
    lines += ["", f"rows meeting every target: {meets} / {len(rows)} (targets: segment counts exact at 20-120 Hz; "
              f"lowest frame macro-F1 >= {TARGET_F1} (>= {TARGET_F1_LOW_RATE} at 15 Hz); preconditions and effects "
              f"precision and recall >= {TARGET_LEARNING}; no near-duplicate skills)"]
    return "\n".join(lines) + "\n"


__all__ = ["Segment", "segmentation_quality", "learning_quality", "compare_actions", "quality_report", "QualityReport",
           "quality_markdown", "ConditionQuality", "condition_quality", "sources_report", "sources_markdown",
           "frame_rate"]
