"""The garbage collector during start-up.

Start-up (importing a subcommand's modules, typer building and parsing the
command line) allocates many objects that live for the whole run and makes
almost no garbage, so the cyclic collector's passes over them are wasted
work, ~10 ms of a ~0.2 s run.  :func:`pause_gc` (called by the console
script's entry point) turns the collector off; :func:`resume_gc` (called as a
command starts its work) freezes what start-up made, so later collections do
not scan it again, and turns the collector back on.
"""

from __future__ import annotations

import gc

_paused = False


def pause_gc() -> None:
    """Turn the cyclic garbage collector off until :func:`resume_gc` (if it is on)."""
    global _paused
    if gc.isenabled():
        gc.disable()
        _paused = True


def resume_gc() -> None:
    """Undo :func:`pause_gc`: freeze the objects made so far and turn the collector on again."""
    global _paused
    if _paused:
        _paused = False
        gc.freeze()
        gc.enable()
