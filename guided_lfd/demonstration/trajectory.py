"""PDDL trajectory files: the states a robot passed through and the actions between them.

The format of the IPC learning track and of AMLGym::

    (:trajectory
      (:state (clear b2) (handempty) (on b2 b1) (ontable b1))
      (:action (unstack b2 b1))
      (:state (clear b1) (holding b2) (ontable b1))
      ...)

Every state is complete (closed world: what it does not list is false), and
states and actions alternate, starting and ending with a state.  The file is
read through the project's s-expression source map (which knows every
token's line and column), against a prior domain that declares the
predicates and the operators' signatures; what does not fit is a one-line
error naming file:line:col, as for PDDL files.  Objects get their types from
the positions they fill (an operator's parameter, a predicate's argument: the
narrowest type asked of them, as SAM infers them) or from a problem file.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from guided_lfd.demonstration.action_model import Observation
from guided_lfd.errors import Location, PddlSemanticError, PddlSyntaxError
from guided_lfd.pddl.model import Atom, Domain, type_ancestors
from guided_lfd.pddl.source import SExpr, SourceMap, Token, check_ascii

__all__ = ["Trajectory", "is_trajectory", "read_trajectory", "object_types", "learn_from_trajectories"]


@dataclass(frozen=True)
class Trajectory:
    """One trajectory: its states, and each step as an :class:`Observation`."""

    source: str
    states: tuple[frozenset[Atom], ...]
    steps: tuple[Observation, ...]
    #: Every object named, with the type its uses imply (or the problem's).
    objects: dict[str, str]
    #: Where each object is used as that type (its first such use), for messages.
    where: dict[str, Location] = field(default_factory=dict, compare=False)


def is_trajectory(text: str) -> bool:
    """Whether ``text`` is a PDDL trajectory rather than a JSON document (told apart by content)."""
    for line in text.splitlines():
        stripped = line.strip().lstrip("\ufeff")
        if not stripped or stripped.startswith(";"):
            continue
        return stripped.startswith("(")
    return False


def _words(node: SExpr, what: str, src: SourceMap) -> list[Token]:
    """The tokens of a flat list ``(name arg ...)``; a nested list or an empty one is an error."""
    if not node.items:
        raise PddlSyntaxError(f"empty list, expected {what}", src.location(node.line, node.col))
    for item in node.items:
        if isinstance(item, SExpr):
            raise PddlSyntaxError(f"nested list in {what}, expected names only", src.location(item.line, item.col))
    words = [item for item in node.items if isinstance(item, Token)]
    for tok in words[1:]:
        if tok.text.startswith(("?", ":")):
            kind = "variable" if tok.text.startswith("?") else "keyword"
            raise PddlSyntaxError(f"{kind} '{tok.text}' in {what}, expected an object name",
                                  src.location(tok.line, tok.col))
    return words


def _state(node: SExpr, src: SourceMap, prior: Domain, uses: dict[str, list[tuple[str, Token]]]) -> frozenset[Atom]:
    atoms: set[Atom] = set()
    for item in node.items[1:]:
        if isinstance(item, Token):
            raise PddlSyntaxError(f"'{item.text}' in a state, expected an atom '(predicate object ...)'",
                                  src.location(item.line, item.col))
        if item.head() == "not":
            raise PddlSyntaxError("'not' in a state, expected only the atoms that are true (closed world)",
                                  src.location(item.items[0].line, item.items[0].col))
        words = _words(item, "an atom", src)
        name = words[0].lower
        pred = prior.predicates.get(name)
        if pred is None:
            raise PddlSemanticError(f"predicate '{words[0].text}' is not declared in {prior.path}",
                                    src.location(words[0].line, words[0].col))
        args = [w.lower for w in words[1:]]
        if len(args) != pred.arity:
            raise PddlSemanticError(f"'{name}' takes {pred.arity} argument(s) in {prior.path}, here {len(args)}",
                                    src.location(words[0].line, words[0].col))
        for (_, t), tok in zip(pred.params, words[1:]):
            uses.setdefault(tok.lower, []).append((t, tok))
        atoms.add(Atom(name, tuple(args)))
    return frozenset(atoms)


def _action(node: SExpr, src: SourceMap, prior: Domain,
            uses: dict[str, list[tuple[str, Token]]]) -> tuple[str, tuple[str, ...], Location]:
    body = node.items[1:]
    if len(body) != 1 or not isinstance(body[0], SExpr):
        raise PddlSyntaxError("expected one ground action '(:action (operator object ...))'",
                              src.location(node.line, node.col))
    words = _words(body[0], "an action", src)
    name = words[0].lower
    try:
        schema = prior.action(name)
    except KeyError:
        raise PddlSemanticError(f"operator '{words[0].text}' is not declared in {prior.path}",
                                src.location(words[0].line, words[0].col)) from None
    args = tuple(w.lower for w in words[1:])
    if len(args) != len(schema.params):
        raise PddlSemanticError(f"'{name}' takes {len(schema.params)} argument(s) in {prior.path}, here {len(args)}",
                                src.location(words[0].line, words[0].col))
    for (_, t), tok in zip(schema.params, words[1:]):
        uses.setdefault(tok.lower, []).append((t, tok))
    return name, args, src.location(words[0].line, words[0].col)


def object_types(uses: dict[str, list[tuple[str, Token]]], prior: Domain, src: SourceMap) -> dict[str, str]:
    """Each object's type: the narrowest type its uses ask for; two uses no one type satisfies is an error."""
    types: dict[str, str] = {}
    for obj, seen in uses.items():
        best = "object"
        for t, tok in seen:
            if t.startswith("(either") or t == best:
                continue
            if best in type_ancestors(prior.types, t):
                best = t  # narrower
            elif t not in type_ancestors(prior.types, best):
                raise PddlSemanticError(f"object '{tok.text}' is used as a {best} and here as a {t}, "
                                        "expected one type", src.location(tok.line, tok.col))
        types[obj] = best
    return types


