"""Where the project's shipped data is, from whatever folder a command runs.

``study``, ``quality``, ``demos`` and ``bench`` read the repository's data
(``data/study``, ``data/demos``, ``data/domains``, ``benchmarks/``).  Run
from the checkout, the working folder is the root; run from anywhere else,
the checkout the package was installed from (``pip install -e .``) is.  An
explicit ``--root`` always wins.  When neither holds the data, the missing
file is named (exit 30) instead of failing deep inside a reader.
"""

from __future__ import annotations

from pathlib import Path

from guided_lfd.errors import InputFileError, Location

__all__ = ["checkout_root", "data_root", "require", "require_folder"]


def checkout_root() -> Path | None:
    """The source checkout this package runs from (the folder above it, when it holds ``data/``), else None."""
    here = Path(__file__).resolve().parent.parent
    return here if (here / "data").is_dir() else None


def data_root(root: Path | None, needs: str) -> Path:
    """``root`` when given; else the working folder when it holds ``needs`` (a path relative to the root); else
    the checkout's (see :func:`checkout_root`); else the working folder (its missing file is then named)."""
    if root is not None:
        return root
    if (Path.cwd() / needs).exists():
        return Path(".")
    checkout = checkout_root()
    if checkout is not None and (checkout / needs).exists():
        return checkout
    return Path(".")


def require(*paths: Path, hint: str = "run from the checkout, or give --root DIR") -> None:
    """Refuse (exit 30) the first of ``paths`` that is not there, saying where the data is looked for."""
    for path in paths:
        if not path.exists():
            raise InputFileError(f"not found (the repository's shipped data: {hint})", Location(str(path)))


def require_folder(path: Path, expected: str) -> None:
    """Refuse (exit 30) ``path`` where it is there but no folder, saying which folder was ``expected``."""
    if path.exists() and not path.is_dir():
        raise InputFileError(f"is a file, expected {expected}", Location(str(path)))
