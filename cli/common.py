"""Shared pieces of the command-line layer: console, options, error handling."""

from __future__ import annotations

import builtins
import functools
import os
import re
import stat
import sys
from typing import TYPE_CHECKING, Annotated, Callable, TypeVar

import typer

from cli.startup import resume_gc
from guided_lfd.errors import (
    EXIT_BAD_OPTION, EXIT_CODES, EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_MEMORY, EXIT_OK, EXIT_TERMINATED, EXIT_USAGE,
    GuidedLfdError, InputFileError, Location, OptionError, Terminated,
)
from guided_lfd.deadline import checked_time_limit
from guided_lfd.io import check_writable, write_text

if TYPE_CHECKING:
    from rich.console import Console

    from guided_lfd.pddl.model import Domain

F = TypeVar("F", bound=Callable)

#: rich's emoji-code pattern (rich/_emoji_replace.py): text it could match is left to rich.
_EMOJI_CODE = re.compile(r"(:(\S*?)(?:(?:\-)(emoji|text))?:)")
#: Environment variables that can make rich treat a file as a terminal (or change how it writes).
_RICH_ENVIRONMENT = ("FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE")


def plain_stderr() -> bool:
    """Whether rich would write to stderr as to a plain file: no terminal, no colour forced.

    Checked conservatively (any doubt means False): then rich's Console
    decides, as it always did.
    """
    stream = sys.stderr
    if stream is None or hasattr(stream, "rich_proxied_file") or sys.platform == "win32":
        return False
    if any(name in os.environ for name in _RICH_ENVIRONMENT) or hasattr(builtins, "get_ipython"):
        return False
    if getattr(sys.stdin, "__module__", "").startswith("idlelib"):
        return False
    try:
        return not stream.isatty()
    except Exception:  # a closed or odd stream: let rich handle it
        return False


def plain_text(message: str, markup: bool) -> str | None:
    """``message`` exactly as rich prints it to a plain file, if that is certain; else None.

    Certain for one line of printable ASCII with no emoji code and, with
    markup, no markup other than a whole-message ``[dim]...[/]`` (which a
    plain file does not show).
    """
    if markup and message.startswith("[dim]") and message.endswith("[/]"):
        message = message[len("[dim]"):-len("[/]")]
    if not (message.isascii() and message.isprintable()) or _EMOJI_CODE.search(message):
        return None
    if markup and ("[" in message or "]" in message or "\\" in message):
        return None
    return message


def one_line(message: str) -> str:
    """``message`` with every character that is not printable (line breaks too) as its escape."""
    if message.isprintable():
        return message
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in message)


class Ui:
    """Where diagnostics go: stderr, silenced by ``--quiet`` (data never is).

    Diagnostics are printed with rich; but when stderr is no terminal and the
    line is plain (the usual case in scripts and pipelines), they are written
    directly, byte for byte as rich would, which spares importing rich.console
    (~25 ms of a ~0.2 s run).
    """

    def __init__(self) -> None:
        self.quiet = False
        self.warned: set[str] = set()

    @property
    def console(self) -> Console:
        """A rich Console on stderr (created per use so that it follows sys.stderr: CliRunner swaps it)."""
        from rich.console import Console

        return Console(stderr=True, quiet=self.quiet, highlight=False, soft_wrap=True)

    def _print(self, message: str, markup: bool) -> bool:
        """Write ``message`` without rich if that gives rich's output; whether it did."""
        text = plain_text(message, markup)
        if text is None or not plain_stderr():
            return False
        sys.stderr.write(text + "\n")
        sys.stderr.flush()  # as rich's Console does after each print
        return True

    def info(self, message: str) -> None:
        """A diagnostic line on stderr (rich markup allowed)."""
        if self.quiet:
            return
        if not self._print(message, markup=True):
            self.console.print(message)

    def reading_warnings(self, *domains: Domain | None) -> None:
        """The reader's warnings about ``domains`` (``Domain.warnings``) on stderr, each once per run."""
        for domain in domains:
            for warning in domain.warnings if domain is not None else ():
                if warning not in self.warned:
                    self.warned.add(warning)
                    self.info_plain(warning)

    def info_plain(self, message: str) -> None:
        """A diagnostic line quoted from an input (no markup), silenced by ``--quiet``."""
        if self.quiet:
            return
        message = one_line(message)
        if not self._print(message, markup=False):
            self.console.print(message, markup=False)

    def error(self, message: str) -> None:
        """A one-line error on stderr; shown even with ``--quiet``.

        Characters that are not printable (a line or record separator quoted
        from a damaged input) are written as escapes, so the error stays one line.
        """
        message = one_line(message)
        if not self._print(message, markup=False):
            from rich.console import Console

            Console(stderr=True, highlight=False, soft_wrap=True).print(message, markup=False)


