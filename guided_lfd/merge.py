"""Merging demonstrated knowledge into the robot's domain (``guided-lfd merge``).

The robot's prior domain and one or more learned domains become one domain:

* types, constants and predicates are united.  The prior's type hierarchy
  is authoritative: a learned domain that only knows ``drawer - object``
  changes nothing, and one that would move a type the prior declares (so
  that the prior's actions accept other objects) is refused.  Types the
  prior does not know may be refined by a later domain.  Contradictions (two
  specific parents, a cycle, a predicate with two arities) raise
  :class:`MergeError`.
* actions equal up to a renaming (and reordering) of their parameters are
  kept once, under the first name; the later copy is reported as a duplicate.
* two learned actions with the same name, parameters and effects are one
  skill shown in more situations: it is kept once, requiring what both
  require, its evidence summed (a precondition one of them lacks was varied).
* two different actions with the same name are both kept: the later one is
  renamed (``open_drawer_2``) and the clash reported.
* every action keeps a comment saying which file (and which action there) it
  came from, so a merged domain can be traced back to the demonstrations.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field, replace

from guided_lfd.errors import Location, MergeError
from guided_lfd.pddl.formula import ConditionalEffect, substitute
from guided_lfd.pddl.evidence import EVIDENCE_HEAD
from guided_lfd.pddl.model import (ActionSchema, Atom, Domain, Evidence, Predicate, common_supertype,
                                   type_ancestors)

#: Actions with more parameters than this are compared by position only
#: (all orderings of 8 parameters would be 40320 comparisons per pair).
MAX_PERMUTED_PARAMETERS = 7


@dataclass
class MergeResult:
    """The merged domain and what the merge did, one line per decision."""

    domain: Domain
    duplicates: list[str] = field(default_factory=list)
    #: merged action name -> (the domain it came from, its name there)
    sources: dict[str, tuple[Domain, str]] = field(default_factory=dict)
    renamed: list[str] = field(default_factory=list)
    refined: list[str] = field(default_factory=list)
    #: skills without a cost effect given cost 1 in a library with action costs
    costed: list[str] = field(default_factory=list)
    #: learned skills shown again in another situation, kept once with the preconditions both require
    generalised: list[str] = field(default_factory=list)

    def locate(self, action: str) -> Location:
        """Where a merged action is written in the file it came from."""
        domain, name = self.sources[action]
        source = domain.source
        expr = source.action(name) if source is not None else None
        return Location(domain.path) if expr is None else Location(domain.path, expr.line, expr.col)

    @property
    def notes(self) -> list[str]:
        """Every decision, in the order: refinements, generalisations, duplicates, renames, costs given."""
        return [*self.refined, *self.generalised, *self.duplicates, *self.renamed, *self.costed]


def _merge_types(merged: dict[str, str | None], declared_by_prior: set[str], domain: Domain,
                 result: MergeResult) -> None:
    """Add ``domain``'s types; the prior's hierarchy is authoritative.

    A later domain may add types and may refine the parent of a type the
    prior does not declare (``drawer - object`` to ``drawer - furniture``).
    It may not move a type the prior declares: that would change which
    objects the prior's actions accept.
    """
    for t, parent in domain.types.items():
        if t == "object":
            continue
        parent = parent or "object"
        if t not in merged:
            if t in type_ancestors(merged, parent):
                raise MergeError(f"type {t} would be its own ancestor via {parent} ({domain.path}); "
                                 "expected a type hierarchy without cycles", domain.locate(t, ":types"))
            merged[t] = parent
            continue
        old = merged[t] or "object"
        if parent == old or parent in type_ancestors(merged, old):
            continue  # the same, or less specific ("some object"): nothing to add
        if t in declared_by_prior:
            raise MergeError(f"type {t} is declared under {old} by the prior and under {parent} in "
                             f"{domain.path}; expected the prior's type hierarchy", domain.locate(t, ":types"))
        if old not in type_ancestors(merged, parent):
            raise MergeError(f"type {t} is declared under {old} and under {parent} ({domain.path}); "
                             "expected one type hierarchy", domain.locate(t, ":types"))
        if t in type_ancestors(merged, parent):
            raise MergeError(f"type {t} would be its own ancestor via {parent} ({domain.path}); "
                             "expected a type hierarchy without cycles", domain.locate(t, ":types"))
        merged[t] = parent
        result.refined.append(f"type {t}: parent {old} refined to {parent} (from {domain.path})")


def _check_namespace(domains: list[Domain]) -> None:
    """A name cannot be both a type and a predicate (PDDL parsers reject the result).

    The domain that introduces the second use of the name is blamed.
    """
    first_type: dict[str, int] = {}
    first_pred: dict[str, int] = {}
    for k, domain in enumerate(domains):
        for t in domain.types:
            first_type.setdefault(t, k)
        for p in domain.predicates:
            first_pred.setdefault(p, k)
    for name in sorted(set(first_type) & set(first_pred)):
        kt, kp = first_type[name], first_pred[name]
        if kt >= kp:
            domain, what, other, section = domains[kt], "type", "predicate", ":types"
        else:
            domain, what, other, section = domains[kp], "predicate", "type", ":predicates"
        raise MergeError(f"{name} is a {what} in {domain.path} and a {other} in {domains[min(kt, kp)].path}; "
                         "expected distinct names", domain.locate(name, section))


def _merge_predicates(merged: dict[str, Predicate], types: dict[str, str | None], domain: Domain,
                      result: MergeResult) -> None:
    for name, pred in domain.predicates.items():
        if name not in merged:
            merged[name] = pred
            continue
        old = merged[name]
        if old.arity != pred.arity:
            raise MergeError(f"predicate {name} has {old.arity} argument(s) in one domain and {pred.arity} "
                             f"in {domain.path}; expected the same arity", domain.locate(name, ":predicates"))
        params = tuple((v, common_supertype(types, t, u)) for (v, t), (_, u) in zip(old.params, pred.params))
        if params != old.params:
            result.refined.append(
                f"predicate {name}: argument types widened to "
                f"({' '.join(t for _, t in params)}) to cover {domain.path}")
            merged[name] = Predicate(name, params)


def _merge_functions(domains: list[Domain], types: dict[str, str | None], predicates: dict[str, Predicate],
                     result: MergeResult) -> dict[str, Predicate]:
    """The domains' cost functions united: one arity each, argument types widened as for predicates."""
    merged: dict[str, Predicate] = {}
    for domain in domains:
        for name, fun in domain.functions.items():
            if name in predicates:
                raise MergeError(f"{name} is a function in {domain.path} and a predicate in another domain; "
                                 "expected distinct names", domain.locate(name, ":functions"))
            old = merged.get(name)
            if old is None:
                merged[name] = fun
                continue
            if old.arity != fun.arity:
                raise MergeError(f"function {name} takes {old.arity} argument(s) in one domain and {fun.arity} "
                                 f"in {domain.path}; expected the same arity", domain.locate(name, ":functions"))
            params = tuple((v, common_supertype(types, t, u)) for (v, t), (_, u) in zip(old.params, fun.params))
            if params != old.params:
                result.refined.append(f"function {name}: argument types widened to "
                                      f"({' '.join(t for _, t in params)}) to cover {domain.path}")
                merged[name] = Predicate(name, params)
    return merged


