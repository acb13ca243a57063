"""The ``guided-lfd`` command: one subcommand per module of this package.

Subcommands are loaded lazily: :data:`SUBCOMMANDS` names each one's module, and
:class:`LazyGroup` imports that module only when the subcommand runs (or its own
``--help`` is asked for).  ``guided-lfd excuse`` therefore never imports what
``evaluate`` or ``segment`` need (pandas, numpy, ...), which used to be most of
its start-up time.
"""

from __future__ import annotations

import importlib
import signal
import sys
from collections.abc import Iterator, MutableMapping
from dataclasses import dataclass
from typing import Annotated, Any

import typer
from typer.core import TyperCommand, TyperGroup

from cli.coercion import QuickCoercionMixin, quicken
from cli.startup import pause_gc
from guided_lfd.errors import EXIT_BAD_OPTION, EXIT_INTERRUPTED, EXIT_OUTPUT, EXIT_TERMINATED, Terminated
from guided_lfd import __version__


@dataclass(frozen=True)
class Subcommand:
    """Where a subcommand lives, and the line ``guided-lfd --help`` shows for it."""

    module: str
    function: str
    #: The first paragraph of the function's docstring, so that the command list of
    #: ``guided-lfd --help`` is the one typer would make, without importing the module
    #: (tests/test_startup.py checks the two agree).  One short line, so that the list
    #: does not cut it off (tests/test_cli_help.py).
    help: str


#: Every subcommand, in the order ``guided-lfd --help`` lists them.
SUBCOMMANDS: dict[str, Subcommand] = {
    "excuse": Subcommand("cli.excuse", "excuse", "Find a minimal excuse: what the human must demonstrate."),
    "plan": Subcommand("cli.plan", "plan", "Plan optimally (A* with LM-cut), or prove unsolvability."),
    "segment": Subcommand("cli.segment", "segment", "Segment a VR hand trace into hand activities."),
    "learn-domain": Subcommand("cli.learn_domain", "learn_domain", "Learn PDDL actions from demonstrations or trajectories."),
    "merge": Subcommand("cli.merge", "merge", "Merge learned domains into the robot's prior domain."),
    "evaluate": Subcommand("cli.evaluate", "evaluate", "Compute the paper's measures of a guided demonstration."),
    "validate": Subcommand("cli.validate", "validate", "Check a plan step by step from the initial state."),
    "bench": Subcommand("cli.bench", "bench", "Run the excuse benchmark (generate, run, report)."),
    "quality": Subcommand("cli.quality", "quality", "Score segmentation and learning on labelled demos."),
    "demos": Subcommand("cli.demos", "demos", "Render the study's demonstrations as hand traces."),
    "teach": Subcommand("cli.teach", "teach",
                        "Teach the robot its task, one demonstration per round."),
    "study": Subcommand("cli.study", "study", "Reproduce the paper's user study from the shipped data."),
}


#: ``-h`` as well as ``--help``, on the group and (inherited through the context) every subcommand.
CONTEXT_SETTINGS = {"help_option_names": ["-h", "--help"]}


def argument_name(param: Any, usage: bool = True) -> str:
    """An argument as usage lines write it (``DOMAIN``, ``[OUT]``, ``SEGMENTS...``); the list drops ``[]``."""
    name = param.metavar or param.name.upper()
    if usage and not param.required:
        name = f"[{name}]"
    return f"{name}..." if param.nargs != 1 else name


class QuickCommand(QuickCoercionMixin, TyperCommand):
    """A subcommand whose trivial parameter values skip typer's pydantic coercion (see cli.coercion).

    Its help writes arguments by their metavars, as a planner's documentation
    does (``Usage: guided-lfd plan [OPTIONS] DOMAIN PROBLEM``; typer would write
    ``{domain}`` and ``domain <str>``), and a required option joins the usage line.
    """

    def collect_usage_pieces(self, ctx: typer.Context) -> list[str]:
        """``[OPTIONS]``, the arguments by name, then any required option with its value."""
        params = self.get_params(ctx)
        pieces = [self.options_metavar] if self.options_metavar else []
        pieces += [argument_name(p) for p in params if p.param_type_name == "argument"]
        for p in params:
            if p.param_type_name == "option" and p.required:
                pieces.append(f"{max(p.opts, key=len)} {p.metavar or p.name.upper()}")
        return pieces

    def format_options(self, ctx: typer.Context, formatter: Any) -> None:
        """typer's Arguments and Options sections, arguments named as in the usage line."""
        args, opts = [], []
        for param in self.get_params(ctx):
            record = param.get_help_record(ctx)
            if record is None:
                continue
            if param.param_type_name == "argument":
                args.append((argument_name(param, usage=False), record[1]))
            elif param.param_type_name == "option":
                opts.append(record)
        for title, rows in (("Arguments", args), ("Options", opts)):
            if rows:
                with formatter.section(title):
                    formatter.write_dl(rows)


