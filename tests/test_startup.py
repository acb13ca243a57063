"""Start-up: what a plain run imports, and the shortcuts that keep it small.

``excuse``, ``plan`` and ``validate`` run in a fresh interpreter through the
console script's entry point (``cli.main.run``); at exit the interpreter
reports ``sys.modules``.  A small task must not import pandas, matplotlib or
numpy (numpy is only for LM-cut on large tasks), nor pydantic (typer's
coercion, see cli/coercion.py) or rich.console (see cli/common.py).
"""

from __future__ import annotations

import io
import json
import subprocess
import sys
from enum import Enum

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import ROOT, damaged_tasks, kitchen

ROBOT, PROBLEM = kitchen(1)
HUMAN, _ = kitchen(1, "human")
KITCHEN_PLAN = "(open_drawer pinkdrawer)\n(take redplate table)\n(put_inside redplate pinkdrawer)\n"

#: Runs guided-lfd with ARGV and writes the imported module names to MODULES at exit.
RUN_CLI = """
import atexit, json, sys
sys.path.insert(0, {root!r})
atexit.register(lambda: open({modules!r}, "w").write(json.dumps(sorted(sys.modules))))
from cli.main import run
sys.argv = ["guided-lfd", *{argv!r}]
run()
"""


def run_cli(tmp_path, *argv: str) -> tuple[subprocess.CompletedProcess, set[str]]:
    """Run ``guided-lfd ARGV`` in a fresh interpreter: its result and every module it imported."""
    modules = tmp_path / "modules.json"
    code = RUN_CLI.format(root=str(ROOT), modules=str(modules), argv=list(argv))
    # stderr is a pipe, not a terminal, as in a script: the usual case to keep fast
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    return done, set(json.loads(modules.read_text()))


def top_level(modules: set[str]) -> set[str]:
    return {m.split(".")[0] for m in modules}


@pytest.fixture
def plan_file(tmp_path):
    path = tmp_path / "kitchen-1.plan"
    path.write_text(KITCHEN_PLAN)
    return str(path)


@pytest.mark.parametrize("command", ["excuse", "excuse-json", "plan", "plan-unsolvable", "validate"])
def test_small_task_imports_no_heavy_library(command, tmp_path, plan_file):
    argv, code, out = {
        "excuse": (["excuse", ROBOT, PROBLEM], 0, "Minimal excuse for kitchen-1-store-plate"),
        "excuse-json": (["excuse", ROBOT, PROBLEM, "--json", "--semantics", "literal"], 0, '"status": "excuse-found"'),
        "plan": (["plan", HUMAN, PROBLEM], 0, "(open_drawer pinkdrawer)"),
        "plan-unsolvable": (["plan", ROBOT, PROBLEM], 10, ""),
        "validate": (["validate", HUMAN, PROBLEM, plan_file], 0, "valid: 3 step(s), goal reached"),
    }[command]
    done, modules = run_cli(tmp_path, *argv)
    assert done.returncode == code, done.stderr
    assert out in done.stdout
    assert "Traceback" not in done.stderr
    heavy = top_level(modules) & {"pandas", "matplotlib", "numpy", "scipy"}
    assert not heavy, f"guided-lfd {command} on kitchen-1 imported {sorted(heavy)}"
    avoidable = modules & {"pydantic", "rich.console", "rich.progress", "cli.evaluate", "cli.segment",
                           "cli.learn_domain", "cli.merge"}
    assert not avoidable, f"guided-lfd {command} on kitchen-1 imported {sorted(avoidable)}"


def test_main_help_imports_no_subcommand(tmp_path):
    done, modules = run_cli(tmp_path, "--help")
    assert done.returncode == 0, done.stderr
    assert "learn-domain  Learn PDDL actions from demonstrations" in done.stdout
    assert not {m for m in modules if m.startswith("cli.")} - {"cli.main", "cli.coercion", "cli.startup"}
    assert "guided_lfd.excuse" not in modules


def test_large_task_still_takes_the_numpy_path(monkeypatch):
    """numpy is imported on demand; a task on the numpy path gets it (and numpy.ma)."""
    from guided_lfd.excuse import lmcut
    from guided_lfd.excuse.space import Semantics, build_space
    from guided_lfd.planning.grounding import ground
    from guided_lfd.pddl.reader import parse_task

    task = ground(*parse_task(ROBOT, PROBLEM))
    space = build_space(task, Semantics.LITERAL)
    small = lmcut.RelaxedExcuseTask(space)
    assert small.small and not hasattr(small, "goal")  # the list tables only
    monkeypatch.setattr(lmcut, "SMALL_TASK_ACTIONS", 0)
    relaxed = lmcut.RelaxedExcuseTask(space)
    assert not relaxed.small
    assert lmcut.np is not None and "numpy.ma" in sys.modules
    assert relaxed.bound(task.init, 0) == small.bound(task.init, 0)


