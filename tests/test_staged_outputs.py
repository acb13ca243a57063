"""Commands that write a folder of results (``study``, ``demos``) stage them beside it and move them in at the end
(issue #25): a run interrupted (Ctrl-C, SIGTERM) or failing part-way leaves the folder as it was, and no staged
files behind.  Before, SIGTERM during ``demos`` or ``study`` left a half-written folder."""

from __future__ import annotations

from pathlib import Path

import pytest

from guided_lfd.errors import EXIT_INTERRUPTED
from guided_lfd.io import staged_folder


def _files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in folder.rglob("*") if p.is_file()}


def test_a_staged_run_moves_its_files_in_and_keeps_the_others(tmp_path):
    out = tmp_path / "results"
    out.mkdir()
    (out / "mine.txt").write_text("mine")
    (out / "study.md").write_text("old")
    with staged_folder(out) as stage:
        assert stage.parent == out  # inside OUT: on its file system, whatever leads there
        (stage / "study.md").write_text("new")
        (stage / "study" / "kitchen-1").mkdir(parents=True)
        (stage / "study" / "kitchen-1" / "robot.pddl").write_text("(define)")
    assert _files(out) == {"mine.txt": b"mine", "study.md": b"new", "study/kitchen-1/robot.pddl": b"(define)"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results"]


@pytest.mark.parametrize("stop", [KeyboardInterrupt, OSError])
def test_a_run_stopped_part_way_leaves_the_folder_as_it_was(tmp_path, stop):
    out = tmp_path / "results"
    out.mkdir()
    (out / "study.md").write_text("old")
    with pytest.raises(stop):
        with staged_folder(out) as stage:
            (stage / "study.md").write_text("half")
            raise stop()
    assert _files(out) == {"study.md": b"old"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results"]


def test_a_new_folder_is_not_made_by_a_stopped_run(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with staged_folder(tmp_path / "new" / "results") as stage:
            (stage / "x").write_text("x")
            raise KeyboardInterrupt
    assert list((tmp_path / "new").iterdir()) == []


def _interrupt_after_writing(folder: Path) -> None:
    (folder / "kitchen-1").mkdir(parents=True, exist_ok=True)
    (folder / "kitchen-1" / "P1-excuse.csv").write_text("half")
    raise KeyboardInterrupt


def test_an_interrupted_demos_leaves_its_folder_as_it_was(runner, app, tmp_path, monkeypatch):
    import guided_lfd.demonstration.study_data as study_data

    out = tmp_path / "traces"
    (out / "kitchen-1").mkdir(parents=True)
    (out / "kitchen-1" / "P1-excuse.csv").write_text("mine")
    monkeypatch.setattr(study_data, "render_study", lambda domains, folder: _interrupt_after_writing(folder))
    result = runner.invoke(app, ["demos", str(out)])
    assert result.exit_code == EXIT_INTERRUPTED, result.stderr
    assert _files(out) == {"kitchen-1/P1-excuse.csv": b"mine"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["traces"]


def test_an_interrupted_study_leaves_its_folder_as_it_was(runner, app, tmp_path, monkeypatch):
    import guided_lfd.study as study

    from conftest import ROOT

    out = tmp_path / "results"
    monkeypatch.setattr(study, "run_study", lambda root, log: (None, []))
    monkeypatch.setattr(study, "write_artefacts", lambda folder, kitchens: _interrupt_after_writing(folder))
    result = runner.invoke(app, ["study", "--root", str(ROOT), "--out", str(out)])
    assert result.exit_code == EXIT_INTERRUPTED, result.stderr
    assert list(tmp_path.iterdir()) == []
