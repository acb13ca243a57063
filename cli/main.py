"""The ``guided-lfd`` command: one subcommand per module of this package."""

from __future__ import annotations

import sys
from typing import Annotated

import typer

from cli.evaluate import evaluate
from cli.excuse import excuse
from cli.learn_domain import learn_domain
from cli.merge import merge
from cli.plan import plan
from cli.segment import segment
from cli.validate import validate
from guided_lfd import __version__

def _one_line_usage_errors() -> None:
    """Typer prints usage errors as a usage block; guided-lfd promises one line."""
    try:
        from typer._click import exceptions as click_exceptions
    except ImportError:  # a typer without its vendored click: keep its format
        return

    def show(self, file=None) -> None:
        out = file or sys.stderr
        command = self.ctx.command_path if getattr(self, "ctx", None) is not None else "guided-lfd"
        message = " ".join(self.format_message().split())
        out.write(f"{command}: usage error: {message} (see --help)\n")

    click_exceptions.UsageError.show = show  # type: ignore[method-assign]


_one_line_usage_errors()

app = typer.Typer(
    name="guided-lfd",
    help="Excuse-guided learning from demonstration: find what a robot needs demonstrated, "
    "learn it from a hand trace, and measure what guidance saved.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"guided-lfd {__version__}")
        raise typer.Exit()


@app.callback()
def main(
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="Show the version and exit.")
    ] = False,
) -> None:
    """Excuse-guided learning from demonstration."""


app.command("excuse")(excuse)
app.command("plan")(plan)
app.command("segment")(segment)
app.command("learn-domain")(learn_domain)
app.command("merge")(merge)
app.command("evaluate")(evaluate)
app.command("validate")(validate)


def run() -> None:
    """Console-script entry point."""
    import cli
    from cli import common

    common.run_started = cli.PROCESS_STARTED  # --time-limit counts start-up too
    app()
