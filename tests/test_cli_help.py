"""The help a planning user expects: ``-h``, usage lines in the paper's words, an example, the exit codes.

Every subcommand's help is read through typer's CliRunner (no terminal):
its usage line names the arguments by their metavars, every option that
takes a value shows one, the help ends with an example that runs and the
exit codes the command can give, each a documented one
(guided_lfd/errors.py's EXIT_CODES, docs/exit-codes.md's table).
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys

import pytest

from conftest import ROOT
from guided_lfd.errors import EXIT_CODES, EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_OK, EXIT_USAGE

#: Each subcommand's usage line, in the words of docs/commands.md (the paper's).
USAGES = {
    "excuse": "guided-lfd excuse [OPTIONS] DOMAIN PROBLEM",
    "plan": "guided-lfd plan [OPTIONS] DOMAIN PROBLEM",
    "segment": "guided-lfd segment [OPTIONS] TRACE",
    "learn-domain": "guided-lfd learn-domain [OPTIONS] DEMONSTRATIONS...",
    "merge": "guided-lfd merge [OPTIONS] PRIOR LEARNED...",
    "evaluate": "guided-lfd evaluate [OPTIONS] ROBOT PROBLEM --human DOMAIN",
    "validate": "guided-lfd validate [OPTIONS] DOMAIN PROBLEM PLAN",
    "bench": "guided-lfd bench [OPTIONS] STEP",
    "quality": "guided-lfd quality [OPTIONS]",
    "demos": "guided-lfd demos [OPTIONS] [OUT]",
    "teach": "guided-lfd teach [OPTIONS] ROBOT PROBLEM...",
    "study": "guided-lfd study [OPTIONS]",
}

#: Subcommands whose file arguments may be '-' (standard input).
READS_STDIN = ("excuse", "plan", "segment", "learn-domain", "merge", "evaluate", "validate")

#: A metavar: a word in capitals (FILE, SECONDS, MIB) or a choice ([literal|consistent]).
METAVAR = re.compile(r"[A-Z][A-Z_]*|\[[a-z-]+(\|[a-z-]+)+\]")


def _help(runner, app, *argv: str) -> str:
    result = runner.invoke(app, list(argv), color=True)
    assert result.exit_code == 0, (argv, result.output)
    return result.output


def _section(text: str, title: str) -> list[str]:
    """The indented lines under ``title:`` up to the next blank line."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip() == title)
    block = []
    for line in lines[start + 1:]:
        if not line.strip():
            break
        block.append(line)
    return block


def _readme_exit_codes() -> set[int]:
    readme = (ROOT / "docs" / "exit-codes.md").read_text()
    table = readme.split("# Exit codes\n", 1)[1].split("\n## ", 1)[0]
    return {int(m.group(1)) for m in re.finditer(r"^\| (\d+) \|", table, re.MULTILINE)}


# -- the group ---------------------------------------------------------------

def test_top_level_help_with_h_and_no_summary_cut_off(runner, app):
    from cli.main import SUBCOMMANDS

    text = _help(runner, app, "-h")
    assert text == _help(runner, app, "--help")
    assert text.startswith("Usage: guided-lfd [OPTIONS] COMMAND [ARGS]...\n")
    for option in ("--version", "--install-completion", "--show-completion", "-h, --help"):
        assert option in text
    commands = _section(text, "Commands:")
    assert [line.split()[0] for line in commands] == list(SUBCOMMANDS)
    for line in commands:
        assert "..." not in line, line
    for name, spec in SUBCOMMANDS.items():
        assert f"  {name} " in text and spec.help in text
        assert "\n" not in spec.help and spec.help.endswith(".")


def test_version_stays(runner, app):
    from guided_lfd import __version__

    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0
    assert result.output == f"guided-lfd {__version__}\n"


def test_summaries_fit_a_standard_terminal():
    """The command list has 78 - 6 - len('learn-domain') = 60 columns for a summary: none is cut."""
    from typer.core import TyperCommand

    from cli.main import SUBCOMMANDS

    for name, spec in SUBCOMMANDS.items():
        assert TyperCommand(name, help=spec.help).get_short_help_str(60) == spec.help, name


# -- every subcommand ----------------------------------------------------------

