"""Exception hierarchy and exit codes of guided-lfd.

Every error the user can cause is a :class:`GuidedLfdError` carrying an exit
code and, where it stems from a file, a :class:`Location`.  The command-line
layer prints ``str(error)`` as one line on stderr and exits with
``error.exit_code``; nothing else should ever reach the user as a traceback.

Exit codes are grouped by meaning (tens: an answer other than success,
twenties: a resource limit, thirties: bad input); docs/exit-codes.md says
what Fast Downward's driver means by the same numbers, mostly something else:

====  ==========================================================
code  meaning
====  ==========================================================
0     success (plan found, plan valid, excuse found or not needed)
1     internal error (a bug: please report it)
2     command-line usage error
10    task unsolvable (``plan``: proven by exhaustive search)
11    no excuse exists: a new skill must be demonstrated
12    plan invalid (``validate``)
13    no excuse within ``--max-size``
14    ``teach`` ended, the task still unsolved (rounds used up, no demonstration)
15    ``teach`` reached the goal only through the demonstration
20    time limit reached
21    task too large to ground (atom or action limit)
22    out of memory (the process's address-space limit was reached)
30    input file missing, unreadable or empty
31    PDDL syntax error
32    PDDL semantic error (unknown object, predicate, type, arity)
33    unsupported PDDL requirement or construct
34    inputs do not belong together (domain and problem, domains to merge)
35    plan file error (unknown action, wrong arity, syntax)
36    demonstration trace / segments error
37    bad option value (cost specification, fixed predicate, ...)
40    output could not be written
130   interrupted (Ctrl-C)
143   terminated (SIGTERM)
====  ==========================================================
"""

from __future__ import annotations

from dataclasses import dataclass

EXIT_OK = 0
EXIT_INTERNAL = 1
EXIT_USAGE = 2
EXIT_UNSOLVABLE = 10
EXIT_NO_EXCUSE = 11
EXIT_PLAN_INVALID = 12
EXIT_NO_EXCUSE_WITHIN_LIMIT = 13
EXIT_NOT_TAUGHT = 14
EXIT_DEMONSTRATION_ONLY = 15
EXIT_TIME_LIMIT = 20
EXIT_TOO_LARGE = 21
EXIT_MEMORY = 22
EXIT_INPUT_FILE = 30
EXIT_PDDL_SYNTAX = 31
EXIT_PDDL_SEMANTIC = 32
EXIT_UNSUPPORTED = 33
EXIT_MISMATCH = 34
EXIT_PLAN_FILE = 35
EXIT_TRACE = 36
EXIT_BAD_OPTION = 37
EXIT_OUTPUT = 40
EXIT_INTERRUPTED = 130
EXIT_TERMINATED = 143

