"""The excuse document: what ``guided-lfd excuse`` prints, as text or JSON, and reading it back.

Library code: :meth:`ExcuseReport.to_json` gives exactly the command line's
document, the command line uses these functions to write it, and
:func:`read_excuse` reads its first excuse (``evaluate --excuse``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from guided_lfd.errors import InputFileError, Location
from guided_lfd.excuse.change import Change, describe_change, describe_skill_change
from guided_lfd.io import read_json_document
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.task import UNREACHABLE_GOAL

if TYPE_CHECKING:  # the report's types, for annotations: the report calls these renderers
    from guided_lfd.excuse.report import Excuse, ExcuseReport

__all__ = ["candidate_text", "excuse_document", "excuse_summary", "excuse_text", "held_fixed_text", "read_excuse",
           "cut_short"]


def held_fixed_text(report: ExcuseReport, model: Domain | None = None) -> str:
    """One line saying what the excuse held fixed and why, and the switch that frees it (empty: nothing held).

    ``model`` is the domain that said what can change (``--fixed-from``, ``--human``), if any."""
    stats, spellings = report.statistics, report.spellings
    parts = [f"{spellings.get(name, name)} ({why})" for name, why in (stats.structure_held or {}).items()]
    if parts:
        return (f"held fixed as the world's structure: {'; '.join(parts)}; --change-structure lets the excuse "
                "change them")
    others = [spellings.get(name, name) for name in stats.fixed_predicates or []]
    if others and model is not None:
        them = "it" if len(others) == 1 else "them"
        return (f"held fixed: {', '.join(others)} (no action of the model {model.name} changes {them}); without "
                f"--fixed-from or --human the excuse may change {them}")
    return ""


def excuse_summary(report: ExcuseReport, spellings: dict[str, str]) -> str:
    """Why no excuse is given, in one line (empty when one is)."""
    if report.status is ExcuseStatus.NONE:
        stats = report.statistics
        structure = list(stats.structure_held or {})
        if stats.structural_excuse:
            return (f"no excuse keeps the world's structure ({', '.join(structure)} held fixed: kinds of things and "
                    f"fixed graphs no action changes); only one that changes it exists: "
                    f"{' '.join(stats.structural_excuse)} (--change-structure allows it)")
        fixed = [p for p in stats.fixed_predicates or [] if p not in structure]
        while_fixed = f" with {', '.join(fixed)} held fixed" if fixed else ""
        if structure:
            while_fixed += f"{' and' if fixed else ' with'} the world's structure ({', '.join(structure)}) kept"
        if any(g.atom == UNREACHABLE_GOAL for g in report.unachievable_goals):
            return ("no excuse exists: the goal can never hold, in any state (Fast Downward's translator proves it: "
                    "an equality or another condition no state satisfies); no demonstration helps")
        if report.unachievable_goals:
            goals = ", ".join(str(g) for g in report.unachievable_goals)
            return (f"no excuse exists: no robot skill achieves {goals}{while_fixed}, and no change of the initial "
                    f"state short of satisfying the goal helps; a new skill must be demonstrated")
        in_the_way = report.statistics.invariants_in_the_way
        if in_the_way:
            changes = " ".join(report.statistics.literal_excuse or [])
            return (f"no excuse keeps the state invariants{while_fixed}: only the invariants "
                    f"{', '.join(in_the_way)} stand in the way (the literal semantics' excuse {changes} breaks "
                    "them; they may hold only because a skill is missing: try --semantics literal, or "
                    "--invariants-from the complete domain)")
        return (f"no excuse exists: no change of the initial state lets the robot reach the goal{while_fixed}; "
                "a new skill must be demonstrated")
    if report.status is ExcuseStatus.NONE_WITHIN_SIZE:
        return "no excuse within --max-size; a larger change or a new skill is needed"
    if report.status is ExcuseStatus.TIMEOUT:
        return "time limit reached before a minimal excuse was found" + _timeout_words(report)
    return ""


def _timeout_words(report: ExcuseReport) -> str:
    """What a timed-out search proved and found: ``; no excuse smaller than 3 changes (proven); ...``."""
    bound = report.statistics.lower_bound
    if bound is None:  # the time ran out before the search
        return ""
    within = f" within --max-size {report.max_size}" if report.max_size is not None else ""
    smaller = f"smaller than {_count(bound, 'change')}" if report.unit_costs else f"cheaper than {bound}"
    out = f"; no excuse {smaller}{within} (proven)" if bound else ""  # 0 proves nothing (a symbolic search)
    best = report.best_candidate
    if best is None:
        return out + "; none found so far"
    return out + f"; best excuse found so far ({_candidate_kind(best)}): size {best.size}, cost {best.cost}"


def _count(n: int, word: str) -> str:
    """``1 change``, ``3 changes``, ``2 steps``."""
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _candidate_kind(best: Excuse) -> str:
    """What a timed-out run's best excuse is: minimal only when its cost meets the lower bound."""
    return "minimal: it meets the lower bound" if best.proven_minimal else "not proven minimal"


