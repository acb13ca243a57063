#!/usr/bin/env python3
"""Hours of demonstration: `segment` and `learn-domain` from a thousand to a million trace rows.

    python benchmarks/segment_scaling.py            # -> benchmarks/segment_results/{scaling.csv,summary.md}

Kitchen I's ``P1-complete`` demonstration (1,710 rows, both hands, 20 s) is
repeated end to end (times shifted; at the start of each copy the state file
puts the world back as it was at the start, so every copy acts on the same
scene), 1 to 600 times: up to 1,026,000 rows, 1.8 hours of recording; the
sizes double from 102,600 rows on.  For
each size, in one run, one process after the other, nothing else beside it:

* ``guided-lfd segment TRACE --csv`` (the segments as CSV rows, streamed),
  whole-run wall time and peak memory (resident set) from outside;
* the same trace piped in, ``guided-lfd segment - --state S --csv``;
* ``guided-lfd learn-domain`` on the segments document of the trace;
* pandas' own ``read_csv`` of the trace, a whole process (start-up included),
  the floor any CSV reader in Python stands on.
"""

from __future__ import annotations

import argparse
import csv
import io
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark import cli_command  # noqa: E402
from guided_lfd.benchmark.results import write_csv  # noqa: E402

SOURCE = ROOT / "data" / "demos" / "kitchen-1" / "P1-complete.csv"
OUT = ROOT / "benchmarks" / "segment_results"
COPIES = (1, 10, 60, 120, 240, 480, 600)
FIELDS = ["copies", "rows", "recording_min", "segments", "segment_s", "segment_mb", "pipe_s", "pipe_mb",
          "learn_s", "learn_mb", "read_csv_s", "read_csv_mb", "segment_over_read_csv"]


def make(copies: int, folder: Path, source: Path = SOURCE) -> tuple[Path, Path]:
    """The demonstration ``source`` repeated ``copies`` times: (trace, state file)."""
    rows = source.read_text().splitlines()
    header, frames = rows[0], rows[1:]
    times = [float(r.split(",", 1)[0]) for r in frames]
    period = max(times) + 0.1
    state_rows = list(csv.reader(io.StringIO(source.with_name(source.stem + ".state.csv").read_text())))[1:]
    initial = {(f, v) for t, f, v in state_rows if float(t) == 0 and not f.startswith("object(")}
    objects = [(t, f, v) for t, f, v in state_rows if f.startswith("object(")]
    changes = [(float(t), f, v) for t, f, v in state_rows if float(t) > 0]
    final: dict[str, str] = {f: v for f, v in initial}
    for _, f, v in changes:
        final[f] = v
    reset = [(f, v) for f, v in initial if final.get(f) != v] + [(f, "false") for f, v in final.items()
                                                                   if v == "true" and (f, "true") not in initial]
    trace, state = folder / f"k1-x{copies}.csv", folder / f"k1-x{copies}.state.csv"
    with trace.open("w") as out:
        out.write(header + "\n")
        for k in range(copies):
            shift = k * period
            for t, row in zip(times, frames):
                out.write(f"{t + shift:.4f},{row.split(',', 1)[1]}\n")
    with state.open("w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(["time", "fluent", "value"])
        writer.writerows(objects)
        writer.writerows(("0", f, v) for f, v in sorted(initial))
        for k in range(copies):
            shift = k * period
            if k:
                writer.writerows((f"{shift + min(times):.4f}", f, v) for f, v in sorted(reset))
            writer.writerows((f"{t + shift:.4f}", f, v) for t, f, v in changes)
    return trace, state


def measure(cmd: list[str], stdin: Path | None = None, stdout: Path | None = None) -> tuple[float, float]:
    """Whole-run wall time (s) and peak resident memory (MB) of one process, as GNU time reports them."""
    with open(stdin or "/dev/null", "rb") as given, open(stdout or "/dev/null", "wb") as taken:
        proc = subprocess.run(["/usr/bin/time", "-f", "%e %M", *cmd], stdin=given, stdout=taken,
                              stderr=subprocess.PIPE)
    last = proc.stderr.decode().strip().splitlines()[-1]
    if proc.returncode:
        raise RuntimeError(f"{' '.join(cmd)}: exit {proc.returncode}: {proc.stderr.decode()[-300:]}")
    wall, kb = last.split()
    return float(wall), int(kb) / 1024


def run(copies: int, folder: Path) -> dict:
    """One size's row."""
    trace, state = make(copies, folder)
    with trace.open() as lines:
        rows = sum(1 for _ in lines) - 1
    last = float(trace.read_text()[-200:].strip().splitlines()[-1].split(",")[0])
    segments_csv, document = folder / "out.csv", folder / "segments.json"
    read_s, read_mb = measure([sys.executable, "-c", "import sys, pandas; pandas.read_csv(sys.argv[1])", str(trace)])
    seg_s, seg_mb = measure([*cli_command(), "segment", str(trace), "--csv", "--quiet"], stdout=segments_csv)
    pipe_s, pipe_mb = measure([*cli_command(), "segment", "-", "--state", str(state), "--csv", "--quiet"],
                              stdin=trace, stdout=folder / "piped.csv")
    measure([*cli_command(), "segment", str(trace), "--quiet", "-o", str(document)])
    learn_s, learn_mb = measure([*cli_command(), "learn-domain", str(document), "--quiet"])
    segments = sum(1 for _ in segments_csv.open()) - 1
    return {"copies": copies, "rows": rows, "recording_min": round(last / 60, 1), "segments": segments,
            "segment_s": round(seg_s, 2), "segment_mb": round(seg_mb), "pipe_s": round(pipe_s, 2),
            "pipe_mb": round(pipe_mb), "learn_s": round(learn_s, 2), "learn_mb": round(learn_mb),
            "read_csv_s": round(read_s, 2), "read_csv_mb": round(read_mb),
            "segment_over_read_csv": round(seg_s / read_s, 1)}


def summary(rows: list[dict], command: str) -> str:
    """The markdown table."""
    lines = ["# segment and learn-domain from a thousand to a million rows", "", f"Regenerate with: `{command}`", "",
             "| rows | recording | segments | `segment` (s / MB) | `segment -` piped (s / MB) | `learn-domain` (s / MB) "
             "| pandas `read_csv` (s / MB) | `segment` / `read_csv` |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['rows']:,} | {r['recording_min']} min | {r['segments']:,} | {r['segment_s']} / "
                     f"{r['segment_mb']} | {r['pipe_s']} / {r['pipe_mb']} | {r['learn_s']} / {r['learn_mb']} | "
                     f"{r['read_csv_s']} / {r['read_csv_mb']} | {r['segment_over_read_csv']} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Generate, measure, write the CSV and the summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, nargs="*", default=list(COPIES))
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for copies in sorted(args.copies):
            folder = Path(tmp) / str(copies)
            folder.mkdir()
            rows.append(run(copies, folder))
            print(rows[-1], flush=True)
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(args.out / "scaling.csv", FIELDS, rows)
    (args.out / "summary.md").write_text(summary(rows, "python benchmarks/segment_scaling.py"))
    print((args.out / "summary.md").read_text())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
