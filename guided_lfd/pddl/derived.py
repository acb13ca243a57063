"""Derived predicates (``:derived`` rules) as every command reads them.

Checked once, when an ADL domain or problem is read (:func:`check_domain`,
:func:`check_init`), so that ``plan``, ``excuse``, ``validate``, ``merge``
and ``learn-domain --prior`` all say the same about a malformed rule, at its
place in the file (exit 32):

* a rule's head is a predicate declared in ``:predicates``, with its arity;
* no action's effect and no atom of ``:init`` names a derived predicate (it
  follows from the basic atoms; Fast Downward's translator refuses both);
* the rules are stratified as Fast Downward's translator normalises them: a
  derived predicate used negatively in a rule, or inside a ``forall`` (which
  the translator compiles into ``(not (exists ... (not ...)))``), comes from
  an earlier stratum (:func:`strata`).  The translator itself checks its
  ground rules, for one problem; this check is the lifted one, on the domain,
  so a domain it passes is stratified for every problem.
"""

from __future__ import annotations

from typing import Iterator

from guided_lfd.errors import Location, PddlSemanticError
from guided_lfd.pddl.formula import DerivedRule, Formula, Junction, Quantified
from guided_lfd.pddl.model import Atom, Domain, Problem, reached
from guided_lfd.pddl.source import SExpr, SourceMap, Token

__all__ = ["check_domain", "check_init", "dependencies", "strata"]


def dependencies(formula: Formula, under: str = "") -> Iterator[tuple[str, str]]:
    """(predicate, how) of each atom ``formula`` uses: ``how`` is "" where it is used positively, else
    "negatively" or "inside a forall" (the translator's normal form negates it there): strict uses, whose
    predicate must come from an earlier stratum."""
    if isinstance(formula, Junction):
        for part in formula.parts:
            yield from dependencies(part, under)
    elif isinstance(formula, Quantified):
        yield from dependencies(formula.body, under or ("inside a forall" if formula.kind == "forall" else ""))
    else:
        yield formula.atom.predicate, under or ("" if formula.positive else "negatively")


def strata(domain: Domain) -> list[list[DerivedRule]]:
    """The derived rules in strata: a predicate a rule uses strictly (see :func:`dependencies`) comes from an
    earlier stratum, one it uses positively from the same or an earlier one.

    Raises :class:`PddlSemanticError` at the rule that uses a derived predicate strictly through itself (no
    stratification exists).
    """
    derived = domain.derived_predicates()
    uses = {p: set() for p in derived}  # head -> the derived predicates its rules use
    for rule in domain.axioms:
        uses[rule.predicate] |= {q for q, _ in dependencies(rule.condition) if q in derived}
    for index, rule in enumerate(domain.axioms):
        for q, how in sorted(dependencies(rule.condition)):
            if how and q in derived and rule.predicate in reached(q, uses):
                through = "" if q == rule.predicate else f", and '{q}' depends on '{rule.predicate}'"
                raise PddlSemanticError(
                    f"derived predicate '{rule.predicate}' uses '{q}' {how}{through}: the rules cannot be "
                    "stratified (expected a predicate a rule uses negatively or inside a forall not to depend on "
                    "the rule's own, as Fast Downward's translator requires)",
                    rule_head(domain, index))
    level = {p: 0 for p in derived}
    for _ in range(len(derived)):  # no strict cycle: the levels settle within as many rounds as predicates
        for rule in domain.axioms:
            for q, how in dependencies(rule.condition):
                if q in derived:
                    level[rule.predicate] = max(level[rule.predicate], level[q] + bool(how))
    out: list[list[DerivedRule]] = [[] for _ in range(max(level.values(), default=-1) + 1)]
    for rule in domain.axioms:
        out[level[rule.predicate]].append(rule)
    return [stratum for stratum in out if stratum]


def _rule_lists(src: SourceMap) -> list[SExpr]:
    return [item for item in src.define().items if isinstance(item, SExpr) and item.head() == ":derived"]


def rule_head(domain: Domain, index: int) -> Location:
    """Where the head of ``domain``'s rule number ``index`` is written (its predicate's name)."""
    rule = domain.axioms[index]
    src = domain.source
    lists = _rule_lists(src) if src is not None else []
    if len(lists) == len(domain.axioms) and len(lists[index].items) > 1:
        head = lists[index].items[1]
        tok = head.items[0] if isinstance(head, SExpr) and head.items else head
        if isinstance(tok, Token) and tok.lower == rule.predicate:
            return src.location(tok.line, tok.col)
    return domain.locate(rule.predicate, ":derived")


def check_domain(domain: Domain) -> None:
    """Refuse (exit 32, at its place) a rule whose head is not a declared predicate of its arity, an action
    whose effect names a derived predicate, and rules that cannot be stratified."""
    for index, rule in enumerate(domain.axioms):
        declared = domain.predicates.get(rule.predicate)
        if declared is None:
            raise PddlSemanticError(f"derived predicate '{rule.predicate}' is not declared (expected it in "
                                    ":predicates, as every predicate)", rule_head(domain, index))
        if declared.arity != len(rule.params):
            raise PddlSemanticError(f"derived predicate '{rule.predicate}' has {len(rule.params)} argument(s) "
                                    f"here and {declared.arity} in :predicates, expected the same arity",
                                    rule_head(domain, index))
    derived = domain.derived_predicates()
    for act in domain.actions:
        changed = [*act.add, *act.delete, *(effect.literal.atom for effect in act.effects)]
        for atom in changed:
            if atom.predicate in derived:
                raise PddlSemanticError(
                    f"action '{act.name}' changes the derived predicate '{atom.predicate}' (expected only basic "
                    "predicates in effects: a derived one follows from them)", _in_effect(domain, act.name, atom))
    strata(domain)


def _in_effect(domain: Domain, action: str, atom: Atom) -> Location:
    """Where ``atom``'s predicate is applied in the effect of ``action``."""
    src = domain.source
    node = src.action(action) if src is not None else None
    if node is not None:
        words = [item for item in node.items if isinstance(item, Token)]
        effect = next((t for t in words if t.lower == ":effect"), None)
        after = node.items[node.items.index(effect) + 1:] if effect is not None else []
        for part in after:
            for item in (part, *part.walk()) if isinstance(part, SExpr) else ():
                if isinstance(item, SExpr) and item.head() == atom.predicate:
                    tok = item.items[0]
                    return src.location(tok.line, tok.col)  # type: ignore[union-attr]
    return domain.locate(atom.predicate, ":action")


def check_init(domain: Domain, problem: Problem, src: SourceMap) -> None:
    """Refuse (exit 32, at the atom) an initial state that lists a derived predicate."""
    derived = domain.derived_predicates()
    for atom in sorted(problem.init):
        if atom.predicate in derived:
            raise PddlSemanticError(f"the initial state lists the derived predicate '{atom.predicate}' (expected "
                                    "only basic atoms: a derived one follows from them)",
                                    src.locate_head(atom.predicate, ":init"))