#: Exit code -> short meaning; docs/exit-codes.md's table and a test are generated from it.
EXIT_CODES: dict[int, str] = {
    EXIT_OK: "success",
    EXIT_INTERNAL: "internal error (a bug)",
    EXIT_USAGE: "command-line usage error (an unknown option, a missing argument)",
    EXIT_UNSOLVABLE: "task unsolvable",
    EXIT_NO_EXCUSE: "no excuse exists: a new skill must be demonstrated",
    EXIT_PLAN_INVALID: "plan invalid",
    EXIT_NO_EXCUSE_WITHIN_LIMIT: "no excuse within --max-size",
    EXIT_NOT_TAUGHT: "teaching ended, the task still unsolved (rounds used up, no demo)",
    EXIT_DEMONSTRATION_ONLY: "teaching ended, the goal reached only through the demonstration",
    EXIT_TIME_LIMIT: "time limit reached",
    EXIT_TOO_LARGE: "task too large to ground",
    EXIT_MEMORY: "out of memory",
    EXIT_INPUT_FILE: "input file missing, unreadable or empty",
    EXIT_PDDL_SYNTAX: "PDDL syntax error",
    EXIT_PDDL_SEMANTIC: "PDDL semantic error",
    EXIT_UNSUPPORTED: "unsupported PDDL requirement or construct",
    EXIT_MISMATCH: "inputs do not belong together (domain and problem, domains to merge)",
    EXIT_PLAN_FILE: "plan file error",
    EXIT_TRACE: "demonstration trace or segments error",
    EXIT_BAD_OPTION: "bad option value (refused by the parser or by the command alike)",
    EXIT_OUTPUT: "output could not be written",
    EXIT_INTERRUPTED: "interrupted (Ctrl-C)",
    EXIT_TERMINATED: "terminated (SIGTERM)",
}


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the process is (see ``cli.main.run``): a subclass of KeyboardInterrupt, so that
    every clean-up Ctrl-C runs (temporary files removed, outputs left as they were) runs for it too."""


@dataclass(frozen=True)
class Location:
    """A position in an input file; ``line`` and ``col`` are 1-based."""

    path: str
    line: int | None = None
    col: int | None = None

    def __str__(self) -> str:
        if self.line is None:
            return self.path
        if self.col is None:
            return f"{self.path}:{self.line}"
        return f"{self.path}:{self.line}:{self.col}"


class GuidedLfdError(Exception):
    """Base of all errors guided-lfd reports to its user."""

    exit_code: int = EXIT_INTERNAL
    kind: str = "error"

    def __init_subclass__(cls, exit_code: int | None = None, kind: str | None = None, **rest: object) -> None:
        """A subclass states its exit code and the word its messages start with in its header."""
        super().__init_subclass__(**rest)
        if exit_code is not None:
            cls.exit_code = exit_code
        if kind is not None:
            cls.kind = kind

    def __init__(self, message: str, location: Location | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.location = location

    def __str__(self) -> str:
        prefix = f"{self.location}: " if self.location is not None else ""
        text = f"{prefix}{self.kind}: {self.message}"
        if text.isprintable():
            return text
        # One line, whatever a damaged input put into the message (a NUL, a line break): as escapes.
        return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in text)


class InputFileError(GuidedLfdError, exit_code=EXIT_INPUT_FILE, kind="input error"):
    """A file is missing, unreadable, empty or not text."""


class PddlSyntaxError(GuidedLfdError, exit_code=EXIT_PDDL_SYNTAX, kind="syntax error"):
    """The text is not well-formed PDDL."""


class PddlSemanticError(GuidedLfdError, exit_code=EXIT_PDDL_SEMANTIC, kind="semantic error"):
    """Well-formed PDDL that names something undeclared or mistyped."""


class UnsupportedFeatureError(GuidedLfdError, exit_code=EXIT_UNSUPPORTED, kind="unsupported"):
    """A requirement or construct outside STRIPS + typing + negation + equality."""


class MismatchError(GuidedLfdError, exit_code=EXIT_MISMATCH, kind="mismatch"):
    """A problem that names another domain than the one given."""


class MergeError(MismatchError):
    """Domains to merge declare the same name incompatibly."""


class PlanFileError(GuidedLfdError, exit_code=EXIT_PLAN_FILE, kind="plan error"):
    """A plan file that cannot be read as a sequence of ground actions."""


class TraceError(GuidedLfdError, exit_code=EXIT_TRACE, kind="trace error"):
    """A demonstration trace or segment file that cannot be used."""


class OptionError(GuidedLfdError, exit_code=EXIT_BAD_OPTION, kind="option error"):
    """An option value that does not make sense for the given task."""


class OutputError(GuidedLfdError, exit_code=EXIT_OUTPUT, kind="output error"):
    """An output file that could not be written."""


class SearchTimeout(GuidedLfdError, exit_code=EXIT_TIME_LIMIT, kind="time limit"):
    """A search ran out of its time limit."""


class TaskTooLarge(GuidedLfdError, exit_code=EXIT_TOO_LARGE, kind="too large"):
    """Grounding would exceed the atom or action limit."""