def _key(action: ActionSchema, order: tuple[int, ...]) -> tuple:
    """The action's content with its parameters renamed positionally in ``order``."""
    binding = {action.params[i][0]: f"?p{k}" for k, i in enumerate(order)}
    return (
        tuple(action.params[i][1] for i in order),
        frozenset(l.substitute(binding) for l in action.precondition),
        frozenset(a.substitute(binding) for a in action.add),
        frozenset(a.substitute(binding) for a in action.delete),
        action.cost.substitute(binding) if isinstance(action.cost, Atom) else action.cost,
        None if action.condition is None else substitute(action.condition, binding),
        frozenset(ConditionalEffect(e.variables, substitute(e.condition, binding), e.literal.substitute(binding))
                  for e in action.effects),
    )


def same_up_to_renaming(a: ActionSchema, b: ActionSchema) -> bool:
    """Whether ``b`` is ``a`` with its parameters renamed (and possibly reordered)."""
    if (len(a.params), len(a.precondition), len(a.add), len(a.delete), len(a.effects), a.condition is None) != (
            len(b.params), len(b.precondition), len(b.add), len(b.delete), len(b.effects), b.condition is None):
        return False
    if sorted(t for _, t in a.params) != sorted(t for _, t in b.params):
        return False
    target = _key(a, tuple(range(len(a.params))))
    n = len(b.params)
    orders = itertools.permutations(range(n)) if n <= MAX_PERMUTED_PARAMETERS else [tuple(range(n))]
    return any(_key(b, order) == target for order in orders)