def test_gc_is_paused_for_start_up_only(tmp_path):
    """run() pauses the collector; a command turns it back on before its work."""
    import gc

    from cli.common import command
    from cli.startup import pause_gc, resume_gc

    seen = []

    @command
    def work(quiet: bool = False) -> None:
        seen.append(gc.isenabled())

    assert gc.isenabled()
    try:
        pause_gc()
        assert not gc.isenabled()
        work()
        assert seen == [True] and gc.isenabled()
    finally:
        resume_gc()
        gc.enable()
    gc.disable()  # a collector someone else turned off stays off
    try:
        work()
        assert seen == [True, False]
    finally:
        gc.enable()


# -- the lazy registry -------------------------------------------------------

def test_registry_help_is_the_commands_own():
    """--help lists the registry's help line: it must give the line typer makes from the docstring."""
    from cli.main import SUBCOMMANDS, load_subcommand
    from typer.core import TyperCommand

    for name, spec in SUBCOMMANDS.items():
        real = load_subcommand(name)
        stub = TyperCommand(name, help=spec.help)
        assert real.name == name
        for limit in (10, 30, 45, 60, 74, 120, 400):
            assert stub.get_short_help_str(limit) == real.get_short_help_str(limit), (name, limit)


def test_every_subcommand_is_listed_and_runs_its_help(runner, app):
    from cli.main import SUBCOMMANDS

    listing = runner.invoke(app, ["--help"])
    assert listing.exit_code == 0
    for name in SUBCOMMANDS:
        assert f"\n  {name} " in listing.output
        result = runner.invoke(app, [name, "--help"])
        assert result.exit_code == 0, (name, result.output)
        assert f"Usage: guided-lfd {name} [OPTIONS]" in result.output


def test_mistyped_command_still_gets_a_suggestion(runner, app):
    result = runner.invoke(app, ["exuse"])
    assert result.exit_code == 2
    assert "No such command 'exuse'. Did you mean 'excuse'?" in result.output


# -- quick coercion: the same values as typer's own --------------------------

class _Ctx:
    """Stands in for a click context: coercion only passes it on (to choice matching)."""

    token_normalize_func = None


def _values_for(param) -> list:
    annotation = param.type_descriptor.annotation
    values = [None, "", "x", "a b", "-", "3", "1e3", "open=2", ("a", "b"), [], ("x",), 1, 2.5, True, b"bytes"]
    if isinstance(annotation, type) and issubclass(annotation, Enum):
        values += list(annotation)
        values += [m.value for m in annotation] + [m.value.upper() for m in annotation] + ["nope"]
    return values


def test_quick_coercion_gives_typers_result_or_defers():
    from typer._coercion import build_runtime_param

    from cli.coercion import QuickCoercion
    from cli.main import SUBCOMMANDS, load_subcommand

    checked = 0
    for name in SUBCOMMANDS:
        command = load_subcommand(name)
        for param in command.params:
            quick = QuickCoercion(param)
            full = build_runtime_param(param.type_descriptor)
            for value in _values_for(param):
                try:
                    expected = ("ok", full.coerce(value, param=param, ctx=_Ctx()))
                except Exception as exc:
                    expected = ("error", type(exc).__name__, str(exc))
                try:
                    got = ("ok", quick.coerce(value, param=param, ctx=_Ctx()))
                except Exception as exc:
                    got = ("error", type(exc).__name__, str(exc))
                assert got == expected, (name, param.name, value)
                if got[0] == "ok":
                    assert type(got[1]) is type(expected[1])
                checked += 1
    assert checked > 300


# -- plain diagnostics: rich's bytes without rich ----------------------------

def _rich_prints(message: str, markup: bool) -> str:
    from rich.console import Console

    buffer = io.StringIO()
    Console(file=buffer, highlight=False, soft_wrap=True, _environ={}).print(message, markup=markup)
    return buffer.getvalue()


MESSAGES = [
    "[dim]landmark search: 1 candidate(s), 2 reachability check(s), 0.02 s[/]",
    "[dim]out.json written[/]",
    "plan of length 3 found by astar-lmcut in 0.00 s (optimal), validated",
    "[dim][/]", "", " lead and trail ", "a" * 300, "x:y", ":smile:", "[bold]b[/bold]", "a [dim]b[/] c",
    "[dim]a[/][dim]b[/]", "path\\[1]", "tab\there", "line\nbreak", "caf\u00e9", "[dim]:+1:[/]", "[]", "[x]",
    "data/robot.pddl:3:5: unknown predicate 'foo'", "100% [dim]", "[/]", "x [link=y]z[/link]",
]


@pytest.mark.parametrize("message", MESSAGES)
@pytest.mark.parametrize("markup", [True, False])
def test_plain_text_is_what_rich_prints(message, markup):
    from cli.common import plain_text

    text = plain_text(message, markup)
    if text is not None:
        assert text + "\n" == _rich_prints(message, markup)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=st.sampled_from("ab :[]/\\-_=.,()'\"%*#@!?0123456789\t\u00e9"), max_size=40),
       st.booleans(), st.booleans())
def test_plain_text_agrees_with_rich(body, dim, markup):
    from cli.common import plain_text

    message = f"[dim]{body}[/]" if dim else body
    text = plain_text(message, markup)
    if text is not None:
        assert text + "\n" == _rich_prints(message, markup)


