"""The excuse document: what ``guided-lfd excuse`` prints, as text or JSON, from an :class:`ExcuseReport`.

Library code: :meth:`ExcuseReport.to_json` gives exactly the command line's
document, and the command line uses these functions to write it.
"""

from __future__ import annotations

from typing import Any

from guided_lfd.excuse.engine import Excuse, ExcuseReport, describe_change
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import Problem

__all__ = ["excuse_document", "excuse_summary", "excuse_text"]


def excuse_summary(report: ExcuseReport, spellings: dict[str, str]) -> str:
    """Why no excuse is given, in one line (empty when one is)."""
    if report.status is ExcuseStatus.NONE:
        fixed = report.statistics.fixed_predicates or []
        while_fixed = f" while {', '.join(fixed)} stay fixed" if fixed else ""
        if report.unachievable_goals:
            goals = ", ".join(str(g) for g in report.unachievable_goals)
            return (f"no excuse exists: no robot skill achieves {goals}{while_fixed}, and no change of the initial "
                    f"state short of satisfying the goal helps; a new skill must be demonstrated")
        return (f"no excuse exists: no change of the initial state lets the robot reach the goal{while_fixed}; "
                "a new skill must be demonstrated")
    if report.status is ExcuseStatus.NONE_WITHIN_SIZE:
        return "no excuse within --max-size; a larger change or a new skill is needed"
    if report.status is ExcuseStatus.TIMEOUT:
        return "time limit reached before a minimal excuse was found"
    return ""


def _excuse_dict(e: Excuse, spellings: dict[str, str]) -> dict[str, Any]:
    return {
        "size": e.size,
        "cost": e.cost,
        "changes": [
            {"change": str(c), "op": "add" if c.added else "delete", "atom": str(c.atom),
             "text": describe_change(c, spellings)}
            for c in e.changes
        ],
        "state": [str(a) for a in sorted(e.state)],
        "plan": [str(step) for step in e.plan],
        "plan_length": len(e.plan),
        "plan_cost": e.plan_cost,
        "plan_optimal": e.plan_optimal,
        "validated": True,
    }


def excuse_document(report: ExcuseReport, domain: str, problem: str, spellings: dict[str, str]) -> dict[str, Any]:
    """The body of the ``guided-lfd/excuse`` JSON document (see the README's JSON formats)."""
    first = report.excuse
    return {
        "domain": domain,
        "problem": problem,
        "semantics": report.semantics.value,
        "strategy": report.strategy,
        "status": report.status.value,
        "message": excuse_summary(report, spellings) or None,
        "excuse": _excuse_dict(first, spellings) if first else None,
        "alternatives": [_excuse_dict(e, spellings) for e in report.excuses[1:]],
        "robot_plan": None if report.robot_plan is None else [str(step) for step in report.robot_plan],
        "robot_plan_cost": report.robot_plan_cost,
        "unachievable_goals": [str(g) for g in report.unachievable_goals],
        "invariants": sorted({g.invariant for g in report.invariant_groups}),
        "statistics": report.statistics.to_dict(),
    }


def _cost_words(cost: int | None, prob: Problem) -> str:
    """``, cost 15`` where actions have costs (under the problem's metric); nothing for unit costs."""
    return f", cost {cost}" if prob.metric and cost is not None else ""


def excuse_text(report: ExcuseReport, prob: Problem, spellings: dict[str, str]) -> str:
    """The report as ``guided-lfd excuse`` prints it for people."""
    name = spellings.get(prob.name, prob.name)
    lines: list[str] = []
    if report.status is ExcuseStatus.ALREADY_SOLVABLE:
        plan = report.robot_plan or []
        lines.append(f"{name}: already solvable, no excuse needed (empty excuse).")
        lines.append(f"Robot plan ({len(plan)} steps{_cost_words(report.robot_plan_cost, prob)}, validated):")
        lines += [f"  {i}. {step}" for i, step in enumerate(plan, 1)]
        return "\n".join(lines) + "\n"
    if not report.excuses:
        return f"{name}: {excuse_summary(report, spellings)}\n"
    total = len(report.excuses)
    for k, e in enumerate(report.excuses, 1):
        which = f"Minimal excuse {k} of {total}" if total > 1 else "Minimal excuse"
        lines.append(f"{which} for {name} (size {e.size}, cost {e.cost}): demonstrate how to reach")
        width = max(len(describe_change(c, spellings)) for c in e.changes)
        for c in e.changes:
            lines.append(f"  {describe_change(c, spellings):<{width}}   {c}")
        kind = "optimal, validated" if e.plan_optimal else "validated"
        lines.append(f"then the robot's own plan ({len(e.plan)} steps{_cost_words(e.plan_cost, prob)}, {kind}):")
        lines += [f"  {i}. {step}" for i, step in enumerate(e.plan, 1)]
        if k < total:
            lines.append("")
    return "\n".join(lines) + "\n"