def _comments_above(domain: Domain, name: str) -> list[str]:
    """The comment lines written right above ``(:action name`` in the domain file."""
    source = domain.source
    expr = source.action(name) if source is not None else None
    if expr is None:
        return []
    lines = source.text.splitlines()[: expr.line - 1]
    out: list[str] = []
    for line in reversed(lines):
        stripped = line.strip()
        if not stripped.startswith(";"):
            break
        out.append(stripped.lstrip(";").strip())
    notes = [c for c in reversed(out) if c]
    # The evidence comment is the action's own (the writer prints it again from its evidence), not an origin.
    heads = [i for i, c in enumerate(notes) if c.startswith(EVIDENCE_HEAD)]
    return notes[:heads[0]] if heads else notes


def _origin(action: ActionSchema, domain: Domain) -> str:
    where = f"from {domain.path} (action {action.name})"
    notes = ([action.origin] if action.origin else []) + _comments_above(domain, action.name)
    return where + "".join(f"\n  {n}" for n in notes)


def _positional(kept: ActionSchema, action: ActionSchema) -> dict[str, str] | None:
    """``action``'s parameters renamed to ``kept``'s: by position if their types agree; else, when one's
    parameters are the other's with some left out (a static relation's object one learning did not need), by
    name; None when neither fits."""
    if [t for _, t in kept.params] == [t for _, t in action.params]:
        return {v: w for (v, _), (w, _) in zip(action.params, kept.params)}
    small, large = sorted((set(kept.params), set(action.params)), key=len)
    return {v: v for v, _ in action.params} if small < large else None


def _shown_again(kept: ActionSchema, action: ActionSchema) -> bool:
    """Whether two learned STRIPS actions are one skill shown in more situations: both with evidence, the same
    parameters (by position) and the same effects; only their preconditions differ."""
    if not kept.evidence or not action.evidence or kept.is_adl or action.is_adl or kept.cost != action.cost:
        return False
    binding = _positional(kept, action)
    return (binding is not None and {a.substitute(binding) for a in action.add} == set(kept.add)
            and {a.substitute(binding) for a in action.delete} == set(kept.delete))


def _same_evidence(kept: ActionSchema, action: ActionSchema) -> bool:
    """Whether two learnings record the same evidence, literal for literal (up to the parameters' names)."""
    binding = _positional(kept, action)
    return binding is not None and sorted(str(e) for e in kept.evidence) == sorted(
        str(e.substitute(binding)) for e in action.evidence)


def generalise(kept: ActionSchema, action: ActionSchema) -> ActionSchema:
    """One learned skill from two of its learnings (:func:`_shown_again`): the preconditions both require, each
    condition's evidence summed (a positive condition one learning lacks was false there: the learners look at
    every atom over the parameters), the teacher's answers kept."""
    binding = _positional(kept, action)
    assert binding is not None
    other = {e.literal.substitute(binding): e for e in action.evidence}
    mine = {e.literal: e for e in kept.evidence}
    n_kept = max(e.demonstrations for e in kept.evidence)
    n_other = max(e.demonstrations for e in action.evidence)
    pre = {l.substitute(binding) for l in action.precondition}
    evidence = []
    for lit in dict.fromkeys([*mine, *other]):
        a, b = mine.get(lit), other.get(lit)
        if (a is None or b is None) and not lit.positive:
            continue  # a learner that did not record a negative condition may not have looked for one: no claim
        confirmed = bool(a and a.confirmed) or bool(b and b.confirmed)
        evidence.append(Evidence(lit, (a.shown if a else 0) + (b.shown if b else 0), n_kept + n_other, confirmed))
    kept_pre = tuple(l for l in kept.precondition if l in pre)
    # A parameter only a dropped precondition named (the other room of a door) is no longer the skill's.
    used = {x for l in kept_pre for x in l.atom.args} | {x for a in (*kept.add, *kept.delete) for x in a.args}
    params = tuple((v, t) for v, t in kept.params if v in used)
    evidence = [e for e in evidence if (e.literal in kept_pre or e.varied)
                and all(x in dict(params) for x in e.literal.atom.args if x.startswith("?"))]
    return replace(kept, params=params, precondition=kept_pre, evidence=tuple(evidence))