def test_plain_stderr_only_for_a_plain_file(monkeypatch):
    from cli import common

    monkeypatch.setattr(sys, "stderr", io.StringIO())
    for name in ("FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE"):
        monkeypatch.delenv(name, raising=False)
    assert common.plain_stderr()
    monkeypatch.setenv("FORCE_COLOR", "1")
    assert not common.plain_stderr()  # rich would colour: it must decide
    monkeypatch.delenv("FORCE_COLOR")

    class Tty(io.StringIO):
        def isatty(self) -> bool:
            return True

    monkeypatch.setattr(sys, "stderr", Tty())
    assert not common.plain_stderr()


def test_diagnostics_written_directly_match_rich(monkeypatch):
    """Ui.info and Ui.error write the same bytes with and without the shortcut."""
    from cli import common

    for name in ("FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE"):
        monkeypatch.delenv(name, raising=False)
    outputs = []
    for shortcut in (True, False):
        monkeypatch.setattr(common, "plain_stderr", lambda: shortcut)
        monkeypatch.setattr(sys, "stderr", io.StringIO())
        ui = common.Ui()
        for message in MESSAGES:
            for show in (ui.info, ui.error):
                try:
                    show(message)
                except Exception as exc:  # rich rejects bad markup ('[/]' closing nothing): so must we
                    sys.stderr.write(f"<{type(exc).__name__}>")
        ui.quiet = True
        ui.info("[dim]not shown[/]")
        ui.error("shown")
        outputs.append(sys.stderr.getvalue())
    assert outputs[0] == outputs[1]


# -- tarski reads the text without its comments: the same result -------------

def _visible_tokens(text: str) -> list[tuple]:
    from antlr4 import InputStream, Token
    from tarski.io._fstrips.parser.lexer import fstripsLexer

    lexer = fstripsLexer(InputStream(text))
    lexer.removeErrorListeners()
    out = []
    while True:
        token = lexer.nextToken()
        if token.channel == Token.DEFAULT_CHANNEL:
            out.append((token.type, token.text, token.line, token.column))
        if token.type == Token.EOF:
            return out


def _corpus() -> list:
    from test_fast_reader import _large_ipc_task

    return sorted(p for folder in ("data", "tests/data") for p in (ROOT / folder).rglob("*.pddl")
                  if not _large_ipc_task(p))


def test_without_comments_gives_tarski_the_same_tokens():
    from guided_lfd.pddl.reader import without_comments

    texts = [p.read_text(encoding="utf-8-sig") for p in _corpus()]
    texts += ["(a ; c\n b)", "(a ; c", "(a ;c\r\n b)", "(a ; x\ry\n b)", "a;b\n", ";\n;;\n(x)", "(x);", "(p ?x; y\n)"]
    stripped = 0
    for text in texts:
        assert _visible_tokens(without_comments(text)) == _visible_tokens(text)
        stripped += without_comments(text) != text
    assert stripped > 10


def _parse_outcome(domain: str, problem: str):
    from guided_lfd.errors import GuidedLfdError
    from guided_lfd.pddl.reader import parse_task

    try:
        dom, prob = parse_task(domain, problem)
    except GuidedLfdError as exc:
        return ("error", type(exc).__name__, str(exc))
    return ("ok", repr(dom.actions), repr(dom.predicates), repr(dom.types), repr(dom.constants),
            repr(sorted(prob.init)), repr(prob.goal), repr(prob.objects))


def test_reading_without_comments_changes_no_result_nor_error(tmp_path, monkeypatch):
    """Damaged kitchen files (seeded): each parses, or fails with the same message, either way.

    Syntax errors can quote comments (or stop inside one): those are
    re-read from the text as written.
    """
    from guided_lfd.pddl import reader

    domain_text = (ROOT / ROBOT).read_text()
    problem_text = (ROOT / PROBLEM).read_text()
    pieces = ["(", ")", " ", "?x", "- ", "and ", "not ", ":effect ", "; note\n", ";x", "\n", "foo ", "\r\n", ";(\n", ":"]
    outcomes = set()
    for domain, problem in damaged_tasks(tmp_path, domain_text, problem_text, pieces, seed=7, count=250):
        fast = _parse_outcome(domain, problem)
        monkeypatch.setattr(reader, "without_comments", lambda text: text)
        as_written = _parse_outcome(domain, problem)
        monkeypatch.undo()
        assert fast == as_written
        outcomes.add(fast[0] if fast[0] == "ok" else fast[1])
    assert {"ok", "PddlSyntaxError"} <= outcomes


def test_corpus_reads_the_same_without_comments(monkeypatch):
    from guided_lfd.pddl import reader

    pairs = []
    for path in _corpus():
        domain = next((path.parent / n for n in ("domain.pddl", "robot.pddl") if (path.parent / n).exists()), None)
        if domain is not None and domain != path:
            pairs.append((str(domain), str(path)))
    assert len(pairs) > 40
    for domain, problem in pairs:
        fast = _parse_outcome(domain, problem)
        monkeypatch.setattr(reader, "without_comments", lambda text: text)
        assert _parse_outcome(domain, problem) == fast, problem
        monkeypatch.undo()