@pytest.mark.parametrize("name", list(USAGES))
def test_subcommand_help(name, runner, app):
    from cli.main import SUBCOMMANDS, argument_name, load_subcommand

    assert set(USAGES) == set(SUBCOMMANDS)
    text = _help(runner, app, name, "-h")
    assert text == _help(runner, app, name, "--help")
    lines = text.splitlines()
    assert lines[0] == f"Usage: {USAGES[name]}"
    # typer's own placeholders are gone: no {domain}, no <str>, <float>, <int>
    assert "{" not in lines[0] and not re.search(r"<[a-z][a-z_\[\]|, ]*>", text), text
    command = load_subcommand(name)
    for param in command.params:
        if param.param_type_name == "argument":
            assert param.metavar and METAVAR.fullmatch(param.metavar), (name, param.name)
            assert f"\n  {argument_name(param, usage=False)}  " in text
        elif not param.is_flag:
            assert param.metavar and METAVAR.fullmatch(param.metavar), (name, param.opts)
            assert f"{max(param.opts, key=len)} {param.metavar}" in text, (name, param.opts)
    # CliRunner wraps help at 80 columns; the blocks kept as written (example, exit codes) fit the 78
    # that click gives text on an 80-column terminal
    assert max(len(line) for line in lines) <= 80, max(lines, key=len)
    for title in ("Example:", "Exit codes:"):
        assert max(len(line) for line in _section(text, title)) <= 78, title
    # plain text on a non-terminal: no colour codes, no unrendered rich or markdown markup
    assert "\x1b[" not in text
    assert not re.search(r"\[/?(bold|dim|italic|red|green|yellow|blue|cyan|magenta|link)[^\]]*\]|\[/\]|`", text), text


@pytest.mark.parametrize("name", list(USAGES))
def test_help_ends_with_an_example_and_the_documented_exit_codes(name, runner, app):
    text = _help(runner, app, name, "-h")
    assert text.index("Options:") < text.index("Example:") < text.index("Exit codes:")
    example = " ".join(line.strip() for line in _section(text, "Example:")).replace("\\ ", "")
    assert shlex.split(example)[:2] == ["guided-lfd", name]
    codes = _section(text, "Exit codes:")
    assert text.rstrip("\n").endswith(codes[-1]), "the exit codes end the help"
    readme = _readme_exit_codes()
    seen = []
    for line in codes:
        match = re.fullmatch(r"    (\d+) +(\S.*)", line)
        assert match, line
        code, meaning = int(match.group(1)), match.group(2)
        assert code in EXIT_CODES, f"{name} -h names exit code {code}, not in guided_lfd.errors.EXIT_CODES"
        assert code in readme, f"{name} -h names exit code {code}, not in docs/exit-codes.md's table"
        if code != EXIT_OK:
            assert meaning == EXIT_CODES[code]
        seen.append(code)
    assert seen == sorted(set(seen))
    assert {EXIT_OK, EXIT_INTERNAL, EXIT_USAGE, EXIT_INTERRUPTED} <= set(seen)


def test_readme_table_and_errors_agree():
    assert _readme_exit_codes() == set(EXIT_CODES)


@pytest.mark.parametrize("name", READS_STDIN)
def test_dash_is_explained(name, runner, app):
    from cli.main import load_subcommand

    text = _help(runner, app, name, "-h")
    for param in load_subcommand(name).params:
        if param.param_type_name == "argument":
            assert "'-' = stdin" in (param.help or ""), (name, param.name)
    assert "'-' = stdout" in text


def test_codes_named_in_option_help_are_documented(runner, app):
    """'(exit 13)' in an option's help, too, is a code of errors.EXIT_CODES that the command lists."""
    from cli.main import SUBCOMMANDS

    for name in SUBCOMMANDS:
        text = _help(runner, app, name, "-h")
        listed = {int(line.split()[0]) for line in _section(text, "Exit codes:")}
        for code in re.findall(r"exit (\d+)", " ".join(text.split())):
            assert int(code) in EXIT_CODES and int(code) in listed, (name, code)


# -- the examples run ------------------------------------------------------------

def test_the_examples_run(runner, app, tmp_path, monkeypatch):
    """The examples of the pipeline's commands, in the order they feed each other, each exit 0."""
    (tmp_path / "data").symlink_to(ROOT / "data")
    monkeypatch.chdir(tmp_path)
    for name in ("segment", "learn-domain", "merge", "evaluate", "plan", "validate", "excuse"):
        text = _help(runner, app, name, "-h")
        example = " ".join(line.strip() for line in _section(text, "Example:")).replace("\\ ", "")
        argv = shlex.split(example)[1:]
        result = runner.invoke(app, argv)
        assert result.exit_code == 0, (example, result.output)
    assert (tmp_path / "merged.pddl").exists() and (tmp_path / "k1.plan").exists()


# -- shell completion ------------------------------------------------------------

def test_shell_completion_completes_commands_and_choices(tmp_path):
    def complete(words: str, cword: int) -> list[str]:
        env = dict(os.environ, _GUIDED_LFD_COMPLETE="complete_bash", COMP_WORDS=words, COMP_CWORD=str(cword))
        code = f"import sys; sys.path.insert(0, {str(ROOT)!r}); sys.argv = ['guided-lfd']; from cli.main import run; run()"
        done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60,
                              cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        return done.stdout.split()

    assert complete("guided-lfd ex", 1) == ["excuse"]
    assert complete("guided-lfd excuse --semantics ", 3) == ["literal", "consistent"]
