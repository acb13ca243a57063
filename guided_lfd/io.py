"""Reading inputs and writing outputs safely, and the JSON conventions of guided-lfd."""

from __future__ import annotations

import os
import stat
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

from guided_lfd.errors import InputFileError, Location, OutputError

#: Version of every JSON document guided-lfd writes; bumped on incompatible change.
FORMAT_VERSION = 1
#: Document versions this release reads.
READABLE_VERSIONS = (1,)

#: Inputs larger than this are refused (a device like /dev/zero never ends).
MAX_INPUT_BYTES = 64 * 1024 * 1024


def read_text(path: str | Path, expected: str = "PDDL") -> str:
    """Return the text of ``path`` (``-`` reads stdin), tolerating a BOM.

    ``expected`` names what the file should hold, for error messages.

    Raises :class:`InputFileError` for missing, unreadable, binary or empty
    files, so that no caller ever sees an ``OSError``.
    """
    name = str(path)
    try:
        if name == "-":
            if sys.stdin is None:
                raise InputFileError("standard input is closed", Location(name))
            if hasattr(sys.stdin, "buffer"):
                data = sys.stdin.buffer.read(MAX_INPUT_BYTES + 1)
            else:
                data = sys.stdin.read(MAX_INPUT_BYTES + 1).encode()
        else:
            with open(name, "rb") as fh:
                data = fh.read(MAX_INPUT_BYTES + 1)
    except FileNotFoundError:
        raise InputFileError("file not found", Location(name)) from None
    except IsADirectoryError:
        raise InputFileError("is a directory, expected a file", Location(name)) from None
    except OSError as exc:
        raise InputFileError(f"cannot read file ({exc.strerror})", Location(name)) from None
    except ValueError:  # a NUL in the name: no file can be called so
        raise InputFileError("file not found (the name contains a NUL character)", Location(name.replace("\0", "\\0"))) from None
    if len(data) > MAX_INPUT_BYTES:
        raise InputFileError(f"larger than {MAX_INPUT_BYTES // (1024 * 1024)} MiB, expected {expected}", Location(name))
    if b"\x00" in data:
        raise InputFileError("binary file, expected text", Location(name))
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise InputFileError("not UTF-8 text", Location(name, line)) from None
    if not text.strip():
        raise InputFileError(f"empty file, expected {expected}", Location(name))
    return text


