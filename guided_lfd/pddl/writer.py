"""Writing :mod:`guided_lfd.pddl.model` objects back to PDDL text.

Output is deterministic (sorted where PDDL does not care about order) so that
golden-file tests and repeated runs compare byte for byte.
"""

from __future__ import annotations

from guided_lfd.pddl.evidence import evidence_lines
from guided_lfd.pddl.model import EQUALITY, TOTAL_COST, ActionSchema, Atom, Domain, Literal, Predicate, Problem


def _typed(pairs: list[tuple[str, str]] | tuple[tuple[str, str], ...], typing: bool = True) -> str:
    if not typing:
        return " ".join(name for name, _ in pairs)
    out: list[str] = []
    i = 0
    pairs = list(pairs)
    while i < len(pairs):
        j = i
        while j < len(pairs) and pairs[j][1] == pairs[i][1]:
            j += 1
        out.append(" ".join(n for n, _ in pairs[i:j]) + f" - {pairs[i][1]}")
        i = j
    return " ".join(out)


def _types_parents_first(types: dict[str, str | None]) -> list[tuple[str, str]]:
    """(type, parent) pairs with every parent declared before its children.

    Tarski rejects a parent type that is used before it is declared.
    """
    out: list[tuple[str, str]] = []
    done = {"object"}
    pending = sorted(t for t in types if t != "object")
    while pending:
        ready = [t for t in pending if (types[t] or "object") in done or (types[t] or "object") not in types]
        if not ready:  # a cycle: write the rest as they are
            ready = pending
        for t in ready:
            out.append((t, types[t] or "object"))
            done.add(t)
        pending = [t for t in pending if t not in done]
    return out


def _conj(parts: list[str]) -> str:
    if not parts:
        return "()"
    if len(parts) == 1:
        return parts[0]
    return "(and " + " ".join(parts) + ")"


def _literal(lit: Literal) -> str:
    return str(lit)


def action_to_pddl(action: ActionSchema, indent: str = "  ") -> str:
    """One ``(:action ...)`` block; ``origin`` becomes a comment above it."""
    lines: list[str] = []
    if action.origin:
        for line in action.origin.splitlines():
            lines.append(f"{indent};; {line}")
    lines += [f"{indent};; {line}" for line in evidence_lines(action)]
    lines.append(f"{indent}(:action {action.name}")
    lines.append(f"{indent}  :parameters ({_typed(action.params)})")
    if action.is_adl:
        from guided_lfd.pddl.formula import effect_text, formula_text
    if action.condition is not None:
        lines.append(f"{indent}  :precondition {formula_text(action.condition)}")
    else:
        lines.append(f"{indent}  :precondition {_conj([_literal(l) for l in action.precondition])}")
    effects = [str(a) for a in action.add] + [f"(not {a})" for a in action.delete]
    effects += [effect_text(eff) for eff in action.effects]
    if action.cost is not None:
        effects.append(f"(increase ({TOTAL_COST}) {action.cost})")
    # An empty effect is '(and)': tarski's grammar has no '()' there. A cost alone stays in '(and ...)': Fast
    # Downward's parser fails on an action whose whole effect is '(increase ...)' (an AssertionError).
    text = _conj(effects) if effects and (len(effects) > 1 or action.cost is None) else f"(and {' '.join(effects)})"
    lines.append(f"{indent}  :effect {text})")
    return "\n".join(lines)


def _adl_requirements(domain: Domain) -> set[str]:
    """The ADL requirements the domain's formulas, effects and rules need."""
    reqs: set[str] = set()
    if any(act.condition is not None for act in domain.actions) or domain.axioms:
        reqs |= {":disjunctive-preconditions", ":quantified-preconditions", ":negative-preconditions", ":equality"}
    if any(act.effects for act in domain.actions):
        reqs.add(":conditional-effects")
    if domain.axioms:
        reqs.add(":derived-predicates")
    return reqs


