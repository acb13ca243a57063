"""Demonstrations: VR hand traces, their segmentation, and the skills learned from them."""

from pathlib import Path


def default_state_path(trace_path: str) -> str:
    """``demo.csv`` -> ``demo.state.csv`` (here, not in ``trace``, so that naming a state file needs no pandas)."""
    p = Path(trace_path)
    return str(p.with_name(p.stem + ".state.csv"))