def load_subcommand(name: str) -> TyperCommand:
    """Import subcommand ``name``'s module and build its command as typer would in a group."""
    spec = SUBCOMMANDS[name]
    function = getattr(importlib.import_module(spec.module), spec.function)
    # A one-command Typer with the group's settings: typer.main.get_command() then builds
    # the command exactly as it builds each command of a group (get_command_from_info).
    single = typer.Typer(add_completion=False, pretty_exceptions_enable=app.pretty_exceptions_enable,
                         pretty_exceptions_short=app.pretty_exceptions_short, rich_markup_mode=app.rich_markup_mode)
    # The help ends with the command's example and exit codes (cli.common.help_footer).
    single.command(name, cls=QuickCommand, context_settings=CONTEXT_SETTINGS,
                   epilog=getattr(function, "help_epilog", None))(function)
    return typer.main.get_command(single)  # type: ignore[return-value]


class _LazyCommands(MutableMapping[str, Any]):
    """The group's ``commands``: every name known up front, each command built on first use.

    TyperGroup reads ``self.commands`` for more than look-ups (its keys feed the
    'Did you mean ...?' of a mistyped command), so the laziness lives in the mapping.
    """

    def __init__(self) -> None:
        self._loaded: dict[str, Any] = {}
        self._extra: list[str] = []  # names added with add_command, outside the registry

    def __getitem__(self, name: str) -> Any:
        if name not in self._loaded:
            if name not in SUBCOMMANDS:
                raise KeyError(name)
            self._loaded[name] = load_subcommand(name)
        return self._loaded[name]

    def __setitem__(self, name: str, command: Any) -> None:
        if name not in SUBCOMMANDS and name not in self._extra:
            self._extra.append(name)
        self._loaded[name] = command

    def __delitem__(self, name: str) -> None:
        raise TypeError("guided-lfd's subcommands cannot be removed")

    def __iter__(self) -> Iterator[str]:
        yield from SUBCOMMANDS
        yield from self._extra

    def __len__(self) -> int:
        return len(SUBCOMMANDS) + len(self._extra)

    def __contains__(self, name: object) -> bool:
        return name in SUBCOMMANDS or name in self._extra


class LazyGroup(QuickCoercionMixin, TyperGroup):
    """A TyperGroup whose subcommands are imported only when needed."""

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        lazy = _LazyCommands()
        for name, command in self.commands.items():  # any built eagerly by typer (none today)
            lazy[name] = command
        self.commands = lazy
        self._listing = False

    def get_params(self, ctx: typer.Context) -> list[Any]:
        """The group's parameters; those typer adds after building it (completion's) coerce quickly too."""
        params = super().get_params(ctx)
        for param in params:
            quicken(param)
        return params

    def list_commands(self, ctx: typer.Context) -> list[str]:
        """Subcommand names in registry order, without loading any."""
        return list(self.commands)

    def get_command(self, ctx: typer.Context, cmd_name: str) -> Any:
        """The subcommand ``cmd_name`` (imported now); a stub while the group's help is written."""
        if self._listing and cmd_name in SUBCOMMANDS:
            # The command list needs only each command's short help: a stub carrying the
            # docstring's first paragraph yields the same line as the real command.
            return TyperCommand(cmd_name, help=SUBCOMMANDS[cmd_name].help, rich_markup_mode=app.rich_markup_mode)
        return super().get_command(ctx, cmd_name)

    def format_commands(self, ctx: typer.Context, formatter: Any) -> None:
        """TyperGroup's command list, from the registry's help lines."""
        self._listing = True
        try:
            super().format_commands(ctx, formatter)
        finally:
            self._listing = False


def _one_line_usage_errors() -> None:
    """Typer prints usage errors as a usage block; guided-lfd promises one line."""
    try:
        from typer._click import exceptions as click_exceptions
    except ImportError:  # a typer without its vendored click: keep its format
        return

    def show(self, file=None) -> None:
        out = file or sys.stderr
        command = self.ctx.command_path if getattr(self, "ctx", None) is not None else "guided-lfd"
        # pydantic's wording inside typer's ("Value error, 'x' is not one of ..."): the reason alone.
        message = " ".join(self.format_message().split()).replace(": Value error, ", ": ")
        bad_value = isinstance(self, click_exceptions.BadParameter) and not isinstance(
            self, click_exceptions.MissingParameter)
        kind = "option error" if bad_value else "usage error"
        out.write(f"{command}: {kind}: {message} (see --help)\n")

    click_exceptions.UsageError.show = show  # type: ignore[method-assign]
    # A value an option does not accept is the same error whether the parser
    # (--semantics foo, --max-size x) or the command (--strategy foo) finds it.
    click_exceptions.BadParameter.exit_code = EXIT_BAD_OPTION
    click_exceptions.MissingParameter.exit_code = click_exceptions.UsageError.exit_code


