"""A symbolic search in a forked process, beside the search that runs here.

Portfolios (``plan``'s default, the excuse search's default) run the symbolic
engine this way: the first exact answer wins, and the worker is killed when
the run ends.  A process, not a thread: a diagram operation is one long C
call that neither a deadline check nor a signal can interrupt, but a process
can always be ended.  The worker inherits the ground task by ``fork`` (no
copying until either side writes) and sends back one picklable answer.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
from typing import Any, Callable


class Forked:
    """``target(*args)`` running in a forked process; :meth:`poll` for its answer, :meth:`stop` to end it.

    ``answer`` is ``("ok", value)`` or ``("error", message)`` once it has come (a worker that died without
    answering, e.g. killed for memory, gives ``("error", ...)`` too).  ``niceness`` (0: none) lowers the
    worker's scheduling priority: where cores are short it takes what the search here leaves.
    """

    def __init__(self, target: Callable[..., Any], *args: Any, niceness: int = 0) -> None:
        context = multiprocessing.get_context("fork")
        self._receive, send = context.Pipe(duplex=False)
        self.process = context.Process(target=_run, args=(send, target, args, niceness), daemon=True)
        self.process.start()
        send.close()
        self.answer: tuple[str, Any] | None = None

    def poll(self, timeout: float = 0.0) -> bool:
        """Whether the answer has come (waiting up to ``timeout`` seconds for it)."""
        if self.answer is None:
            try:
                if self._receive.poll(timeout):
                    self.answer = self._receive.recv()
            except (EOFError, OSError):
                self.answer = ("error", f"the symbolic worker ended without an answer "
                                        f"(exit code {self.process.exitcode})")
        return self.answer is not None

    def value(self) -> Any:
        """The worker's value, or None if it has not answered or failed."""
        if self.answer is None or self.answer[0] != "ok":
            return None
        return self.answer[1]

    def stop(self) -> None:
        """End the worker (if still running) and free its pipe."""
        if self.process.is_alive():
            self.process.kill()
        self.process.join(timeout=5)
        self._receive.close()


def _die_with_parent() -> None:
    """Have the kernel kill this worker when its parent dies, even by SIGKILL (Linux; elsewhere the worker
    ends at its own deadline)."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
        if os.getppid() == 1:  # the parent died before the call
            os._exit(0)
    except (OSError, AttributeError):
        pass


def _run(send: Any, target: Callable[..., Any], args: tuple, niceness: int = 0) -> None:
    # The parent's handlers (its watchdog's alarm, the command line's clean-up on SIGTERM) are not the worker's.
    for sig in (signal.SIGALRM, signal.SIGTERM, signal.SIGINT):
        signal.signal(sig, signal.SIG_DFL)
    signal.setitimer(signal.ITIMER_REAL, 0)
    _die_with_parent()
    if niceness:
        os.nice(niceness)
    # The answer goes through the pipe: holding the parent's stdout and stderr open would keep a caller that
    # reads them (a benchmark runner) waiting for a worker its run no longer needs.
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    os.dup2(devnull, 2)
    from guided_lfd.symbolic import diagrams

    diagrams.MEMORY_SHARE = 0.5
    try:
        answer: tuple[str, Any] = ("ok", target(*args))
    except BaseException as exc:  # noqa: BLE001 - reported to the parent, which decides
        answer = ("error", f"{type(exc).__name__}: {exc}")
    try:
        send.send(answer)
    finally:
        os._exit(0)
