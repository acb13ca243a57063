"""What every report (evaluate, the study, the benchmark) writes the same way.

* **Paths** in reports are relative to a root where they can be
  (:func:`relative_path`), so outputs do not depend on where the checkout is.
* **Tables**: CSV text (:func:`csv_text`: ``None`` is an empty cell, ``\\n``
  line ends) and markdown (:func:`markdown_table`: an empty or missing cell is
  ``-``, a float shows three decimals).
* **Fractions** (F1, useful fraction, misdirected guidance, time ratios, size
  reductions) are rounded by one rule, :func:`round_fraction`: Python's
  ``round(value, 4)``, four digits after the point (round half to even on the
  float), ``None`` stays ``None``.  This is what JSON and CSV outputs carry.
  The one exception is the paper's own mean time ratio in the study's
  headline, kept at the paper's three digits (0.385) since it restates a
  figure the paper printed.
  Markdown and text tables *show* floats with three decimals
  (:func:`markdown_cell`); that is display only, the files keep four digits.
* **Figures** are PNG written without the ``Software`` metadata
  (:func:`save_figure`), so reruns are byte-identical.
* **A missing matplotlib** (the ``plots`` extra): :func:`pyplot` raises
  :class:`PlotsUnavailable`; a report then skips its plots and says so where
  they would be (:func:`plots_markdown`, :data:`PLOTS_HINT`), and the command
  line prints one line on stderr.  Nothing else fails.

matplotlib is imported only when a figure is drawn (not at import time).
"""

from __future__ import annotations

import csv
import io
from pathlib import Path
from typing import Any, Iterable, Sequence

#: Digits after the point of every reported fraction (JSON and CSV).
FRACTION_DIGITS = 4

#: What a report says, and the command line prints, when matplotlib is missing.
PLOTS_HINT = "plots need the plots extra: pip install 'guided-lfd[plots]'"

__all__ = [
    "FRACTION_DIGITS", "PLOTS_HINT", "PlotsUnavailable", "csv_text", "markdown_cell", "markdown_table",
    "plots_markdown", "pyplot", "relative_path", "round_fraction", "save_figure",
]


class PlotsUnavailable(ImportError):
    """matplotlib (the ``plots`` extra) is not installed: plots are skipped."""

    def __init__(self) -> None:
        super().__init__(PLOTS_HINT)


def round_fraction(value: float | None) -> float | None:
    """``value`` rounded to :data:`FRACTION_DIGITS` digits (``None`` stays ``None``)."""
    return None if value is None else round(value, FRACTION_DIGITS)


def relative_path(path: str | Path, root: Path) -> str:
    """``path`` relative to ``root`` (both resolved) when it lies under it; else ``path`` as given."""
    try:
        return str(Path(path).resolve().relative_to(root.resolve()))
    except ValueError:
        return str(path)


def csv_text(header: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """A CSV document: the header, then the rows; ``None`` is an empty cell, lines end in ``\\n``."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(["" if v is None else v for v in row] for row in rows)
    return buf.getvalue()


def markdown_cell(value: Any) -> str:
    """One markdown table cell: ``-`` for ``None`` or ``""``, a float with three decimals, else ``str``."""
    if value is None or value == "":
        return "-"
    return f"{value:.3f}" if isinstance(value, float) else str(value)


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """A markdown table (no trailing newline); cells as :func:`markdown_cell` writes them."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(markdown_cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)


def pyplot() -> Any:
    """``matplotlib.pyplot`` on the Agg backend; :class:`PlotsUnavailable` without matplotlib."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise PlotsUnavailable() from None
    return plt


def save_figure(fig: Any, path: Path, dpi: int) -> Path:
    """Lay out ``fig`` (tightly, unless it has a layout of its own), write it as PNG without version metadata
    (reruns are byte-identical), close it."""
    import matplotlib.pyplot as plt

    if fig.get_layout_engine() is None:
        fig.tight_layout()
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    plt.close(fig)
    return path


def plots_markdown(plots: list[Path] | None, base: Path | None = None) -> list[str]:
    """The ``## Plots`` section: a link per plot, or :data:`PLOTS_HINT` when ``plots`` is None (skipped).

    A link is relative to ``base`` (default: the plot's own folder, i.e. its file name).
    """
    if plots is None:
        return ["## Plots", "", f"Not drawn: {PLOTS_HINT}."]
    return ["## Plots", ""] + [f"![{p.stem}]({relative_path(p, p.parent if base is None else base)})"
                               for p in plots]
