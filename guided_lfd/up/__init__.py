"""guided-lfd for unified-planning (the optional extra ``guided-lfd[up]``).

A unified-planning (UP) ``Problem`` becomes guided-lfd's task through UP's
own PDDL writer, whose name maps lead every name back to the UP object,
fluent or action (:func:`to_task`). On top of it:

* two UP engines: :class:`GuidedLfdPlanner` (a ``OneshotPlanner``: guided-lfd's
  optimal A* with LM-cut, the plans validated) and :class:`GuidedLfdValidator`
  (a ``PlanValidator``: guided-lfd's validator), added to a UP factory by
  ``factory.add_engine(name, "guided_lfd.up", "GuidedLfdPlanner")`` or
  :func:`register`;
* the minimal excuse of a UP problem the robot cannot solve, in UP's terms
  (:func:`find_up_excuses`: fluent expressions to add and remove, and the
  robot's plan from the excuse state as a ``SequentialPlan``).

The names load on first use, and only this package imports
unified_planning: ``import guided_lfd`` does not need it.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

try:
    import unified_planning  # noqa: F401  # every name here needs it
except ModuleNotFoundError as exc:
    raise ModuleNotFoundError("guided_lfd.up needs unified-planning: pip install 'guided-lfd[up]'",
                              name=exc.name) from None

#: Public name -> the module that defines it.
_EXPORTS = {
    "UpTask": "guided_lfd.up.task",
    "to_task": "guided_lfd.up.task",
    "unsupported_features": "guided_lfd.up.task",
    "SUPPORTED_KIND": "guided_lfd.up.task",
    "GuidedLfdPlanner": "guided_lfd.up.engines",
    "GuidedLfdValidator": "guided_lfd.up.engines",
    "register": "guided_lfd.up.engines",
    "UpExcuse": "guided_lfd.up.excuse",
    "UpExcuseReport": "guided_lfd.up.excuse",
    "find_up_excuses": "guided_lfd.up.excuse",
}

__all__ = list(_EXPORTS)

if TYPE_CHECKING:  # for type checkers and IDEs; at run time __getattr__ loads them
    from guided_lfd.up.engines import GuidedLfdPlanner, GuidedLfdValidator, register
    from guided_lfd.up.excuse import UpExcuse, UpExcuseReport, find_up_excuses
    from guided_lfd.up.task import SUPPORTED_KIND, UpTask, to_task, unsupported_features


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'guided_lfd.up' has no attribute {name!r}")
    value = getattr(import_module(module), name)
    globals()[name] = value  # once loaded, a plain attribute
    return value


def __dir__() -> list[str]:
    return sorted(__all__)
