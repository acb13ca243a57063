"""Independent check of an excuse (paper, Definition 2).

Works on the lifted model and plain atom sets only, with the plan validator;
it shares no code with the grounder or the searches, so it can catch their
mistakes.  Every excuse guided-lfd prints has passed this check.
"""

from __future__ import annotations

from dataclasses import dataclass

from guided_lfd.errors import InputFileError, Location
from guided_lfd.io import read_json_document
from guided_lfd.pddl.model import Atom, Domain, Literal, Problem
from guided_lfd.validation import PlanStep, validate_plan


@dataclass(frozen=True)
class Change:
    """One atom made true (``added``) or false in the excuse state."""

    atom: Atom
    added: bool

    def __str__(self) -> str:
        return f"{'+' if self.added else '-'}{self.atom}"


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


def excuse_state(init: frozenset[Atom], changes: list[Change]) -> frozenset[Atom]:
    """I' = I Δ E."""
    state = set(init)
    for change in changes:
        if change.added:
            state.add(change.atom)
        else:
            state.discard(change.atom)
    return frozenset(state)


def _holds(lit: Literal, state: frozenset[Atom]) -> bool:
    return (lit.atom in state) == lit.positive


def check_excuse(
    domain: Domain,
    problem: Problem,
    changes: list[Change],
    plan: list[PlanStep],
    groups: list[tuple[frozenset[Atom], bool]] | None = None,
) -> list[str]:
    """Reasons why ``changes`` with ``plan`` is *not* a valid excuse (empty = valid).

    ``groups`` are (atoms, exactly_one) invariants the excuse state must keep
    (consistent semantics), checked as stated: at most one true atom, and
    exactly one where ``exactly_one`` is set.
    """
    problems: list[str] = []
    atoms = [c.atom for c in changes]
    if len(set(atoms)) != len(atoms):
        problems.append("an atom is changed twice")
    for change in changes:
        if change.added and change.atom in problem.init:
            problems.append(f"{change} adds an atom that is already true")
        if not change.added and change.atom not in problem.init:
            problems.append(f"{change} removes an atom that is already false")
        if change.atom.predicate not in domain.predicates:
            problems.append(f"{change} is not an atom of the domain")
    state = excuse_state(problem.init, changes)
    if all(_holds(lit, state) for lit in problem.goal) and changes:
        problems.append("the excuse state already satisfies the goal")
    report = validate_plan(domain, state, problem.goal, plan, problem)
    if not report.valid:
        failure = report.first_failure
        if failure is not None:
            problems.append(f"plan step {failure.index} {failure.step} is not applicable in the excuse state")
        else:
            problems.append("the plan does not reach the goal from the excuse state")
    for members, exactly_one in groups or []:
        count = len(members & state)
        if count > 1 or (exactly_one and count == 0):
            names = " ".join(str(a) for a in sorted(members))
            problems.append(f"the excuse state breaks the invariant over {names} ({count} true)")
    return problems
