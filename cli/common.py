"""Shared pieces of the command-line layer: console, options, error handling."""

from __future__ import annotations

import functools
import os
import sys
from typing import Annotated, Callable, TypeVar

import typer
from rich.console import Console

from guided_lfd.errors import EXIT_INTERNAL, GuidedLfdError

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
    float | None, typer.Option("--time-limit", min=0.0, help="Give up after this many seconds (exit 20).")
]


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


def stdout_is_terminal() -> bool:
    """Whether stdout is an interactive terminal (then text beats JSON)."""
    try:
        return sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False