def domain_to_pddl(domain: Domain, header: str | None = None) -> str:
    """A complete domain file."""
    reqs = set(domain.requirements) | {":strips", ":typing"}
    if any(not l.positive for a in domain.actions for l in a.precondition if l.atom.predicate != EQUALITY):
        reqs.add(":negative-preconditions")
    if any(l.atom.predicate == EQUALITY for a in domain.actions for l in a.precondition):
        reqs.add(":equality")
    if domain.functions or any(a.cost is not None for a in domain.actions):
        reqs.add(":action-costs")
    reqs |= _adl_requirements(domain)
    order = [":strips", ":typing", ":negative-preconditions", ":equality", ":action-costs"]
    reqs_sorted = [r for r in order if r in reqs] + sorted(reqs - set(order))
    out: list[str] = []
    if header:
        out += [f";; {line}" if line else ";;" for line in header.splitlines()]
    out.append(f"(define (domain {domain.name})")
    out.append(f"  (:requirements {' '.join(reqs_sorted)})")
    types = _types_parents_first(domain.types)
    if types:
        out.append(f"  (:types {_typed(types)})")
    if domain.constants:
        out.append(f"  (:constants {_typed(sorted(domain.constants.items(), key=lambda kv: (kv[1], kv[0])))})")
    preds = []
    for pred in sorted(domain.predicates.values(), key=lambda p: p.name):
        args = _typed(pred.params)
        preds.append(f"({pred.name}{' ' + args if args else ''})")
    out.append("  (:predicates " + "\n               ".join(preds) + ")")
    functions = dict(domain.functions)
    if any(a.cost is not None for a in domain.actions):
        functions.setdefault(TOTAL_COST, Predicate(TOTAL_COST, ()))
    if functions:
        declared = []
        for fun in functions.values():
            args = _typed(fun.params)
            declared.append(f"({fun.name}{' ' + args if args else ''}) - number")
        out.append("  (:functions " + "\n              ".join(declared) + ")")
    if domain.axioms:
        from guided_lfd.pddl.formula import formula_text
    for rule in domain.axioms:
        out.append("")
        head = " ".join((rule.predicate, _typed(rule.params))).strip()
        out.append(f"  (:derived ({head})\n    {formula_text(rule.condition)})")
    for action in domain.actions:
        out.append("")
        out.append(action_to_pddl(action))
    out.append(")")
    return "\n".join(out) + "\n"


def problem_to_pddl(problem: Problem, init: frozenset[Atom] | set[Atom] | None = None, header: str | None = None) -> str:
    """A complete problem file (optionally with another initial state)."""
    state = problem.init if init is None else init
    out: list[str] = []
    if header:
        out += [f";; {line}" if line else ";;" for line in header.splitlines()]
    out.append(f"(define (problem {problem.name})")
    out.append(f"  (:domain {problem.domain_name})")
    if problem.objects:
        objs = sorted(problem.objects.items(), key=lambda kv: (kv[1], kv[0]))
        out.append(f"  (:objects {_typed(objs)})")
    facts = [str(a) for a in sorted(state)]
    facts += [f"(= {term} {value})" for term, value in sorted(problem.function_values.items())]
    if problem.metric:
        facts.append(f"(= ({TOTAL_COST}) 0)")
    out.append("  (:init " + "\n         ".join(facts) + ")")
    if problem.goal_condition is not None:
        from guided_lfd.pddl.formula import formula_text

        goal = formula_text(problem.goal_condition)
    else:  # an empty goal as '(and)': Fast Downward's parser wants a list with something in it
        goal = _conj([str(l) for l in problem.goal]) if problem.goal else "(and)"
    if problem.metric:
        out.append(f"  (:goal {goal})")
        out.append(f"  (:metric minimize ({TOTAL_COST})))")
    else:
        out.append(f"  (:goal {goal}))")
    return "\n".join(out) + "\n"