_one_line_usage_errors()

app = typer.Typer(
    name="guided-lfd",
    cls=LazyGroup,
    help="Excuse-guided learning from demonstration: find what a robot needs demonstrated, "
    "learn it from a hand trace, and measure what guidance saved.",
    epilog="Run 'guided-lfd COMMAND -h' for a command's arguments, an example and its exit codes.",
    context_settings=CONTEXT_SETTINGS,
    no_args_is_help=True,
    # typer's --install-completion / --show-completion: costs no start-up (measured, see docs/benchmarks.md).
    add_completion=True,
    pretty_exceptions_enable=False,
    # click's plain formatter: help is the same plain text on a terminal, a pipe or CliRunner
    # (no markup to render, no colour codes), and --help never imports rich.
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


def run() -> None:
    """Console-script entry point."""
    import cli
    from guided_lfd.deadline import keep_until_exit

    cli.run_started = cli.PROCESS_STARTED  # --time-limit counts start-up too
    pause_gc()  # until the command starts its work: see cli/startup.py
    keep_until_exit()
    signal.signal(signal.SIGTERM, _terminate)  # from here on, as Ctrl-C (see cli/__init__.py for start-up)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    stdout_was_null = _stdout_is_null()
    try:
        app()
        code: Any = 0
    except SystemExit as exc:
        code = exc.code
    except KeyboardInterrupt as exc:  # outside a command (its --help, the group's options)
        code = EXIT_TERMINATED if isinstance(exc, Terminated) else EXIT_INTERRUPTED
    if (code == 1 and _stdout_broke()) or (code in (0, 1) and _stdout_is_null() and not stdout_was_null):
        # click's own answer to a broken stdout while it writes help or the version (exit 1, without a word),
        # or rich's (stdout pointed at the null device, exit 0): the output is cut, which is no success
        _say("-: output error: standard output closed by the reader (broken pipe)")
        code = EXIT_OUTPUT
    elif code == 0 and sys.stdout is None and _asks_for_help(sys.argv[1:]):
        _say("-: output error: standard output is closed")  # help or the version had nowhere to go
        code = EXIT_OUTPUT
    if code in (EXIT_INTERRUPTED, EXIT_TERMINATED) and not cli.interruption_reported:
        # Stopped while typer parsed the options: typer calls every KeyboardInterrupt 130, without a word.
        code = EXIT_TERMINATED if _TERMINATED else EXIT_INTERRUPTED
        _say("terminated (SIGTERM)" if _TERMINATED else "interrupted")
    _end(code)


_TERMINATED = False


def _asks_for_help(args: list[str]) -> bool:
    """Whether the command line asks only for help or the version (what goes to stdout before any command)."""
    return any(a in ("-h", "--help", "--version") for a in args)


def _terminate(signum: int, frame: Any) -> None:
    """SIGTERM: raised as :class:`~guided_lfd.errors.Terminated` where the process is, to end as Ctrl-C does."""
    global _TERMINATED
    _TERMINATED = True
    raise Terminated()


def _stdout_broke() -> bool:
    """Whether click found stdout closed by its reader (it then wraps stdout to silence the final flush; typer
    may carry its own copy of click, so the wrapper is known by its name)."""
    return type(sys.stdout).__name__ == "PacifyFlushWrapper"


def _stdout_is_null() -> bool:
    """Whether stdout's file descriptor is the null device (rich points it there when its reader closed it)."""
    import os

    try:
        return os.path.samestat(os.fstat(1), os.stat(os.devnull))
    except OSError:
        return False


def _say(line: str) -> None:
    """One line on stderr, if there is a stderr to write to."""
    try:
        if sys.stderr is not None:
            sys.stderr.write(line + "\n")
    except (OSError, ValueError):
        pass


def _end(code: Any) -> None:
    """Flush the output and end the process without tearing the interpreter down.

    Every output file is complete by now (written atomically); what is left
    is freeing the run's objects, a second or more on a large task, and after
    a time limit that is time past the limit.  So the process just ends.
    """
    import atexit
    import os

    if code is None:
        code = 0
    elif not isinstance(code, int):
        print(code, file=sys.stderr)
        code = 1
    atexit._run_exitfuncs()  # what libraries registered still runs (logging's flush, ...)
    for stream in (sys.stdout, sys.stderr):
        try:
            if stream is not None:  # None: the stream was closed when the process started (`>&-`)
                stream.flush()
        except (OSError, ValueError):  # a closed pipe or stream: nothing more can be said on it
            if stream is sys.stdout and code == 0:  # what was left of the output did not reach its reader
                _say("-: output error: standard output closed by the reader (broken pipe)")
                code = EXIT_OUTPUT
    os._exit(code)
