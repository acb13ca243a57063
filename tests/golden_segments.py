"""Every shipped and test trace's segments, for the golden comparison of tests/test_segment_golden.py.

The household series' renders are committed under tests/data/household-renders/ (the human model's optimal
plan, and so the render, depends on the interpreter's hash seed when several plans are optimal).

    python tests/golden_segments.py        # rewrites tests/data/golden/segments.jsonl

One JSON line per trace: its path (relative to the project) and every
segment as ``guided-lfd segment`` finds it (hand, activity, times, objects,
what the hand held, fluents added and deleted).  Regenerate only when a
change to the segmenter is meant to change segments, and say why.  The file
is the segmenter's own output, so it catches a change, not an error: the
segments read by hand in tests/test_segment_golden.py are the independent check.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "data" / "golden" / "segments.jsonl"


def traces() -> list[Path]:
    """Every trace CSV with a state file beside it, under data/ and tests/data/."""
    found = [p.with_name(p.name[: -len(".state.csv")] + ".csv")
             for base in (ROOT / "data", ROOT / "tests" / "data") for p in base.rglob("*.state.csv")]
    # Regressions of bad or odd input (tests/data/regressions/odd-traces) are checked on their own.
    return sorted(p for p in found if p.is_file() and "odd-traces" not in p.parts)


def segment_key(s) -> list:
    """A segment as a plain list (rounded times, sorted fluents), as the golden file keeps it."""
    return [s.hand, s.activity, round(s.start, 4), round(s.end, 4), s.object, s.target, s.held_before,
            s.held_after, sorted(map(str, s.added)), sorted(map(str, s.deleted))]


def segments_of(trace: Path) -> list[list]:
    """The trace's segments as plain lists (rounded times, sorted fluents)."""
    from guided_lfd.demonstration.segment import segment
    from guided_lfd.demonstration.trace import load_demonstration

    return [segment_key(s) for s in segment(load_demonstration(str(trace)))]


def repeated(source: Path, copies: int, folder: Path) -> tuple[Path, Path]:
    """The demonstration ``source`` repeated ``copies`` times end to end, as the segment scaling benchmark
    makes it: (trace, state file) in ``folder``."""
    benchmarks = str(ROOT / "benchmarks")
    if benchmarks not in sys.path:
        sys.path.insert(0, benchmarks)
    import segment_scaling

    return segment_scaling.make(copies, folder, source)


def main() -> int:
    """Write the golden file."""
    sys.path.insert(0, str(ROOT))
    lines = [json.dumps({"trace": str(t.relative_to(ROOT)), "segments": segments_of(t)}, separators=(",", ":"))
             for t in traces()]
    GOLDEN.write_text("\n".join(lines) + "\n")
    print(f"{len(lines)} traces -> {GOLDEN.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