def merge_domains(domains: list[Domain], name: str | None = None) -> MergeResult:
    """Merge ``domains`` (the prior first) into one; see the module docstring for the rules."""
    if not domains:
        raise ValueError("merge_domains needs at least one domain")
    result = MergeResult(domains[0])
    requirements: dict[str, None] = {}
    types: dict[str, str | None] = {}
    spellings: dict[str, str] = {}
    prior_types = {t for t in domains[0].types if t != "object"}
    for domain in domains:
        requirements.update(dict.fromkeys(domain.requirements))
        _merge_types(types, prior_types, domain, result)
        for spelled_lower, spelled in domain.spellings.items():
            spellings.setdefault(spelled_lower, spelled)
    _check_namespace(domains)
    constants: dict[str, str] = {}
    predicates: dict[str, Predicate] = {}
    for domain in domains:
        _merge_constants(constants, types, domain)
        _merge_predicates(predicates, types, domain, result)
    actions = _merge_actions(domains, result)
    functions = _merge_functions(domains, types, predicates, result)
    result.domain = Domain(
        name=name or domains[0].name,
        requirements=tuple(requirements),
        types=types,
        constants=constants,
        predicates=predicates,
        actions=actions,
        path="<merged>",
        spellings=spellings,
        functions=functions,
        # An object one domain's actions use undeclared stays so, unless another declares it.
        implicit_constants=tuple(dict.fromkeys(
            c for d in domains for c in d.implicit_constants if c not in constants)),
        # Derived predicates' rules, each once (two rules for one predicate: it holds where either does).
        axioms=tuple(dict.fromkeys(rule for d in domains for rule in d.axioms)),
    )
    return result


def _merge_constants(merged: dict[str, str], types: dict[str, str | None], domain: Domain) -> None:
    """Add ``domain``'s constants; one declared twice keeps the more specific of two related types."""
    for const, t in domain.constants.items():
        if const not in merged:
            merged[const] = t
        elif merged[const] != t:
            if merged[const] in type_ancestors(types, t):
                merged[const] = t
            elif t not in type_ancestors(types, merged[const]):
                raise MergeError(f"constant {const} is of type {merged[const]} and of type {t} "
                                 f"({domain.path}); expected one type", domain.locate(const, ":constants"))


def _merge_actions(domains: list[Domain], result: MergeResult) -> list[ActionSchema]:
    """Every domain's actions: equal ones (up to renaming) once, name clashes renamed, origins kept."""
    actions: list[ActionSchema] = []
    taken: set[str] = set()
    costed = any(domain.functions for domain in domains)
    for domain in domains:
        for action in domain.actions:
            shown = next((kept for kept in actions if kept.name == action.name and _shown_again(kept, action)), None)
            if shown is not None and same_up_to_renaming(shown, action) and _same_evidence(shown, action):
                shown = None  # the same learning twice (a domain merged with itself): a duplicate, not more evidence
            if shown is not None:
                result.generalised.append(f"{action.name} ({domain.path}) is {shown.name} shown in another "
                                          "situation: kept once, requiring what both require")
                generalised = generalise(shown, action)
                actions[actions.index(shown)] = replace(
                    generalised, origin=f"{shown.origin}\nalso {_origin(action, domain)}")
                continue
            twin = next((kept for kept in actions if same_up_to_renaming(kept, action)), None)
            if twin is not None:
                result.duplicates.append(
                    f"{action.name} ({domain.path}) equals {twin.name} up to parameter renaming: kept once")
                extra = _origin(action, domain)
                actions[actions.index(twin)] = replace(twin, origin=f"{twin.origin}\nalso {extra}")
                continue
            new_name, k = action.name, 1
            while new_name in taken:
                k += 1
                new_name = f"{action.name}_{k}"
            if new_name != action.name:
                result.renamed.append(
                    f"{action.name} ({domain.path}) differs from the {action.name} already merged: "
                    f"renamed to {new_name}")
            taken.add(new_name)
            result.sources[new_name] = (domain, action.name)
            cost = action.cost
            if cost is None and costed and not domain.functions:
                # A skill from a domain without costs joins a library with them: under the
                # metric it would be free; it costs 1, as it did where it came from.
                cost = 1
                result.costed.append(f"{new_name} ({domain.path}) has no action cost: it costs 1")
            actions.append(replace(action, name=new_name, origin=_origin(action, domain), cost=cost))
    return actions