def read_trajectory(path: str, text: str, prior: Domain, objects: dict[str, str] | None = None) -> Trajectory:
    """The trajectory in ``text`` (read from ``path``), checked against ``prior``'s predicates and operators.

    ``objects``: the objects' types from a problem file, if given (an object it does not declare is an error).
    """
    check_ascii(path, text)  # as the PDDL files: their names are the prior's
    src = SourceMap(path, text, definition="(:trajectory ...)")
    root = src.roots[0]
    if root.head() != ":trajectory":
        raise PddlSyntaxError("expected '(:trajectory (:state ...) (:action ...) ...)'", src.location(root.line, root.col))
    uses: dict[str, list[tuple[str, Token]]] = {}
    states: list[frozenset[Atom]] = []
    actions: list[tuple[str, tuple[str, ...], Location]] = []
    for item in root.items[1:]:
        if not isinstance(item, SExpr):
            raise PddlSyntaxError(f"'{item.text}' in a trajectory, expected '(:state ...)' or '(:action ...)'",
                                  src.location(item.line, item.col))
        head = item.head()
        expected = ":state" if len(states) == len(actions) else ":action"
        if head not in (":state", ":action"):
            raise PddlSyntaxError(f"'{head or '('}' in a trajectory, expected '({expected} ...)'",
                                  src.location(item.line, item.col))
        if head != expected:
            what = "two actions without a state between them" if head == ":action" and states else (
                "an action before the first state" if head == ":action" else "two states without an action between them")
            raise PddlSyntaxError(f"{what}, expected '({expected} ...)'", src.location(item.line, item.col))
        if head == ":state":
            states.append(_state(item, src, prior, uses))
        else:
            actions.append(_action(item, src, prior, uses))
    if not states:
        raise PddlSyntaxError("a trajectory without states, expected '(:state ...)'", src.location(root.line, root.col))
    if len(actions) == len(states):
        raise PddlSyntaxError("the trajectory ends with an action, expected the state after it '(:state ...)'",
                              actions[-1][2])
    types = object_types(uses, prior, src)
    if objects is not None:
        for obj, seen in uses.items():
            if obj not in objects and obj not in prior.constants:
                tok = seen[0][1]
                raise PddlSemanticError(f"object '{tok.text}' is not declared in the problem",
                                        src.location(tok.line, tok.col))
        types = {o: objects.get(o) or prior.constants[o] for o in uses}
    types = {o: prior.constants.get(o, t) for o, t in types.items()}
    for obj, seen in uses.items():  # a declared type (the problem's, a constant's) must fit every use
        for t, tok in seen:
            if not t.startswith("(either") and t not in type_ancestors(prior.types, types[obj]):
                raise PddlSemanticError(f"object '{tok.text}' is a {types[obj]}, used here as a {t}; expected "
                                        "an object of that type", src.location(tok.line, tok.col))
    steps = tuple(Observation(name, args, states[i], states[i + 1], str(where))
                  for i, (name, args, where) in enumerate(actions))
    where = {}
    for obj, seen in uses.items():
        tok = next((tok for t, tok in seen if t == types[obj]), seen[0][1])
        where[obj] = src.location(tok.line, tok.col)
    return Trajectory(path, tuple(states), steps, types, where)


def learn_from_trajectories(prior: Domain, trajectories: list[Trajectory], model: str = "safe") -> Domain:
    """``prior`` with its empty-bodied operators learned from ``trajectories`` (see
    :func:`guided_lfd.demonstration.action_model.learn_operators`); notes for the user in ``warnings``."""
    from guided_lfd.demonstration.action_model import learn_operators

    objects: dict[str, str] = {}
    origin: dict[str, Location] = {}  # where each object's type so far was asked for
    for trajectory in trajectories:
        for obj, t in trajectory.objects.items():
            here = trajectory.where.get(obj, Location(trajectory.source))
            known = objects.setdefault(obj, t)
            origin.setdefault(obj, here)
            if t in type_ancestors(prior.types, known):
                continue  # the earlier use asked for as much or more
            if known not in type_ancestors(prior.types, t):
                raise PddlSemanticError(f"object '{obj}' is a {t} here and a {known} in an earlier trajectory "
                                        f"({origin[obj]}); expected one type", here)
            objects[obj], origin[obj] = t, here  # this trajectory's uses are narrower
    steps = [step for t in trajectories for step in t.steps]
    states = [state for t in trajectories for state in t.states]
    domain, notes = learn_operators(prior, steps, objects, model, states)
    where = ", ".join(t.source for t in trajectories)
    return replace(domain, warnings=tuple(f"{where}: warning: {note}" for note in notes))
