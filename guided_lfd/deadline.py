"""Time limits that bound a whole run, not only its search loops.

The searches check their deadline cooperatively (a ``time.monotonic()``
comparison every few hundred nodes), which lets them stop cleanly and
report what they found.  Code without such checks (parsing, grounding
passes, invariant synthesis in Fast Downward's translator, pyperplan's A*)
is bounded by a watchdog: ``SIGALRM`` raises :class:`SearchTimeout` in the
main thread once the deadline (plus a short grace for the cooperative
checks) has passed.  Watchdogs nest: an inner, shorter one restores the
outer one's remaining time when it ends.

Outside the main thread (or without ``SIGALRM``) only the cooperative checks
apply.
"""

from __future__ import annotations

import math
import signal
import threading
import time
from contextlib import contextmanager
from typing import Iterator

from guided_lfd.errors import SearchTimeout

#: How long past the deadline the watchdog waits: the cooperative checks
#: stop first and keep what was found; the watchdog is the safety net.
GRACE_S = 0.25

#: Objects kept alive until the process ends (None: not asked for; see :func:`linger`).
_LINGERING: list[object] | None = None


def keep_until_exit() -> None:
    """Let :func:`linger` keep objects alive until the process ends.

    For a process that ends without tearing down its interpreter (the
    console script ends with ``os._exit``): freeing a search's millions of
    frontier entries when a deadline stops it takes about a second, which is
    spent after the time limit and helps no one.
    """
    global _LINGERING
    if _LINGERING is None:
        _LINGERING = []


def lingering() -> bool:
    """Whether :func:`keep_until_exit` was called (the process will not free its objects)."""
    return _LINGERING is not None


def linger(*objects: object) -> None:
    """Keep ``objects`` alive until the process ends, if :func:`keep_until_exit` was called."""
    if _LINGERING is not None:
        _LINGERING.extend(objects)


#: The largest time limit taken (about 11.6 days): beyond it a deadline overflows the platform's timers.
MAX_TIME_LIMIT = 1e6


def checked_time_limit(value: float | None, name: str = "--time-limit") -> float | None:
    """``value`` if it is a usable time limit (None = none; finite, > 0, at most :data:`MAX_TIME_LIMIT`), else
    :class:`~guided_lfd.errors.OptionError` naming it as ``name`` (the option, or the library's argument)."""
    from guided_lfd.errors import OptionError

    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not value <= MAX_TIME_LIMIT \
            or not math.isfinite(value) or value <= 0:
        shown = f"{value:g}" if isinstance(value, float) else repr(value)
        shown = shown if len(shown) <= 24 else shown[:20] + "..."
        raise OptionError(f"{name} {shown}: expected a number of seconds > 0 and <= {MAX_TIME_LIMIT:g}")
    return float(value)


def deadline_after(seconds: float | None, start: float | None = None) -> float | None:
    """The ``time.monotonic()`` value ``seconds`` after ``start`` (default: now); None = no limit."""
    if seconds is None:
        return None
    return (time.monotonic() if start is None else start) + seconds


def remaining(deadline: float | None) -> float | None:
    """Seconds left until ``deadline`` (None = unlimited; may be negative)."""
    return None if deadline is None else deadline - time.monotonic()


def seconds_left(deadline: float | None, what: str | None = None) -> float | None:
    """Seconds left before ``deadline`` as a time limit for a call (None: no limit; at least 1 ms, so that the
    call ends as its own timeout); with ``what``, :class:`SearchTimeout` once the deadline has passed."""
    if what is not None:
        check(deadline, what)
    left = remaining(deadline)
    return None if left is None else max(0.001, left)


def check(deadline: float | None, what: str = "run") -> None:
    """Raise :class:`SearchTimeout` if ``deadline`` has passed."""
    if deadline is not None and time.monotonic() > deadline:
        raise SearchTimeout(f"{what} exceeded the time limit")


def _usable() -> bool:
    return threading.current_thread() is threading.main_thread() and hasattr(signal, "SIGALRM")


@contextmanager
def watchdog(deadline: float | None, what: str = "run", grace: float = GRACE_S) -> Iterator[None]:
    """Raise :class:`SearchTimeout` inside the block once ``deadline + grace`` has passed.

    An enclosing watchdog that would fire earlier keeps precedence; when the
    block ends the enclosing one is re-armed with its remaining time.
    """
    if deadline is None or not _usable():
        yield
        return
    fire_at = deadline + grace
    previous_handler = signal.getsignal(signal.SIGALRM)
    previous_left, _ = signal.getitimer(signal.ITIMER_REAL)
    now = time.monotonic()
    outer_at = now + previous_left if previous_left > 0 else math.inf
    if outer_at <= fire_at or fire_at - now > MAX_TIME_LIMIT:  # the enclosing limit comes first, or none in reach
        yield
        return

    def on_alarm(signum, frame):
        raise SearchTimeout(f"{what} exceeded the time limit")

    signal.signal(signal.SIGALRM, on_alarm)
    signal.setitimer(signal.ITIMER_REAL, max(1e-3, fire_at - now))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous_handler)
        if outer_at != math.inf:
            signal.setitimer(signal.ITIMER_REAL, max(1e-3, outer_at - time.monotonic()))