def write_text(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (``-`` writes stdout).

    A regular file is replaced through a temporary file in the same folder,
    so an interrupted run never leaves a half-written file and the previous
    content survives any failure; it keeps the old file's permissions (new
    files get the umask's).  A symbolic link is followed, and a device or
    FIFO (``/dev/null``) is written in place, never replaced.
    """
    name = str(path)
    if name == "-":
        _write_stdout(text)
        return
    import tempfile  # here, not at start-up: most runs write only to stdout

    target = _output_target(name)
    try:
        if target.exists() and not target.is_file():
            with open(target, "w", encoding="utf-8") as fh:  # device or FIFO: write in place
                fh.write(text)
            return
        mode = stat.S_IMODE(target.stat().st_mode) if target.exists() else _default_mode()
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name[:50]}.", suffix=".tmp", dir=target.parent)
    except OutputError:
        raise
    except OSError as exc:
        raise OutputError(f"cannot write ({exc.strerror or exc})", Location(name)) from None
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write ({exc.strerror or exc})", Location(name)) from None
        raise


@contextmanager
def staged_folder(out: Path) -> Iterator[Path]:
    """A hidden folder inside ``out`` to write a run's many outputs into; they move into place when the run ends.

    A run that fails or is interrupted (Ctrl-C, SIGTERM) before then leaves ``out`` as it was (a folder it made
    is removed again) and removes the staged files, so a folder of results is never half replaced; the move
    itself is one rename per file, inside ``out`` (so on its file system, whatever links or mounts lead there).
    Files already in ``out`` that the run does not write are kept.
    """
    import shutil
    import tempfile

    made = not out.exists()
    try:
        out.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(prefix=".staged-", dir=out))
    except OSError as exc:
        raise OutputError(f"cannot write there ({exc.strerror or exc})", Location(str(out))) from None
    done = False
    try:
        yield stage
        _move_into(stage, out)
        done = True
    finally:
        shutil.rmtree(stage, ignore_errors=True)
        if made and not done:
            shutil.rmtree(out, ignore_errors=True)


def _move_into(stage: Path, out: Path) -> None:
    """Move every file under ``stage`` to the same place under ``out`` (each an atomic replace)."""
    try:
        for folder, subfolders, files in os.walk(stage):
            target = out / Path(folder).relative_to(stage)
            for name in subfolders:
                (target / name).mkdir(exist_ok=True)
            for name in files:
                os.replace(Path(folder) / name, target / name)
    except OSError as exc:
        raise OutputError(f"cannot write there ({exc.strerror or exc})", Location(str(out))) from None


def _output_target(name: str) -> Path:
    """The file an output name stands for (links followed); refuses folders."""
    if name.endswith(("/", os.sep)) or not Path(name).name:
        raise OutputError("expected a file name, got a folder", Location(name))
    try:
        target = Path(os.path.realpath(name))
        is_dir = target.is_dir()
        looped = target.is_symlink()  # realpath stops where links loop; writing there would replace a link
    except OSError as exc:  # a name the OS refuses (too long, a loop of links, ...)
        raise OutputError(f"cannot write ({exc.strerror or exc})", Location(name)) from None
    if looped:
        raise OutputError("cannot write (a loop of symbolic links)", Location(name))
    if is_dir:
        raise OutputError("is a directory, expected a file name", Location(name))
    return target


def _default_mode() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _write_stdout(text: str) -> None:
    stream = sys.stdout
    if stream is None:
        raise OutputError("standard output is closed", Location("-"))
    try:
        fd = _real_descriptor(stream)
        if fd is None:
            stream.write(text)
            stream.flush()
        else:
            # Python's buffered stdout takes a short write to a pipe whose reader left (| head -c10) as done,
            # and the rest of the output is lost without a word: write every byte, or fail.
            stream.flush()
            view = memoryview(text.encode(stream.encoding or "utf-8", errors="replace"))
            while view:
                view = view[os.write(fd, view):]
    except BrokenPipeError:
        raise OutputError("standard output closed by the reader (broken pipe)", Location("-")) from None
    except (OSError, ValueError) as exc:
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
        raise OutputError(f"cannot write standard output ({reason})", Location("-")) from None


def _real_descriptor(stream) -> int | None:
    """``stream``'s file descriptor when it is the process's own stdout (not a test runner's capture)."""
    try:
        fd = stream.fileno()
    except (AttributeError, OSError, ValueError):
        return None
    return fd if fd == 1 else None


def check_writable(path: str | Path) -> None:
    """Fail early (before any work is written) if ``path`` cannot be an output file."""
    name = str(path)
    if name == "-":
        return
    target = _output_target(name)
    try:
        return _check_writable_target(name, target)
    except OSError as exc:
        raise OutputError(f"cannot write ({exc.strerror or exc})", Location(name)) from None


def _check_writable_target(name: str, target: Path) -> None:
    if not target.parent.is_dir():
        raise OutputError("its folder does not exist", Location(name))
    if len(target.name) > 200:
        raise OutputError("file name too long", Location(name))
    if not os.access(target.parent, os.W_OK) and not (target.exists() and os.access(target, os.W_OK)):
        raise OutputError("no permission to write there", Location(name))


def json_document(kind: str, body: dict[str, Any], version: int = FORMAT_VERSION) -> str:
    """Serialise a versioned JSON document (stable key order, trailing newline); ``version``: the format's own
    where it moved on (``guided-lfd/teach`` is at 2)."""
    import json  # here, not at start-up: only --json and JSON inputs need it

    doc = {"format": f"guided-lfd/{kind}", "format_version": version, **body}
    return json.dumps(doc, indent=2, sort_keys=False) + "\n"


def read_json_document(path: str, kind: str, error: type, origin: str, text: str | None = None) -> tuple[str, dict]:
    """The text and body of a ``guided-lfd/<kind>`` JSON document (``-`` = stdin; ``text``: already read).

    Anything else raises ``error`` (a :class:`~guided_lfd.errors.GuidedLfdError`
    class) naming the file; ``origin`` says which command writes such documents.
    """
    import json

    expected = f"a guided-lfd/{kind} document"
    if text is None:
        text = read_text(path, f"{expected} (from {origin})")
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise error(f"not JSON ({exc.msg}), expected {expected}", Location(path, exc.lineno, exc.colno)) from None
    except RecursionError:
        raise error(f"JSON nested too deeply, expected {expected}", Location(path)) from None
    if not isinstance(doc, dict) or doc.get("format") != f"guided-lfd/{kind}":
        raise error(f"expected {expected} (from {origin})", Location(path, 1))
    version = doc.get("format_version", FORMAT_VERSION)  # a document without one is read as version 1
    if type(version) is not int or version not in READABLE_VERSIONS:
        line = next((n for n, row in enumerate(text.splitlines(), 1) if '"format_version"' in row), 1)
        readable = ", ".join(str(v) for v in READABLE_VERSIONS)
        raise error(f"format_version {json.dumps(version)} of guided-lfd/{kind} is not one this release reads "
                    f"(it reads version {readable})", Location(path, line))
    return text, doc

