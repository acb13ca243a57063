"""Whether a second model of the world speaks the robot's language.

``--human``, ``--invariants-from`` and ``--fixed-from`` each read another
domain (usually the human's) and use its predicates on the robot's task: its
invariants group the task's atoms, its static predicates are held fixed, its
plans measure a demonstration.  A predicate of the same name with another
number of arguments, or an argument of an unrelated type, would silently mean
something else there, so it is refused (exit 34) before any work.
"""

from __future__ import annotations

from guided_lfd.errors import Location, MismatchError
from guided_lfd.pddl.model import Domain, Problem, type_ancestors

__all__ = ["check_model_fits", "check_human_model"]


def _related(a: str, b: str, *domains: Domain) -> bool:
    """Whether types ``a`` and ``b`` are one within the other in some of ``domains``' hierarchies.  Types no
    domain declares together are unrelated (``widget`` of the model beside ``furniture`` of the robot: the
    task's objects are of the robot's types, so the model's predicate would be true of none), unless one of
    them is ``object``, which every type is within."""
    if "object" in (a, b) or a == b:
        return True
    if a.startswith("(either") or b.startswith("(either"):  # related if some member of either is
        return any(_related(x, y, *domains) for x in _members(a) for y in _members(b))
    for domain in domains:
        if a in domain.types and b in domain.types and (
                a in type_ancestors(domain.types, b) or b in type_ancestors(domain.types, a)):
            return True
    return False


def _members(t: str) -> list[str]:
    """The types an ``(either t1 t2 ...)`` type stands for (a plain type: itself)."""
    return t[len("(either"):].rstrip(")").split() if t.startswith("(either") else [t]


def check_model_fits(robot: Domain, model: Domain, option: str) -> None:
    """Refuse (:class:`~guided_lfd.errors.MismatchError`, exit 34) a ``model`` given with ``option`` that declares
    one of ``robot``'s predicates with another arity or an argument of an unrelated type."""
    for name, pred in model.predicates.items():
        mine = robot.predicates.get(name)
        if mine is None:
            continue
        spelled = model.spellings.get(name, name)
        where = model.locate(name, ":predicates")
        if pred.arity != mine.arity:
            raise MismatchError(f"{option}: predicate {spelled} takes {pred.arity} argument(s) here and "
                                f"{mine.arity} in the robot's domain {robot.path}; expected the same arity", where)
        for k, ((_, theirs), (_, ours)) in enumerate(zip(pred.params, mine.params), start=1):
            if not _related(theirs, ours, robot, model):
                raise MismatchError(f"{option}: argument {k} of predicate {spelled} is of type {theirs} here and of "
                                    f"type {ours} in the robot's domain {robot.path}; expected the same or a related "
                                    "type", where)


def check_human_model(human: Domain, problem: Problem) -> None:
    """Refuse (exit 34) a human model written for another domain: one lacking a predicate or an object type
    the task uses (its plans could not say anything about this world), before any round or search."""

    def refuse(what: str) -> None:
        raise MismatchError(f"the human model (domain '{human.name}') is for another domain than the task's "
                            f"('{problem.domain_name}'): {what} (expected a model of the task's world)",
                            Location(human.path))

    used = {a for a in problem.init} | {lit.atom for lit in problem.goal}
    for atom in sorted(used):
        if atom.predicate == "=":
            continue
        declared = human.predicates.get(atom.predicate)
        if declared is None:
            refuse(f"it has no predicate {atom.predicate}, which the task uses in {atom}")
        elif declared.arity != len(atom.args):
            refuse(f"its predicate {atom.predicate} takes {declared.arity} argument(s), the task's {atom} "
                   f"{len(atom.args)}")
    types = set(human.types) | {"object"}
    for obj, kind in sorted(problem.objects.items()):
        if kind not in types:
            refuse(f"it has no type {kind}, the type of the task's object {obj}")


def refuse_adl(command: str, problem: Problem | None, *domains: Domain | None) -> None:
    """Refuse (exit 33) a command that does not handle ADL yet, naming the first domain or problem that uses it."""
    from guided_lfd.errors import Location, UnsupportedFeatureError

    for domain in domains:
        if domain is not None and domain.is_adl:
            where = Location(domain.path)
            break
    else:
        if problem is None or problem.goal_condition is None:
            return
        where = Location(problem.path)
    raise UnsupportedFeatureError(
        f"{command} does not handle ADL (conditional effects, quantifiers, disjunctions, derived predicates) yet; "
        "plan, validate, excuse and merge do", where)
