"""``guided-lfd segment``: a VR hand trace -> hand-activity segments."""

from __future__ import annotations


import json
from typing import Annotated

import typer

from cli.common import OutputOption, QuietOption, check_files, output_format, command, help_footer, ui
from guided_lfd import errors
from guided_lfd.demonstration.segment import segment as segment_trace
from guided_lfd.demonstration.segment import segment_json, segments_csv, segments_document
from guided_lfd.demonstration.trace import default_state_path, load_demonstration
from guided_lfd.errors import OptionError
from guided_lfd.io import json_document, write_text


@help_footer(
    example="guided-lfd segment data/demos/kitchen-1/P1-excuse.csv -o p1.segments.json",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_TRACE, errors.EXIT_OUTPUT),
    success="segments written",
)
@command
def segment(
    trace: Annotated[str, typer.Argument(metavar="TRACE",
                                         help="Hand trace CSV ('-' = stdin; then give --state).")],
    state: Annotated[
        str | None, typer.Option("--state", metavar="FILE", help="Environment state CSV ('-' = stdin; default: TRACE.state.csv).")
    ] = None,
    csv_out: Annotated[bool, typer.Option("--csv", help="Write CSV instead of JSON.")] = False,
    json_out: Annotated[bool, typer.Option("--json", help="Write the versioned JSON document (the default).")] = False,
    jsonl_out: Annotated[bool, typer.Option("--jsonl", help="Write JSON Lines, one segment a line (with TRACE '-': "
                                                            "each as soon as it closes).")] = False,
    include_idle: Annotated[bool, typer.Option("--idle/--no-idle", help="Keep Idle segments.")] = False,
    output: OutputOption = "-",
    quiet: QuietOption = False,
) -> None:
    """Segment a VR hand trace into hand activities.

    Reach, Take, Put, Stack, Release, Idle, and Open/Close named by the fluent
    they change; each hand on its own, jitter and dropped frames debounced.
    Every segment carries the fluents it added and deleted. Writes the
    segments JSON document (the default), CSV or JSON Lines. Reading
    the trace from a pipe ('-', with --state) with --csv or --jsonl, each
    segment is written as soon as it closes, in bounded memory.
    """
    if trace == "-" and state is None:
        raise OptionError("TRACE '-' (standard input) has no TRACE.state.csv beside it; expected --state FILE")
    state_path = state or default_state_path(trace)
    check_files([trace, state_path], {"--output": output})
    if jsonl_out and (csv_out or json_out):
        raise OptionError("--jsonl: give one of --json, --csv, --jsonl")
    if csv_out and json_out:  # before streaming: a pipe is refused the same way as a file
        output_format(output, json_out, csv_out)
    if trace == "-" and state_path != "-" and output == "-" and (csv_out or jsonl_out):
        _stream(state_path, csv_out, include_idle)
        return
    if jsonl_out:
        text = "".join(json.dumps(segment_json(s), separators=(",", ":")) + "\n"
                       for s in _segments(trace, state_path, include_idle)[1])
        write_text(output, text)
        return
    csv_out = output_format(output, json_out, csv_out, default="json") == "csv"
    demo, segments = _segments(trace, state_path, include_idle)
    if csv_out:
        text = segments_csv(segments)
    else:
        text = json_document("segments", segments_document(demo, segments, state_path))
    write_text(output, text)
    ui.info(f"[dim]{len(segments)} segment(s) from {len(demo.frames)} frames[/]")


def _segments(trace: str, state_path: str, include_idle: bool):
    """(the demonstration, its segments) of a whole trace file."""
    demo = load_demonstration(trace, state_path)
    return demo, [s for s in segment_trace(demo) if include_idle or s.activity != "Idle"]


def _stream(state_path: str, csv_out: bool, include_idle: bool) -> None:
    """Segment standard input as it arrives, writing each segment (CSV rows or JSON Lines) as it closes."""
    import sys

    from guided_lfd.demonstration.stream import stream_segments

    count = 0
    if csv_out:
        write_text("-", segments_csv([]))
    for index, seg in enumerate(stream_segments(sys.stdin.buffer, state_path)):
        if not include_idle and seg.activity == "Idle":
            continue
        seg.index = index
        # Written and flushed at once; a reader that stopped reading is the output error (40), as for files.
        write_text("-", segments_csv([seg], header=False) if csv_out
                   else json.dumps(segment_json(seg), separators=(",", ":")) + "\n")
        count += 1
    ui.info(f"[dim]{count} segment(s) from standard input[/]")
