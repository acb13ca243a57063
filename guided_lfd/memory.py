"""Memory caps: a run that outgrows its cap ends as the documented memout, not by the OOM killer."""

from __future__ import annotations


def cap_memory(pid: int, megabytes: int) -> None:
    """Cap process ``pid``'s address space, so that running out raises MemoryError there.

    Without a cap, a run whose frontier outgrows the machine (the baseline's
    breadth-first search on sokoban task04 filled a 24 GiB machine) is killed by the
    kernel's OOM killer, and may take the run beside it down too.  Only the soft
    limit is set, and never above a hard limit already in force (``ulimit -v``,
    a cluster job): raising it would fail every run.
    """
    import resource

    try:
        _, hard = resource.prlimit(pid, resource.RLIMIT_AS)
        limit = megabytes * 1024 * 1024
        if hard != resource.RLIM_INFINITY:
            limit = min(limit, hard)
        resource.prlimit(pid, resource.RLIMIT_AS, (limit, hard))
    except ProcessLookupError:
        pass  # it has ended already


#: The largest ``--memory-limit`` (MiB): 1 EiB, far above any machine, and its bytes still fit the C long the
#: operating system's limit takes.
MAX_MEMORY_MIB = 2**40


def cap_own_memory(megabytes: int) -> None:
    """Cap this process's address space (``--memory-limit``); see :func:`cap_memory`."""
    import os

    cap_memory(os.getpid(), megabytes)
