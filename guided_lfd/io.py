"""Writing outputs safely, and the JSON conventions of guided-lfd."""

from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path
from typing import Any

from guided_lfd.errors import Location, OutputError

#: Version of every JSON document guided-lfd writes; bumped on incompatible change.
FORMAT_VERSION = 1


def write_text(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (``-`` writes stdout).

    The text goes to a temporary file next to the target which then replaces
    it, so an interrupted run never leaves a half-written file and the
    previous content survives any failure before the rename.
    """
    name = str(path)
    if name == "-":
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    target = Path(name)
    if target.is_dir():
        raise OutputError("is a directory, expected a file name", Location(name))
    directory = target.parent if str(target.parent) else Path(".")
    try:
        directory.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise OutputError(f"cannot write ({exc.strerror})", Location(name)) from None
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
    except OSError as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise OutputError(f"cannot write ({exc.strerror})", Location(name)) from None
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def json_document(kind: str, body: dict[str, Any]) -> str:
    """Serialise a versioned JSON document (stable key order, trailing newline)."""
    doc = {"format": f"guided-lfd/{kind}", "format_version": FORMAT_VERSION, **body}
    return json.dumps(doc, indent=2, sort_keys=False) + "\n"
