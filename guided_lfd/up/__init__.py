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

Only this package imports unified_planning: ``import guided_lfd`` does not
need it.
"""

from __future__ import annotations

try:
    import unified_planning  # noqa: F401  # every name here needs it
except ModuleNotFoundError as exc:
    raise ModuleNotFoundError("guided_lfd.up needs unified-planning: pip install 'guided-lfd[up]'",
                              name=exc.name) from None

from guided_lfd.up.engines import GuidedLfdPlanner, GuidedLfdValidator, register  # noqa: E402
from guided_lfd.up.excuse import UpExcuse, UpExcuseReport, find_up_excuses  # noqa: E402
from guided_lfd.up.task import SUPPORTED_KIND, UpTask, to_task, unsupported_features  # noqa: E402

__all__ = ["SUPPORTED_KIND", "GuidedLfdPlanner", "GuidedLfdValidator", "UpExcuse", "UpExcuseReport", "UpTask",
           "find_up_excuses", "register", "to_task", "unsupported_features"]