ui = Ui()

QuietOption = Annotated[bool, typer.Option("--quiet", "-q", help="No diagnostics on stderr (data and errors still appear).")]
JsonOption = Annotated[bool, typer.Option("--json", help="Write a versioned JSON document instead of text.")]
OutputOption = Annotated[str, typer.Option("--output", "-o", metavar="FILE",
                                           help="Write the result to FILE ('-' = stdout), atomically.")]
TimeLimitOption = Annotated[
    float | None, typer.Option("--time-limit", metavar="SECONDS",
                               help="Give up after SECONDS, start-up and reading included (exit 20).")
]
SkillChangesOption = Annotated[
    str, typer.Option("--skill-changes", metavar="[on|off]",
                      help="'on' (default): an excuse may also drop a learned precondition no demonstration tested "
                           "('-(ontable ?y) in unstack': show that skill once more where it is false); 'off': state "
                           "changes alone.")
]
RelaxPriorOption = Annotated[
    bool, typer.Option("--relax-prior", help="Skill changes may drop preconditions of the robot's given skills too "
                                             "(those without learned evidence).")
]


def skill_changes_switch(skill_changes: str, relax_prior: bool) -> bool:
    """``--skill-changes on|off`` as a flag; OptionError for another value, or ``--relax-prior`` with ``off``."""
    if skill_changes.lower() not in ("on", "off"):
        raise OptionError(f"--skill-changes {skill_changes}: expected 'on' or 'off'")
    if relax_prior and skill_changes.lower() == "off":
        raise OptionError("--relax-prior: needs skill changes (it contradicts --skill-changes off)")
    return skill_changes.lower() == "on"

MemoryLimitOption = Annotated[
    int | None, typer.Option("--memory-limit", metavar="MIB",
                             help="Address-space cap in MiB; a run that needs more ends with exit 22.")
]


#: Exit codes every subcommand can give: the last lines of each one's help list them too.
COMMON_EXIT_CODES = (EXIT_INTERNAL, EXIT_USAGE, EXIT_BAD_OPTION, EXIT_INTERRUPTED, EXIT_TERMINATED)


def help_footer(example: str, exit_codes: tuple[int, ...], success: str) -> Callable[[F], F]:
    """Decorator: the command's help ends with EXAMPLE and the exit codes it can give.

    ``exit_codes`` are the command's own (:data:`COMMON_EXIT_CODES` are added),
    each listed with its meaning from :data:`guided_lfd.errors.EXIT_CODES`;
    ``success`` says what exit 0 means for this command.  The text becomes the
    command's epilog (``cli.main.load_subcommand`` passes it to typer).
    """
    codes = sorted({EXIT_OK, *exit_codes, *COMMON_EXIT_CODES})
    unknown = [code for code in codes if code not in EXIT_CODES]
    if unknown:
        raise ValueError(f"undocumented exit code(s) {unknown}: add them to guided_lfd.errors.EXIT_CODES")
    # "\b" (click's no-rewrap mark) keeps each block's lines as written.
    lines = ["\b", "Example:", *(f"  {line}" for line in example.strip().splitlines()), "",
             "\b", "Exit codes:"]
    lines += [f"  {code:<4} {success if code == EXIT_OK else EXIT_CODES[code]}" for code in codes]
    epilog = "\n".join(lines)

    def attach(fn: F) -> F:
        fn.help_epilog = epilog  # type: ignore[attr-defined]
        return fn

    return attach


