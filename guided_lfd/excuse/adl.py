"""Excuses on ADL tasks: the paper's breadth-first search over change sets, an optimal planner call each.

The landmark strategy and its reachability oracle work on STRIPS ground
tasks (plain adds and deletes, no axioms).  An ADL task (conditional effects,
quantified or disjunctive conditions, derived predicates) is grounded in Fast
Downward's normal form with every changeable atom kept
(:func:`guided_lfd.planning.adl.ground_adl`) and searched with the baseline
strategy, whose candidate checks are guided-lfd's ADL A*: change sets by
increasing weight, only basic atoms changed (derived atoms follow from them),
the invariants of the consistent semantics synthesised from the normalised
task.  Every excuse passes the independent check, which evaluates
conditional effects and derived predicates with its own lifted code.
"""

from __future__ import annotations

import time
from dataclasses import replace
from typing import TYPE_CHECKING

from guided_lfd.errors import OptionError
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.excuse.baseline import BaselineSearch
from guided_lfd.excuse import outcome as search_outcome
from guided_lfd.excuse.outcome import SearchLimits
from guided_lfd.excuse.verify import verify_excuse
from guided_lfd.planning.validation import plan_steps

if TYPE_CHECKING:
    from guided_lfd.excuse.engine import ExcuseOptions, _Run
    from guided_lfd.excuse.report import ExcuseReport

#: The strategy every ADL task is searched with (see the module's docstring).
ADL_STRATEGY = "baseline"


def adl_options(options: "ExcuseOptions") -> "ExcuseOptions":
    """The options an ADL task is searched with: the baseline strategy (``--slack`` needs the landmark one)."""
    if options.slack:
        raise OptionError(f"--slack {options.slack}: needs the landmark strategy, which plans STRIPS tasks only "
                          "(this domain uses ADL)")
    return replace(options, strategy=ADL_STRATEGY)


def search_adl(run: "_Run", space: ChangeSpace) -> "ExcuseReport":
    """Check solvability and search the minimal excuses of an ADL task prepared by the engine."""
    from guided_lfd.deadline import seconds_left
    from guided_lfd.planning import find_plan

    options, task, stats = run.options, space.task, run.stats
    run._enter("already solvable?")
    plan0 = find_plan(task, search="astar-lmcut", time_limit_s=seconds_left(run.deadline, "already solvable?")).plan
    if plan0 is not None:
        verify_excuse(run.domain, run.problem, [], plan0)
        run.robot_plan_cost = sum(a.cost for a in plan0)
        return run.report(ExcuseStatus.ALREADY_SOLVABLE, plan_steps(plan0), candidates=0, planner_calls=1)
    run._enter("searching")
    limits = SearchLimits(all_minimal=options.all_minimal, max_size=options.max_size, deadline=run.deadline,
                          max_solutions=search_outcome.MAX_EXCUSES + 1)
    search_start = time.monotonic()
    stats.setup_time_s = round(search_start - run.start, 6)
    outcome = BaselineSearch().search(space, limits, run.progress)
    stats.search_time_s = round(time.monotonic() - search_start, 6)
    stats.candidates, stats.planner_calls, stats.nodes_expanded = (outcome.candidates, outcome.planner_calls + 1,
                                                                   outcome.expanded)
    search_outcome.cap_excuses(outcome, stats)
    run.phase = "robot plan"
    for changes in outcome.solutions:  # each plan is the ADL A*'s: optimal
        run.excuses.append(run.checked_excuse(changes, outcome.plans[changes], True))
    status = outcome.status
    if status is ExcuseStatus.TIMEOUT:
        stats.phase = "searching"
        if run.excuses:
            status = ExcuseStatus.FOUND
            stats.incomplete = True
        else:
            run._bound_reached(space, outcome.lower_bound)
    return run.report(status)