def _excuse_dict(e: Excuse, spellings: dict[str, str]) -> dict[str, Any]:
    return {
        "size": e.size,
        "cost": e.cost,
        "changes": [
            {"change": str(c), "op": "add" if c.added else "delete", "atom": str(c.atom),
             "text": describe_change(c, spellings)}
            for c in e.changes
        ],
        "skill_changes": [
            {"change": str(c), "action": c.action, "precondition": str(c.literal),
             "text": describe_skill_change(c, spellings)}
            for c in e.skill_changes
        ],
        "state": [str(a) for a in sorted(e.state)],
        "plan": [str(step) for step in e.plan],
        "plan_length": len(e.plan),
        "plan_cost": e.plan_cost,
        "plan_optimal": e.plan_optimal,
        "validated": True,
    }


def excuse_document(report: ExcuseReport, domain: str, problem: str, spellings: dict[str, str]) -> dict[str, Any]:
    """The body of the ``guided-lfd/excuse`` JSON document (see docs/formats.md)."""
    first = report.excuse
    return {
        "domain": domain,
        "problem": problem,
        "semantics": report.semantics.value,
        "strategy": report.strategy,
        "status": report.status.value,
        "message": excuse_summary(report, spellings) or None,
        "preference": report.preference,
        "excuse": _excuse_dict(first, spellings) if first else None,
        "alternatives": [_excuse_dict(e, spellings) for e in report.excuses[1:]],
        "best_candidate": (None if report.best_candidate is None else
                           {**_excuse_dict(report.best_candidate, spellings),
                            "proven_minimal": report.best_candidate.proven_minimal}),
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
        lines.append(f"Robot plan ({_count(len(plan), 'step')}{_cost_words(report.robot_plan_cost, prob)}, validated):")
        lines += [f"  {i}. {step}" for i, step in enumerate(plan, 1)]
        return "\n".join(lines) + "\n"
    if not report.excuses:
        return f"{name}: {excuse_summary(report, spellings)}\n" + candidate_text(report, prob, spellings)
    if report.preference:
        lines.append(f"{name}: {report.preference}.")
    total = len(report.excuses)
    for k, e in enumerate(report.excuses, 1):
        if report.preference and k == 1:
            kind = "Preferred excuse"
        else:
            kind = "Minimal excuse" if e.cost == min(x.cost for x in report.excuses) else "Excuse within the slack"
        which = f"{kind} {k} of {total}" if total > 1 else kind
        lines += _excuse_lines(f"{which} for {name} (size {e.size}, cost {e.cost})", e, prob, spellings)
        if k < total:
            lines.append("")
    lines += [f"({note})" for note in cut_short(report)]
    return "\n".join(lines) + "\n"


def candidate_text(report: ExcuseReport, prob: Problem, spellings: dict[str, str]) -> str:
    """A timed-out run's best excuse as the text shows it (empty when there is none)."""
    best = report.best_candidate
    if best is None:
        return ""
    title = f"Best excuse found so far ({_candidate_kind(best)}; size {best.size}, cost {best.cost})"
    return "\n".join(_excuse_lines(title, best, prob, spellings)) + "\n"


def _excuse_lines(title: str, e: Excuse, prob: Problem, spellings: dict[str, str]) -> list[str]:
    """An excuse's lines: ``title``, its changes, then the robot's plan from its state."""
    texts = [(describe_change(c, spellings), str(c)) for c in e.changes]
    texts += [(describe_skill_change(c, spellings), str(c)) for c in e.skill_changes]
    width = max(len(text) for text, _ in texts)
    lines = [f"{title}: demonstrate how to reach"] if e.changes else [f"{title}: show a skill once more"]
    lines += [f"  {text:<{width}}   {change}" for text, change in texts[:len(e.changes)]]
    if e.changes and e.skill_changes:
        lines.append("and show a skill once more")
    lines += [f"  {text:<{width}}   {change}" for text, change in texts[len(e.changes):]]
    kind = "optimal, validated" if e.plan_optimal else "validated"
    dropped = ", with the precondition(s) dropped" if e.skill_changes else ""
    lines.append(f"then the robot's own plan ({_count(len(e.plan), 'step')}{_cost_words(e.plan_cost, prob)}, "
                 f"{kind}{dropped}):")
    lines += [f"  {i}. {step}" for i, step in enumerate(e.plan, 1)]
    return lines


def cut_short(report: ExcuseReport) -> list[str]:
    """Why the excuses listed may not be every one asked for (``--all`` at its cap or out of time), if so."""
    stats, out = report.statistics, []
    if stats.truncated:
        more = f"more excuses within --slack {report.slack}" if report.slack else "more minimal excuses"
        out.append(f"--all stopped at {stats.max_excuses:,} excuses: {more} may exist")
    if stats.incomplete:
        out.append("the time limit ended the search: the excuses listed are minimal, but maybe not all of them")
    return out


def read_excuse(path: str, domain: Domain, problem: Problem) -> list[Change]:
    """The first excuse of a ``guided-lfd/excuse`` JSON document (``guided-lfd excuse --json``).

    Atoms must be ground atoms of the domain's predicates over the problem's
    objects (or the domain's constants); anything else is an
    :class:`~guided_lfd.errors.InputFileError` naming the file.
    """
    text, doc = read_json_document(path, "excuse", InputFileError, "`guided-lfd excuse --json`")
    excuse = doc.get("excuse")
    if not isinstance(excuse, dict) or not isinstance(excuse.get("changes"), list):
        raise InputFileError("expected a guided-lfd/excuse document with an excuse "
                             "(from `guided-lfd excuse --json`)", Location(path, 1))
    if not excuse["changes"]:
        raise InputFileError("the excuse has no changes (expected at least one)", _position(text, path, '"changes"'))
    objects = {**domain.constants, **problem.objects}
    subtypes = domain.subtypes()
    changes = []
    for item in excuse["changes"]:
        atom_text = str(item.get("atom", "")) if isinstance(item, dict) else ""
        where = _position(text, path, atom_text or str(item))
        words = atom_text.strip().strip("()").lower().split()
        op = item.get("op") if isinstance(item, dict) else None
        if not words or op not in ("add", "delete"):
            raise InputFileError(f"excuse change {item!r}: expected {{\"op\": \"add\"|\"delete\", "
                                 f"\"atom\": \"(pred obj ...)\"}}", where)
        pred = domain.predicates.get(words[0])
        if pred is None:
            raise InputFileError(f"excuse change {atom_text}: unknown predicate {words[0]} "
                                 f"(expected a predicate of {domain.path})", where)
        if len(words) - 1 != pred.arity:
            raise InputFileError(f"excuse change {atom_text}: {words[0]} takes {pred.arity} argument(s), "
                                 f"got {len(words) - 1}", where)
        for obj, (_, ptype) in zip(words[1:], pred.params):
            if obj not in objects:
                raise InputFileError(f"excuse change {atom_text}: unknown object {obj} "
                                     f"(expected an object of {problem.path})", where)
            if objects[obj] not in subtypes.get(ptype, {ptype}):
                raise InputFileError(f"excuse change {atom_text}: {obj} is a {objects[obj]}, {words[0]} expects "
                                     f"a {ptype}", where)
        changes.append(Change(Atom(words[0], tuple(words[1:])), op == "add"))
    return changes


def _position(text: str, path: str, needle: str) -> Location:
    """Where ``needle`` first appears in ``text`` (line 1 if it does not)."""
    at = text.find(needle) if needle else -1
    if at < 0:
        return Location(path, 1)
    line = text.count("\n", 0, at) + 1
    return Location(path, line, at - (text.rfind("\n", 0, at) + 1) + 1)
