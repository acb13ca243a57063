"""How an excuse search ended: one status for the strategies, the report, the document and the exit code."""

from __future__ import annotations

from enum import StrEnum

from guided_lfd import errors

__all__ = ["ExcuseStatus"]


class ExcuseStatus(StrEnum):
    """The outcome of an excuse search (its value is the document's ``status``).

    A strategy ends ``FOUND``, ``NONE``, ``NONE_WITHIN_SIZE`` or ``TIMEOUT``;
    the engine adds ``ALREADY_SOLVABLE`` (no search was needed).
    """

    FOUND = "excuse-found"
    ALREADY_SOLVABLE = "already-solvable"
    NONE = "no-excuse"  # proved: no change of the initial state helps
    NONE_WITHIN_SIZE = "no-excuse-within-size"  # none within --max-size
    TIMEOUT = "timeout"

    @property
    def exit_code(self) -> int:
        """The command line's exit code for this outcome (docs/exit-codes.md)."""
        return _EXIT_CODES[self]


_EXIT_CODES = {
    ExcuseStatus.FOUND: errors.EXIT_OK,
    ExcuseStatus.ALREADY_SOLVABLE: errors.EXIT_OK,
    ExcuseStatus.NONE: errors.EXIT_NO_EXCUSE,
    ExcuseStatus.NONE_WITHIN_SIZE: errors.EXIT_NO_EXCUSE_WITHIN_LIMIT,
    ExcuseStatus.TIMEOUT: errors.EXIT_TIME_LIMIT,
}
