#!/usr/bin/env python3
"""Segmentation and learning against a tracker's noise: a sweep of tracking loss and dropped frames.

    python benchmarks/noise_sweep.py      # -> benchmarks/noise_results/{sweep.csv,summary.md}

The independent trace source's generator (tests/data/traces/generate.py, which shares only the CSV formats with
the tool) draws every scenario's two scripts under each sweep condition: one tracking loss of the hand inside a
take, a transport or an opening, 0 to 2 s long, and 0 to 20 % dropped frames (1 mm tremor; a slow demonstrator,
every motion 2.5 times as long, so that a 2 s loss fits inside a transport), with three seed bases.  ``guided-lfd quality``'s scoring (guided_lfd.demonstration.quality) then gives, per condition, the
demonstrations whose segments match the truth in number (exact), the lowest frame macro-F1, and the learned
skills' precondition and effect precision and recall against the scenario's human.pddl.
"""

from __future__ import annotations

import argparse
import importlib.util
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark.results import write_csv  # noqa: E402

TRACES = ROOT / "tests" / "data" / "traces"
OUT = ROOT / "benchmarks" / "noise_results"
LOSSES = (0.0, 0.5, 1.0, 1.5, 2.0)
DROPS = (0.0, 0.05, 0.10, 0.20)
SEED_BASES = (34_000, 44_000, 54_000)
FIELDS = ["loss_s", "drop", "seed_base", "scenario", "demos", "exact", "min_f1", "pre_precision", "pre_recall",
          "eff_precision", "eff_recall"]


def _generator():
    spec = importlib.util.spec_from_file_location("independent_traces", TRACES / "generate.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["independent_traces"] = module
    spec.loader.exec_module(module)
    return module


def sweep(seed_bases: tuple[int, ...]) -> list[dict]:
    """Every (loss, drop) condition drawn with each seed base, scored per scenario."""
    from guided_lfd.demonstration.quality import sources_report

    gen = _generator()
    gen.CONDITIONS = [gen.Condition(f"loss-{loss:g}-drop-{drop:g}", tremor_m=0.001, drop=drop, tempo=2.5,
                                    loss_s=(loss, loss) if loss else (0.0, 0.0))
                      for loss in LOSSES for drop in DROPS]
    rows = []
    for base in seed_bases:
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            gen.generate(out, seed_base=base)
            for scenario in ("stacking", "cupboard"):  # their models live beside their traces
                for model in ("human.pddl", "problem.pddl"):
                    shutil.copy(TRACES / scenario / model, out / scenario / model)
            for r in sources_report(ROOT / "data" / "demos", ROOT / "data" / "domains", [out]):
                if r.source != str(out) or r.condition == "all":
                    continue
                loss, drop = r.condition.split("-")[1], r.condition.split("-")[3]
                rows.append({"loss_s": float(loss), "drop": float(drop), "seed_base": base, "scenario": r.scenario,
                             "demos": len(r.segmentation), "exact": r.exact, "min_f1": round(r.min_f1, 3),
                             **{k: round(r.learning[k], 3) for k in ("pre_precision", "pre_recall", "eff_precision",
                                                                    "eff_recall")}})
    return rows


def summary(rows: list[dict], command: str) -> str:
    """Per condition, over scenarios and seed bases."""
    lines = ["# Segmentation against a tracker's noise", "", f"Regenerate with: `{command}`", "",
             "| tracking loss (s) | dropped frames | demonstrations | segments exact | lowest frame F1 | "
             "preconditions P / R (lowest) | effects P / R (lowest) |", "|---|---|---|---|---|---|---|"]
    for loss in LOSSES:
        for drop in DROPS:
            group = [r for r in rows if r["loss_s"] == loss and r["drop"] == drop]
            if not group:
                continue
            demos, exact = sum(r["demos"] for r in group), sum(r["exact"] for r in group)
            low = {k: min(r[k] for r in group) for k in ("min_f1", "pre_precision", "pre_recall", "eff_precision",
                                                          "eff_recall")}
            lines.append(f"| {loss:g} | {drop:.0%} | {demos} | {exact} ({exact / demos:.1%}) | {low['min_f1']:.3f} | "
                         f"{low['pre_precision']:.2f} / {low['pre_recall']:.2f} | "
                         f"{low['eff_precision']:.2f} / {low['eff_recall']:.2f} |")
    demos, exact = sum(r["demos"] for r in rows), sum(r["exact"] for r in rows)
    lines += ["", f"All: {exact} of {demos} demonstrations segment exactly ({exact / demos:.1%})."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run the sweep and write the CSV and the summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT)
    parser.add_argument("--seed-bases", type=int, nargs="*", default=list(SEED_BASES))
    args = parser.parse_args(argv)
    rows = sweep(tuple(args.seed_bases))
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(args.out / "sweep.csv", FIELDS, rows)
    (args.out / "summary.md").write_text(summary(rows, "python benchmarks/noise_sweep.py"))
    print((args.out / "summary.md").read_text())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
