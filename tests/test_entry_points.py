"""Every entry point is a subcommand: bench, quality, demos, study (no argparse main left in the library)."""

from __future__ import annotations

import ast

from conftest import ROOT


def test_no_argparse_main_is_left_in_the_library():
    for path in sorted((ROOT / "guided_lfd").rglob("*.py")):
        tree = ast.parse(path.read_text())
        names = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
        imports = {a.name for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom)) for a in n.names}
        assert "main" not in names and "argparse" not in imports, path


def test_quality_prints_the_report(runner, app):
    from guided_lfd.demonstration.quality import quality_markdown, quality_report

    result = runner.invoke(app, ["quality", "--demos", str(ROOT / "data/demos"), "--domains", str(ROOT / "data/domains")])
    assert result.exit_code == 0, result.output
    assert result.stdout == quality_markdown(quality_report(ROOT / "data/demos", ROOT / "data/domains"))
    assert result.stdout.startswith("| demonstration | frame F1 | segments (truth / found) |")


def test_demos_renders_the_shipped_demonstrations_again(runner, app, tmp_path):
    result = runner.invoke(app, ["demos", str(tmp_path), "--domains", str(ROOT / "data/domains"), "--quiet"])
    assert result.exit_code == 0, result.output
    rendered = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*.csv"))
    assert len(rendered) == 60  # 2 kitchens x 5 demonstrators x (excuse, complete) x (trace, state, labels)
    for rel in rendered:
        assert (tmp_path / rel).read_bytes() == (ROOT / "data/demos" / rel).read_bytes(), rel


def test_bench_refuses_an_unknown_step(runner, app):
    result = runner.invoke(app, ["bench", "bogus"])
    assert result.exit_code == 37 and "STEP bogus: expected one of: generate, run, report, all" in result.stderr
