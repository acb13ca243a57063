"""Shared pieces of the command-line layer: console, options, error handling."""

from __future__ import annotations

import functools
import math
import os
from typing import Annotated, Callable, TypeVar

import typer
from rich.console import Console

from guided_lfd.errors import EXIT_INTERNAL, GuidedLfdError, OptionError
from guided_lfd.io import write_text

F = TypeVar("F", bound=Callable)


class Ui:
    """Where diagnostics go: stderr, silenced by ``--quiet`` (data never is)."""

    def __init__(self) -> None:
        self.quiet = False

    @property
    def console(self) -> Console:
        # Created per use so that it follows sys.stderr (CliRunner swaps it).
        return Console(stderr=True, quiet=self.quiet, highlight=False, soft_wrap=True)

    def info(self, message: str) -> None:
        """A diagnostic line on stderr (rich markup allowed)."""
        self.console.print(message)

    def error(self, message: str) -> None:
        """A one-line error on stderr; shown even with ``--quiet``."""
        Console(stderr=True, highlight=False, soft_wrap=True).print(message, markup=False)


ui = Ui()

QuietOption = Annotated[bool, typer.Option("--quiet", "-q", help="No diagnostics on stderr (data and errors still appear).")]
JsonOption = Annotated[bool, typer.Option("--json", help="Write a versioned JSON document instead of text.")]
OutputOption = Annotated[str, typer.Option("--output", "-o", help="Write the result here ('-' = stdout). Written atomically.")]
TimeLimitOption = Annotated[
    float | None, typer.Option("--time-limit", help="Give up after this many seconds (exit 20).")
]

#: ``time.monotonic()`` when the console script started (set by
#: :func:`cli.main.run`); None when the commands run in-process (tests).
run_started: float | None = None


def started_at() -> float:
    """When this run's clock started: the console script's start, else now."""
    import time

    return run_started if run_started is not None else time.monotonic()


#: Longest time limit accepted (about 11 days); beyond it timers overflow.
MAX_TIME_LIMIT = 1e6


def check_time_limit(value: float | None) -> float | None:
    """A usable --time-limit: finite, positive, at most :data:`MAX_TIME_LIMIT`."""
    if value is None:
        return None
    if not math.isfinite(value) or value <= 0 or value > MAX_TIME_LIMIT:
        raise OptionError(f"--time-limit {value:g}: expected a number of seconds > 0 and <= {MAX_TIME_LIMIT:g}")
    return value


def check_inputs(*paths: str) -> None:
    """Standard input can be read once: refuse ``-`` for two inputs."""
    if sum(1 for p in paths if p == "-") > 1:
        raise OptionError("'-' (standard input) can stand for only one input file")


def emit(output: str, text: str, success: bool) -> None:
    """Write a result; a failed run never replaces an existing output file.

    On failure the document still goes to stdout when that is the output.
    """
    if success or output == "-":
        write_text(output, text)
    else:
        ui.info(f"[dim]{output} not written: the run did not succeed[/]")


def command(fn: F) -> F:
    """Turn library errors into one line on stderr and the documented exit code."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        ui.quiet = bool(kwargs.get("quiet", False))
        try:
            return fn(*args, **kwargs)
        except typer.Exit:
            raise
        except GuidedLfdError as exc:
            ui.error(str(exc))
            raise typer.Exit(exc.exit_code) from None
        except KeyboardInterrupt:
            ui.error("interrupted")
            raise typer.Exit(130) from None
        except RecursionError:
            ui.error("internal error: input nested too deeply")
            raise typer.Exit(EXIT_INTERNAL) from None
        except Exception as exc:  # a bug: one line, never a traceback
            if os.environ.get("GUIDED_LFD_DEBUG"):
                raise
            ui.error(f"internal error: {type(exc).__name__}: {exc} (please report; GUIDED_LFD_DEBUG=1 shows the traceback)")
            raise typer.Exit(EXIT_INTERNAL) from None

    return wrapper  # type: ignore[return-value]