def apply_memory_limit(megabytes: int | None) -> None:
    """Cap this process's memory (``--memory-limit``): running out is then the memout exit, not the OOM killer."""
    if megabytes is None:
        return
    from guided_lfd.memory import MAX_MEMORY_MIB, cap_own_memory

    if not 1 <= megabytes <= MAX_MEMORY_MIB:
        raise OptionError(f"--memory-limit {megabytes}: expected a number of MiB from 1 to {MAX_MEMORY_MIB}")

    cap_own_memory(megabytes)


def started_at() -> float:
    """When this run's clock started: the console script's start (see :mod:`cli`), else now."""
    import time

    import cli

    return cli.run_started if cli.run_started is not None else time.monotonic()


def check_time_limit(value: float | None) -> float | None:
    """A usable --time-limit: finite, positive, at most :data:`guided_lfd.deadline.MAX_TIME_LIMIT`."""
    return checked_time_limit(value)


def path_name(value: str) -> "Path":
    """A path option's value as a Path; an empty name is refused (exit 37), not taken for the working folder."""
    from pathlib import Path

    if not str(value).strip():
        raise typer.BadParameter("expected a file or folder name, got an empty one")
    return Path(value)


def check_output_folder(folder: "Path", option: str) -> None:
    """Refuse (exit 40), before any work, an output folder that is a file or cannot be made or written."""
    from pathlib import Path

    from guided_lfd.errors import Location, OutputError

    try:
        if folder.exists() and not folder.is_dir():
            raise OutputError(f"{option}: is a file, expected a folder (the file is kept)", Location(str(folder)))
        existing = next((p for p in [folder, *folder.parents] if p.exists()), Path("."))
        if not existing.is_dir():
            raise OutputError(f"{option}: {existing} is a file, expected a folder", Location(str(folder)))
        writable = os.access(existing, os.W_OK | os.X_OK)
    except (OSError, RuntimeError) as exc:
        raise OutputError(f"{option}: cannot use it as a folder ({getattr(exc, 'strerror', None) or exc})",
                          Location(str(folder))) from None
    if not writable:
        raise OutputError(f"{option}: cannot write into {existing} (permission denied)", Location(str(folder)))


def check_apart(out: "Path", option: str, inputs: "list[Path]", root: "Path | None" = None) -> None:
    """Refuse (exit 37), before any work, an output folder that is one of the folders a run reads or lies in one,
    or is the data's ``root`` itself: the run would mix its files into its own inputs."""
    try:
        where = out.resolve()
        if root is not None and where == root.resolve():
            raise OptionError(f"{option} {out}: is the data's root ({root}); expected a folder of its own")
        for folder in inputs:
            if folder.exists() and where.is_relative_to(folder.resolve()):
                raise OptionError(f"{option} {out}: lies in {folder}, which this run reads; expected a folder "
                                  "elsewhere")
    except (OSError, RuntimeError):  # a name the OS refuses: the output check says so
        return


def check_inputs(*paths: str) -> None:
    """Standard input can be read once: refuse ``-`` for two inputs."""
    if sum(1 for p in paths if p == "-") > 1:
        raise OptionError("'-' (standard input) can stand for only one input file")


def output_format(output: str, json_out: bool = False, csv_out: bool = False, default: str = "text") -> str:
    """``json``, ``csv`` or ``default``: the flags first, else the output file's extension (``-o r.json``)."""
    if json_out and csv_out:
        raise OptionError("--csv and --json: choose one output format")
    if json_out:
        return "json"
    if csv_out:
        return "csv"
    suffix = output.lower().rsplit(".", 1)[-1] if output != "-" and "." in output else ""
    if suffix in ("json", "csv") and suffix in _FORMATS_OF.get(default, (suffix,)):
        return suffix
    return default


#: Which formats an extension may select, by a command's default format.
_FORMATS_OF = {"text": ("json",), "json": ("json", "csv"), "pddl": ("json",), "table": ("json", "csv")}


def _same_file(a: str, b: str) -> bool:
    """Whether two path names reach the same file (links, ``..`` and hard links resolved)."""
    try:
        if os.path.exists(a) and os.path.exists(b):
            return os.path.samefile(a, b)
        return os.path.realpath(a) == os.path.realpath(b)
    except OSError:  # an unresolvable name is no input: check_writable reports it
        return False


