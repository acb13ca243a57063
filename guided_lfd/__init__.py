"""guided-lfd: excuse-guided learning from demonstration.

The library behind the ``guided-lfd`` command: parse PDDL, ground it, plan and
validate, find minimal excuses (what the robot needs a human to demonstrate),
and learn, merge and evaluate demonstrated skills.

    from guided_lfd import read_task, find_excuses, ExcuseOptions
    domain, problem = read_task("robot.pddl", "problem.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(time_limit=10))
    print(report.to_json())          # what `guided-lfd excuse --json` prints

The names below load on first use, so that ``import guided_lfd`` (and the
command line's start-up) stays cheap.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

#: Public name -> the module that defines it (read_task is defined below).
_EXPORTS = {
    "plan": "guided_lfd.api",
    "validate": "guided_lfd.api",
    "PlanReport": "guided_lfd.api",
    "find_excuses": "guided_lfd.excuse.engine",
    "ExcuseOptions": "guided_lfd.excuse.engine",
    "ExcuseReport": "guided_lfd.excuse.report",
    "Excuse": "guided_lfd.excuse.report",
    "Progress": "guided_lfd.excuse.progress",
    "Semantics": "guided_lfd.excuse.space",
    "Change": "guided_lfd.excuse.change",
    "PlanStep": "guided_lfd.planning.validation",
    "ValidationReport": "guided_lfd.planning.validation",
    "Domain": "guided_lfd.pddl.model",
    "Problem": "guided_lfd.pddl.model",
    "GuidedLfdError": "guided_lfd.errors",
}

__all__ = ["__version__", "read_task", *_EXPORTS]

if TYPE_CHECKING:  # for type checkers and IDEs; at run time __getattr__ loads them
    from unified_planning.model import Problem as UPProblem

    from guided_lfd.api import PlanReport, Source, plan, validate
    from guided_lfd.errors import GuidedLfdError
    from guided_lfd.excuse.change import Change
    from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
    from guided_lfd.excuse.report import Excuse, ExcuseReport
    from guided_lfd.excuse.progress import Progress
    from guided_lfd.excuse.space import Semantics
    from guided_lfd.pddl.model import Domain, Problem
    from guided_lfd.planning.validation import PlanStep, ValidationReport


def read_task(domain: Source | UPProblem, problem: Source | None = None) -> tuple[Domain, Problem]:
    """The task of a domain and a problem, each a path or PDDL text (:func:`guided_lfd.api.read_task`), or of a
    unified-planning ``Problem`` alone (the extra ``up``; :func:`guided_lfd.up.to_task` also maps the names back).

    Raises the one-line :class:`~guided_lfd.errors.GuidedLfdError` of the
    command line (``file:line:col``; ``<domain>``/``<problem>`` for text).
    """
    if problem is None and type(domain).__module__.startswith("unified_planning."):  # never a str or a Path
        from guided_lfd.up.task import to_task

        task = to_task(domain)  # type: ignore[arg-type]
        return task.domain, task.problem
    from guided_lfd.api import read_task as read_pddl_task

    return read_pddl_task(domain, problem)  # type: ignore[arg-type]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'guided_lfd' has no attribute {name!r}")
    value = getattr(import_module(module), name)
    globals()[name] = value  # once loaded, a plain attribute
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
