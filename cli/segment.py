"""``guided-lfd segment``: a VR hand trace -> hand-activity segments."""

from __future__ import annotations


from typing import Annotated

import typer

from cli.common import OutputOption, QuietOption, check_files, output_format, command, help_footer, ui
from guided_lfd import errors
from guided_lfd.demonstration.segment import segment as segment_trace
from guided_lfd.demonstration.segment import segments_csv, segments_document
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
    include_idle: Annotated[bool, typer.Option("--idle/--no-idle", help="Keep Idle segments.")] = False,
    output: OutputOption = "-",
    quiet: QuietOption = False,
) -> None:
    """Segment a VR hand trace into hand activities.

    Reach, Take, Put, Stack, Release, Idle, and Open/Close named by the fluent
    they change; each hand on its own, jitter and dropped frames debounced.
    Every segment carries the fluents it added and deleted. Writes the
    segments JSON document (the default) or CSV.
    """
    if trace == "-" and state is None:
        raise OptionError("TRACE '-' (standard input) has no TRACE.state.csv beside it; expected --state FILE")
    state_path = state or default_state_path(trace)
    check_files([trace, state_path], {"--output": output})
    csv_out = output_format(output, json_out, csv_out, default="json") == "csv"
    demo = load_demonstration(trace, state_path)
    segments = [s for s in segment_trace(demo) if include_idle or s.activity != "Idle"]
    if csv_out:
        text = segments_csv(segments)
    else:
        text = json_document("segments", segments_document(demo, segments, state_path))
    write_text(output, text)
    ui.info(f"[dim]{len(segments)} segment(s) from {len(demo.frames)} frames[/]")