def _is_standard_input(path: str) -> bool:
    """Whether ``path`` is the file redirected to standard input (``plan - p.pddl -o d.pddl < d.pddl``)."""
    try:
        given, stdin = os.stat(path), os.fstat(0)
    except (OSError, ValueError):  # no such output yet, or no standard input: nothing to overwrite
        return False
    return stat.S_ISREG(stdin.st_mode) and (given.st_dev, given.st_ino) == (stdin.st_dev, stdin.st_ino)


def check_files(inputs: list[str | None], outputs: dict[str, str | None]) -> None:
    """Refuse, before any work, outputs that would replace an input or each other, or cannot be written.

    ``inputs`` are the run's input file names (``-`` and None skipped);
    ``outputs`` maps each output option (``--output``) to its file name.
    Standard input may stand for one input only.
    """
    named = [p for p in inputs if p is not None]
    check_inputs(*named)
    files = [p for p in named if p != "-"]
    for path in files:  # a missing input is the first thing to say (30), before an output's folder (40)
        if not os.path.lexists(path):
            raise InputFileError("file not found", Location(path))
    to_stdout = [option for option, path in outputs.items() if path == "-"]
    if len(to_stdout) > 1:
        raise OptionError(f"{' and '.join(to_stdout)} both name '-' (standard output); expected one of them a file")
    given = [(option, path) for option, path in outputs.items() if path is not None and path != "-"]
    for k, (option, path) in enumerate(given):
        for source in files:
            if _same_file(path, source):
                raise OptionError(f"{option} {path} is an input of this run; expected another file")
        if "-" in named and _is_standard_input(path):
            raise OptionError(f"{option} {path} is the file on standard input ('-'); expected another file")
        for other_option, other in given[:k]:
            if _same_file(path, other):
                raise OptionError(f"{option} {path} is also {other_option}; expected another file")
    for option, path in outputs.items():
        if path is not None:
            check_writable(path)


def emit(output: str, text: str, failure: str | None = None, structured: bool = True) -> None:
    """Write a run's result; for a meaningful non-zero result also say why on stderr.

    ``failure`` is the one-line reason when the result is not a success (no
    excuse, time limit, invalid plan): it always goes to stderr, ``--quiet``
    included, and the document is written all the same, since its status says
    what happened.  A text result on stdout is then left out (it would only
    repeat the reason: no message appears on both streams).  A run that ends
    in an error never gets here, so it writes nothing.
    """
    if failure is None or structured or output != "-":
        write_text(output, text)
    if failure is not None:
        ui.error(failure)


def command(fn: F) -> F:
    """Turn library errors into one line on stderr and the documented exit code."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        resume_gc()  # start-up is over (see cli/startup.py)
        ui.quiet = bool(kwargs.get("quiet", False))
        ui.warned = set()
        out_of_memory = False
        try:
            return fn(*args, **kwargs)
        except MemoryError:
            # Only a flag here: the traceback still holds what filled the memory,
            # which is freed once the handler is left.
            out_of_memory = True
        except typer.Exit:
            raise
        except GuidedLfdError as exc:
            ui.error(str(exc))
            raise typer.Exit(exc.exit_code) from None
        except KeyboardInterrupt as exc:
            import cli

            terminated = isinstance(exc, Terminated)
            ui.error("terminated (SIGTERM)" if terminated else "interrupted")
            cli.interruption_reported = True
            raise typer.Exit(EXIT_TERMINATED if terminated else EXIT_INTERRUPTED) from None
        except RecursionError:
            ui.error("internal error: input nested too deeply")
            raise typer.Exit(EXIT_INTERNAL) from None
        except Exception as exc:  # a bug: one line, never a traceback
            if os.environ.get("GUIDED_LFD_DEBUG"):
                raise
            ui.error(f"internal error: {type(exc).__name__}: {exc} (please report; GUIDED_LFD_DEBUG=1 shows the traceback)")
            raise typer.Exit(EXIT_INTERNAL) from None
        if out_of_memory:
            ui.error("out of memory: the run needed more memory than the process may use")
            raise typer.Exit(EXIT_MEMORY)

    return wrapper  # type: ignore[return-value]

