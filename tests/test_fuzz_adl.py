"""A fuzz target for ADL through the command line: random small ADL tasks through ``plan``, ``validate``,
``excuse``, ``learn-domain --prior`` and ``merge`` (issue #57).

Each example is a random well-formed ADL domain and problem (a few types,
predicates of arity 0-2, constants and objects; actions whose preconditions
mix ``and``, ``or``, ``not``, ``imply``, ``exists``, ``forall`` and ``=``, whose
effects hold ``when`` and ``forall``-``when``; stratified ``:derived`` rules,
recursive ones too; sometimes action costs), or, one time in five, such a task
with one fault of the kind a hand-written ADL file has (a derived head of
another arity or undeclared, a derived predicate in an effect or ``:init``,
rules that cannot be stratified, an undeclared predicate, type or variable, a
``when`` in a precondition, an unsupported requirement, a damaged token).
The files are written to a temporary folder and run through the command line
in-process (typer's CliRunner), in four targets (``plan`` then ``validate``;
``excuse`` with random options; ``learn-domain --prior`` then ``plan`` and
``merge``; ``merge`` then ``plan``):

* every command ends with an exit code of the table (docs/exit-codes.md), never
  1, never a traceback or ``internal error``, and an error is one line;
* a well-formed task is never refused as bad input (no 3x code);
* a plan ``plan`` prints validates with ``validate`` (and a random plan is
  judged valid, invalid or a plan file error);
* an excuse ``excuse`` reports makes the task solvable: its ``--excuse-problem``
  read back, the library plans it and validates the plan;
* ``learn-domain --prior`` learns the prior's emptied operators from
  trajectories walked with the lifted semantics, and ``merge`` joins the domain
  with a variant that shares names; what they write plans and validates too.

Seeded (hypothesis draws each example's seed, derandomized as the
``reproducible`` profile is; the task is made from the seed, so a failure
prints the task): 600 examples in CI (150 per target), 10,000 more under
``--slow`` (``GUIDED_LFD_ADL_FUZZ_EXAMPLES`` and
``GUIDED_LFD_ADL_FUZZ_SLOW_EXAMPLES`` set the numbers per target).  The first
runs found an action whose effect is its cost alone (written back for the
translator as a bare ``(increase ...)``: an internal error) and ``(not (= a
b))`` in a STRIPS goal (refused as unsupported); the tests at the end pin them.
"""

from __future__ import annotations

import os
import random
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import ROOT
from guided_lfd import errors

#: Examples per target (four targets): 150 in CI, 2,500 under --slow.
EXAMPLES = int(os.environ.get("GUIDED_LFD_ADL_FUZZ_EXAMPLES", "150"))
SLOW_EXAMPLES = int(os.environ.get("GUIDED_LFD_ADL_FUZZ_SLOW_EXAMPLES", "2500"))
CODES = set(errors.EXIT_CODES)
#: Codes for bad input: a well-formed task never gets one.
BAD_INPUT = {errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED, errors.EXIT_MISMATCH,
             errors.EXIT_INPUT_FILE}
LIMIT = "10"


# --- random ADL tasks ---------------------------------------------------------------------------------------

@dataclass
class Task:
    """A generated task: the domain's pieces (for the prior and the variant built from them), the problem, and
    the fault put into every text made of them (``None``: well-formed)."""

    header: str
    rules: list[str]
    actions: dict[str, tuple[str, str]]  # name -> (parameters, body)
    problem_text: str
    variant_rules: list[str]
    variant_actions: dict[str, tuple[str, str]]
    emptied: list[str]  # the prior's operators to learn
    fault: str | None = None
    damage: Callable[[str, str], tuple[str, str]] | None = None

    def texts(self, rules: list[str] | None = None, actions: dict[str, tuple[str, str]] | None = None,
              clean: bool = False) -> tuple[str, str]:
        """(domain, problem) of these rules and actions (default: the task's), the fault put in unless ``clean``."""
        acts = actions if actions is not None else self.actions
        body = "\n  ".join([*(self.rules if rules is None else rules),
                            *(f"(:action {name} :parameters ({ps}) {b})" for name, (ps, b) in acts.items())])
        domain = f"{self.header}\n  {body})\n"
        if self.damage is None or clean:
            return domain, self.problem_text
        return self.damage(domain, self.problem_text)

    def prior(self) -> tuple[str, str]:
        """The domain with the operators to learn emptied (their signatures kept)."""
        return self.texts(actions={name: (ps, ":precondition (and) :effect (and)" if name in self.emptied else b)
                                   for name, (ps, b) in self.actions.items()})

    def variant(self) -> tuple[str, str]:
        """A domain sharing the task's predicates and some action names (to merge with it)."""
        return self.texts(rules=self.variant_rules, actions=self.variant_actions)

    def describe(self) -> str:
        domain, problem = self.texts()
        return f"fault: {self.fault}\n--- domain\n{domain}--- problem\n{problem}"


class _Gen:
    """The random choices of one task, from a seed (hypothesis draws the seeds)."""

    def __init__(self, seed: int):
        self.rng = random.Random(seed)
        self.fresh = 0

    def int(self, lo: int, hi: int) -> int:
        return self.rng.randint(lo, hi)

    def pick(self, items):
        return self.rng.choice(list(items))

    def flip(self, p: float = 0.5) -> bool:
        return self.rng.random() < p

    def var(self) -> str:
        self.fresh += 1
        return f"?v{self.fresh}"


def adl_task(seed: int, faults: bool = True) -> Task:
    """A random small ADL task (see the module's docstring); with ``faults``, one in five has a fault."""
    g = _Gen(seed)
    typed = g.flip(0.8)
    types: dict[str, str | None] = {"object": None}  # type -> its parent
    if typed:
        types.update({"t0": "object", "t1": "object"})
        if g.flip():
            types["t2"] = "t0"
    kinds = [t for t in types if t != "object"] or ["object"]
    constants = {f"c{i}": g.pick(kinds) for i in range(g.int(0, 2))}
    objects = {f"o{i}": g.pick(kinds) for i in range(g.int(1, 4))}
    for t in kinds:  # mostly every type has an object, so that quantifiers range over something
        if t not in {**constants, **objects}.values() and g.flip(0.7):
            objects[f"o{len(objects)}"] = t
    arg_types = list(types) if typed else ["object"]
    basic = {f"p{i}": tuple(g.pick(arg_types) for _ in range(g.int(0, 2))) for i in range(g.int(2, 4))}
    derived = {f"d{i}": tuple(g.pick(arg_types) for _ in range(g.int(0, 2))) for i in range(g.int(0, 2))}
    signature = {**basic, **derived}
    costs = g.flip(0.15)

    def below(t: str | None, s: str) -> bool:
        while t is not None:
            if t == s:
                return True
            t = types.get(t)
        return s == "object"

    def term(scope: dict[str, str], wanted: str, ground: bool) -> str | None:
        """A variable in scope, a constant or (in a goal or :init) an object of type ``wanted``."""
        choices = [v for v, t in scope.items() if below(t, wanted)] + [c for c, t in constants.items()
                                                                        if below(t, wanted)]
        if ground:
            choices += [o for o, t in objects.items() if below(t, wanted)]
        return g.pick(choices) if choices else None

    def atom(scope: dict[str, str], preds: list[str], ground: bool) -> str | None:
        usable = [p for p in preds if all(term(scope, t, ground) is not None for t in signature[p])]
        if not usable:
            return None
        p = g.pick(usable)
        return f"({p}{''.join(' ' + term(scope, t, ground) for t in signature[p])})"

    def typed_var(v: str, t: str) -> str:
        return f"{v} - {t}" if typed else v

    def formula(depth: int, scope: dict[str, str], preds: dict[str, str], ground: bool = False,
                negative: bool = False, in_forall: bool = False) -> str:
        """A formula over ``preds`` (name -> 'any', or 'positive' for a rule's own head: used only positively
        and outside a forall, so that the rules stay stratified)."""
        kind = g.pick(["lit"] * 3 + (["and", "or", "imply", "exists", "forall", "not"] if depth else [])
                      + (["eq"] if scope or constants else []))
        if kind == "eq":
            names = list(scope) + list(constants)
            return f"(= {g.pick(names)} {g.pick(names)})"
        if kind == "lit":
            neg = g.flip(0.4)
            allowed = [p for p, how in preds.items() if how == "any" or (negative == neg and not in_forall)]
            a = atom(scope, allowed, ground)
            if a is None:
                return g.pick(["(and)", "(or)"])
            return f"(not {a})" if neg else a
        if kind == "not":
            return f"(not {formula(depth - 1, scope, preds, ground, not negative, in_forall)})"
        if kind in ("and", "or"):
            parts = [formula(depth - 1, scope, preds, ground, negative, in_forall) for _ in range(g.int(1, 3))]
            return f"({kind} {' '.join(parts)})"
        if kind == "imply":
            return (f"(imply {formula(depth - 1, scope, preds, ground, not negative, in_forall)} "
                    f"{formula(depth - 1, scope, preds, ground, negative, in_forall)})")
        v, t = g.var(), g.pick(arg_types)
        # A forall, or an exists under a negation, is a forall for the translator.
        inner = formula(depth - 1, {**scope, v: t}, preds, ground, negative,
                        in_forall or (kind == "forall") != negative)
        return f"({kind} ({typed_var(v, t)}) {inner})"

    def literal(scope: dict[str, str]) -> str | None:
        a = atom(scope, list(basic), False)
        return None if a is None else (f"(not {a})" if g.flip(0.4) else a)

    every = {p: "any" for p in signature}

    def effect(scope: dict[str, str]) -> str:
        parts = []
        for _ in range(g.int(1, 3)):
            how = g.pick(["lit", "lit", "when", "forall"])
            if how == "lit":
                part = literal(scope)
            elif how == "when":
                inner = [x for x in (literal(scope) for _ in range(g.int(1, 2))) if x]
                part = f"(when {formula(1, scope, every)} (and {' '.join(inner)}))" if inner else None
            else:
                v, t = g.var(), g.pick(kinds)
                inner_scope = {**scope, v: t}
                part = literal(inner_scope)
                if part and g.flip(0.7):
                    part = f"(when {formula(1, inner_scope, every)} {part})"
                part = f"(forall ({typed_var(v, t)}) {part})" if part else None
            if part:
                parts.append(part)
        if costs:
            parts.append(f"(increase (total-cost) {g.int(0, 3)})")
        return f"(and {' '.join(parts)})"

    def action() -> tuple[str, str]:
        scope = {g.var(): g.pick(kinds) for _ in range(g.int(0, 2))}
        pre = formula(g.int(0, 2), scope, every)
        return " ".join(typed_var(v, t) for v, t in scope.items()), f":precondition {pre} :effect {effect(scope)}"

    def rule(d: str, preds: dict[str, str]) -> str:
        head = {g.var(): t for t in derived[d]}
        return f"(:derived ({d}{''.join(' ' + typed_var(v, t) for v, t in head.items())}) {formula(2, head, preds)})"

    # Stratified rules: d_i over the basic predicates, the d_j before it in any polarity, itself positively.
    rules, layered = [], list(derived)
    for i, d in enumerate(layered):
        preds = {p: "any" for p in [*basic, *layered[:i]]}
        if g.flip(0.4):
            preds[d] = "positive"
        rules += [rule(d, preds) for _ in range(g.int(1, 2))]
    actions = {f"a{k}": action() for k in range(g.int(1, 3))}
    # The variant to merge with: some of the actions again (as they are, or another body under the name), new ones.
    variant_actions = {}
    for _ in range(g.int(1, 3)):
        name = g.pick([*actions, "b0", "b1"])
        variant_actions[name] = actions[name] if name in actions and g.flip() else action()
    variant_rules = [r for r in rules if g.flip(0.7)]
    if derived and g.flip(0.3):
        d = layered[0]
        variant_rules.append(rule(d, {p: "any" for p in basic}))
    emptied = [name for name in actions if g.flip()] or [g.pick(actions)]

    requirements = g.pick([":adl", ":adl :derived-predicates", ":strips :negative-preconditions :equality "
                           ":disjunctive-preconditions :quantified-preconditions :conditional-effects"])
    if typed and ":typing" not in requirements:
        requirements += " :typing"
    if derived and ":derived-predicates" not in requirements:
        requirements += " :derived-predicates"
    if costs:
        requirements += " :action-costs"
    declared = " ".join(f"({p}{''.join(' ' + typed_var(f'?a{i}', t) for i, t in enumerate(args))})"
                        for p, args in signature.items())
    type_decl = ("(:types " + " ".join(f"{t} - {s}" for t, s in types.items() if s) + ")") if typed else ""
    const_decl = f"(:constants {' '.join(typed_var(c, t) for c, t in constants.items())})" if constants else ""
    functions = "(:functions (total-cost) - number)" if costs else ""
    header = (f"(define (domain fz) (:requirements {requirements}) {type_decl} {const_decl} "
              f"(:predicates {declared}) {functions}")
    init = sorted({a for a in (atom({}, list(basic), True) for _ in range(g.int(0, 6))) if a})
    goal = formula(g.int(1, 2), {}, every, ground=True)
    problem = (f"(define (problem fzp) (:domain fz) (:objects {' '.join(typed_var(o, t) for o, t in objects.items())})"
               f" (:init {' '.join(init)}{' (= (total-cost) 0)' if costs else ''}) (:goal {goal})"
               f"{' (:metric minimize (total-cost))' if costs else ''})")
    task = Task(header, rules, actions, problem, variant_rules, variant_actions, emptied)
    if faults and g.flip(0.2):
        task.fault, task.damage = _fault(g, basic, derived, list(objects))
    return task


FAULTS = ["derived-head-arity", "derived-head-undeclared", "derived-in-effect", "derived-in-init",
          "negative-cycle", "forall-cycle", "undeclared-predicate", "wrong-arity", "unbound-variable",
          "undeclared-type", "when-in-precondition", "unsupported-requirement", "token"]


def _fault(g: _Gen, basic: dict, derived: dict, objects: list[str]):
    """One fault of the kind a hand-written ADL file has: its name and how it changes (domain, problem)."""
    fault = g.pick(FAULTS)
    if fault.startswith("derived-") or fault.endswith("-cycle"):
        if not derived:
            fault = "token"
        else:
            d = g.pick(derived)
            arity = len(derived[d])
            hs = "".join(f" ?h{i}" for i in range(arity))
    p0 = "(p0" + " ?unbound" * len(basic["p0"]) + ")"

    def rule(text: str):
        return lambda dom, prob: (dom.replace("(:action", f"{text}\n  (:action", 1), prob)

    def in_precondition(text: str):
        return lambda dom, prob: (dom.replace(":precondition ", f":precondition (and {text} ", 1)
                                  .replace(" :effect", ") :effect", 1), prob)

    def in_effect(text: str):
        return lambda dom, prob: (dom.replace(":effect (and", f":effect (and {text}", 1), prob)

    if fault == "derived-head-arity":
        return fault, rule(f"(:derived ({d}{hs} ?h{arity}) (and))")
    if fault == "derived-head-undeclared":
        return fault, rule("(:derived (dd) (and))")
    if fault == "derived-in-effect":
        return fault, in_effect(f"(forall ({hs}) ({d}{hs}))" if arity else f"({d})")
    if fault == "derived-in-init":
        args = "".join(f" {g.pick(objects)}" for _ in range(arity))
        return fault, lambda dom, prob: (dom, prob.replace("(:init", f"(:init ({d}{args})", 1))
    if fault == "negative-cycle":
        return fault, rule(f"(:derived ({d}{hs}) (not ({d}{hs})))")
    if fault == "forall-cycle":
        return fault, rule(f"(:derived ({d}{hs}) (forall (?f) (and ({d}{hs}) (= ?f ?f))))")
    if fault == "undeclared-predicate":
        return fault, in_precondition("(zz)")
    if fault == "wrong-arity":
        return fault, in_precondition("(p0 ?w ?w ?w)")
    if fault == "unbound-variable":
        return fault, in_effect(f"(when {p0} (and))" if basic["p0"] else "(when (= ?unbound ?unbound) (and))")
    if fault == "undeclared-type":
        return fault, in_effect("(forall (?h - nosuchtype) (and))")
    if fault == "when-in-precondition":
        return fault, in_precondition("(when (and) (and))")
    if fault == "unsupported-requirement":
        return fault, lambda dom, prob: (dom.replace("(:requirements", "(:requirements :numeric-fluents", 1), prob)
    which, how, at, to = g.pick(["domain", "problem"]), g.pick(["delete", "duplicate", "swap"]), g.int(0, 999), \
        g.int(0, 999)

    def token(dom: str, prob: str) -> tuple[str, str]:
        tokens = re.findall(r"\s+|[()]|[^\s()]+", dom if which == "domain" else prob)
        k, j = at % len(tokens), to % len(tokens)
        if how == "delete":
            del tokens[k]
        elif how == "duplicate":
            tokens.insert(k, tokens[k])
        else:
            tokens[k], tokens[j] = tokens[j], tokens[k]
        text = "".join(tokens)
        return (text, prob) if which == "domain" else (dom, text)

    return "token", token


# --- running the commands -----------------------------------------------------------------------------------

def _check(result, task: Task, command: str) -> int:
    """The invariant every command keeps; returns its exit code."""
    code = result.exit_code
    where = f"{command}: exit {code}\n{result.stderr}\n{task.describe()}"
    assert code in CODES, where
    assert code != errors.EXIT_INTERNAL, where
    assert "Traceback" not in result.stderr and "Traceback" not in result.stdout, where
    assert "internal error" not in result.stderr, where
    if code not in (0, errors.EXIT_UNSOLVABLE, errors.EXIT_NO_EXCUSE, errors.EXIT_PLAN_INVALID,
                    errors.EXIT_NO_EXCUSE_WITHIN_LIMIT):
        assert len([line for line in result.stderr.splitlines() if ": warning: " not in line]) == 1, where
    if task.fault is None:
        assert code not in BAD_INPUT, where
    return code


def _write(folder: Path, name: str, texts: tuple[str, str]) -> tuple[str, str]:
    domain, problem = folder / f"{name}-domain.pddl", folder / f"{name}-problem.pddl"
    domain.write_text(texts[0])
    problem.write_text(texts[1])
    return str(domain), str(problem)


def _plan_validates(runner, app, task: Task, domain: str, problem: str) -> int:
    """``plan``; the plan it prints validates with ``validate``. Returns plan's exit code."""
    plan_file = Path(domain).with_suffix(".plan")
    code = _check(runner.invoke(app, ["plan", domain, problem, "-q", "--time-limit", LIMIT, "-o", str(plan_file)]),
                  task, "plan")
    if code == 0:
        result = runner.invoke(app, ["validate", domain, problem, str(plan_file), "-q"])
        assert result.exit_code == 0, (f"the plan 'plan' printed does not validate: exit {result.exit_code} "
                                       f"{result.stderr}\n{plan_file.read_text()}\n{task.describe()}")
    return code


def _fuzz_settings(examples: int):
    return settings(max_examples=examples, deadline=None, derandomize=True, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                           HealthCheck.data_too_large, HealthCheck.filter_too_much])


def _walks(domain_text: str, problem_text: str, rng: random.Random) -> list[str]:
    """One or two trajectories of the (well-formed) task, walked from its initial state with the lifted semantics:
    random applicable actions, complete states of basic atoms."""
    from guided_lfd.pddl.formula import bindings_of
    from guided_lfd.pddl.model import objects_by_type
    from guided_lfd.pddl.reader import parse_task
    from guided_lfd.pddl.semantics import derived_atoms, effect_atoms, failed_conditions, strata

    domain, problem = parse_task("d.pddl", "p.pddl", domain_text=domain_text, problem_text=problem_text)
    objects = objects_by_type(domain, problem)
    layers = strata(domain)
    ground = [(schema, b) for schema in domain.actions for b in bindings_of(schema.params, objects)]
    walks = []
    for _ in range(rng.randint(1, 2)):
        state = frozenset(problem.init)
        lines = [f"(:state {' '.join(sorted(map(str, state)))})"]
        for _ in range(rng.randint(0, 4)):
            world = state | derived_atoms(domain, state, objects, layers)
            able = [(s, b) for s, b in ground if not failed_conditions(s, b, world, objects)]
            if not able:
                break
            schema, binding = rng.choice(able)
            adds, dels = effect_atoms(schema, binding, world, objects)
            state = frozenset((state - dels) | adds)
            args = "".join(f" {binding[v]}" for v, _ in schema.params)
            lines += [f"(:action ({schema.name}{args}))", f"(:state {' '.join(sorted(map(str, state)))})"]
        walks.append("(:trajectory\n  " + "\n  ".join(lines) + ")\n")
    return walks


# --- the targets: 150 examples each in CI ---------------------------------------------------------------------

def _plan_target(runner, app, tmp_path_factory, task: Task, rng: random.Random) -> None:
    folder = tmp_path_factory.mktemp("plan")
    domain, problem = _write(folder, "task", task.texts())
    code = _plan_validates(runner, app, task, domain, problem)
    # A plan of random steps: valid, invalid (12) or a plan file error (35), never anything else.
    arity = {name: ps.count("?") for name, (ps, _) in task.actions.items()}
    objects = re.findall(r"\b[oc]\d\b", task.problem_text + task.header)
    steps = []
    for _ in range(rng.randint(0, 3)):
        name = rng.choice([*arity, "nosuch"]) if rng.random() < 0.2 else rng.choice(list(arity))
        n = arity.get(name, 1) if rng.random() < 0.9 else rng.randint(0, 3)
        steps.append(f"({name}{''.join(' ' + rng.choice(objects) for _ in range(n))})")
    plan = folder / "random.plan"
    plan.write_text("\n".join(steps) + "\n")
    result = runner.invoke(app, ["validate", domain, problem, str(plan), "-q"])
    code = _check(result, task, "validate")
    if task.fault is None:
        assert code in (0, errors.EXIT_PLAN_INVALID, errors.EXIT_PLAN_FILE), (code, result.stderr, task.describe())


def _excuse_target(runner, app, tmp_path_factory, task: Task, rng: random.Random) -> None:
    from guided_lfd import plan, read_task, validate

    folder = tmp_path_factory.mktemp("excuse")
    domain, problem = _write(folder, "task", task.texts())
    excused = folder / "excused.pddl"
    # At most three changes: the baseline search's candidates grow with the atoms to the power of the size.
    args = ["excuse", domain, problem, "-q", "--time-limit", LIMIT, "--semantics",
            rng.choice(["consistent", "literal"]), "--max-size", rng.choice(["2", "3"]), "--excuse-problem",
            str(excused)]
    predicates = sorted(set(re.findall(r"\((p\d)", task.header)))
    if rng.random() < 0.2:
        args += ["--all"]
    if rng.random() < 0.2:
        args += ["--verify"]
    if rng.random() < 0.15:
        args += ["--fixed", rng.choice(predicates)]
    if rng.random() < 0.15:
        args += ["--cost", f"{rng.choice(predicates)}={rng.randint(0, 3)}"]
    if rng.random() < 0.15:
        variant, _ = _write(folder, "variant", task.variant())
        args += [rng.choice(["--invariants-from", "--fixed-from", "--human"]), variant]
    code = _check(runner.invoke(app, args), task, "excuse")
    if code != 0:
        return
    # An excuse makes the task solvable (none written: the task is solvable as it is); planned and validated by
    # the library from the excuse state that --excuse-problem wrote.
    robot, excuse_problem = read_task(domain, str(excused) if excused.exists() else problem)
    result = plan(robot, excuse_problem, time_limit=float(LIMIT))
    assert result.plan is not None, f"the excuse state is not solvable ({result.status})\n{task.describe()}"
    assert validate(robot, excuse_problem, [str(step) for step in result.plan]).valid, task.describe()


def _learn_target(runner, app, tmp_path_factory, task: Task, rng: random.Random) -> None:
    folder = tmp_path_factory.mktemp("learn")
    prior, problem = _write(folder, "prior", task.prior())
    walks = []
    for k, text in enumerate(_walks(*task.texts(clean=True), rng)):
        walk = folder / f"walk-{k}.traj"
        walk.write_text(text)
        walks.append(str(walk))
    learned = folder / "learned.pddl"
    args = ["learn-domain", "--prior", prior, *walks, "-q", "-o", str(learned),
            "--model", rng.choice(["safe", "general"])]
    if rng.random() < 0.5:
        args += ["--problem", problem]
    code = _check(runner.invoke(app, args), task, "learn-domain")
    if code == 0:  # the learned domain plans the task, and merges back into the prior
        _plan_validates(runner, app, task, str(learned), problem)
        merged = folder / "merged.pddl"
        if _check(runner.invoke(app, ["merge", prior, str(learned), "-q", "-o", str(merged)]), task, "merge") == 0:
            _plan_validates(runner, app, task, str(merged), problem)


def _merge_target(runner, app, tmp_path_factory, task: Task, rng: random.Random) -> None:
    folder = tmp_path_factory.mktemp("merge")
    domain, problem = _write(folder, "task", task.texts())
    variant, _ = _write(folder, "variant", task.variant())
    merged = folder / "merged.pddl"
    pair = [domain, variant] if rng.random() < 0.7 else [variant, domain]
    if _check(runner.invoke(app, ["merge", *pair, "-q", "-o", str(merged)]), task, "merge") == 0:
        _plan_validates(runner, app, task, str(merged), problem)


TARGETS = {"plan-validate": _plan_target, "excuse": _excuse_target, "learn-domain": _learn_target,
           "merge": _merge_target}


@pytest.mark.parametrize("target", list(TARGETS))
@_fuzz_settings(EXAMPLES)
@given(seed=st.integers(0, 2**32 - 1))
def test_adl_fuzz(runner, app, tmp_path_factory, target, seed):
    """Random ADL tasks through each command: a documented exit code, never an internal error; plans validate,
    excuses make the task solvable (see the module's docstring)."""
    TARGETS[target](runner, app, tmp_path_factory, adl_task(seed), random.Random(~seed))


@pytest.mark.slow
@pytest.mark.parametrize("target", list(TARGETS))
@_fuzz_settings(SLOW_EXAMPLES)
@given(seed=st.integers(0, 2**32 - 1))
def test_adl_fuzz_long(runner, app, tmp_path_factory, target, seed):
    """The same, 2,500 examples per target (10,000 in all) under --slow."""
    TARGETS[target](runner, app, tmp_path_factory, adl_task(seed), random.Random(~seed))


# --- what the fuzzer found ----------------------------------------------------------------------------------

FOUND = ROOT / "tests" / "data" / "adl" / "fuzz"


@pytest.mark.parametrize("domain", ["cost-alone.pddl", "cost-alone-bare.pddl", "cost-alone-strips.pddl"])
def test_an_action_whose_effect_is_its_cost_alone_is_read_planned_and_excused(runner, app, tmp_path, domain):
    """An effect that is the action's cost alone: the writer gave the translator a bare '(increase ...)', on which
    its parser fails (ADL: plan and excuse 'internal error: AssertionError'; STRIPS: excuse 34 'cannot synthesise
    invariants'), and written so in an ADL file it was 31 'AssertionError'."""
    from guided_lfd.pddl.reader import parse_domain
    from guided_lfd.pddl.writer import domain_to_pddl

    files = [str(FOUND / domain), str(FOUND / "cost-alone-problem.pddl")]
    planned = runner.invoke(app, ["plan", *files, "-q"])
    assert planned.exit_code == 0, planned.stderr
    assert planned.stdout.splitlines()[:2] == ["(make)", "; cost = 2 (general cost)"]
    excused = runner.invoke(app, ["excuse", *files, "-q", "--json"])
    assert excused.exit_code == 0, excused.stderr
    assert '"already-solvable"' in excused.stdout
    assert ":effect (and (increase (total-cost) 1))" in domain_to_pddl(parse_domain(files[0]))
    merged = tmp_path / "merged.pddl"
    assert runner.invoke(app, ["merge", files[0], files[0], "-q", "-o", str(merged)]).exit_code == 0
    assert runner.invoke(app, ["plan", str(merged), files[1], "-q"]).exit_code == 0


def test_equality_in_a_strips_goal_is_read_as_fast_downward_reads_it(runner, app, tmp_path):
    """'(not (= a b))' in the goal of a STRIPS task with :equality was 33 'equality in the goal is not supported'
    (the ADL paths read it); now the goal's formula holds it, on every path ('(not (= a a))' as literals alone
    was then an internal error: the STRIPS grounder took '=' for an atom)."""
    domain = str(FOUND / "goal-equality.pddl")
    holds = str(FOUND / "goal-equality-problem.pddl")
    planned = runner.invoke(app, ["plan", domain, holds, "-q"])
    assert planned.exit_code == 0 and planned.stdout.splitlines()[0] == "(finish b)", planned.stderr
    plan = tmp_path / "plan.txt"
    plan.write_text("(finish b)\n")
    assert runner.invoke(app, ["validate", domain, holds, str(plan), "-q"]).exit_code == 0
    assert runner.invoke(app, ["excuse", domain, holds, "-q"]).exit_code == 0
    for never in ("goal-equality-false.pddl", "goal-equality-self.pddl"):
        never = str(FOUND / never)
        assert runner.invoke(app, ["plan", domain, never, "-q"]).exit_code == errors.EXIT_UNSOLVABLE, never
        assert runner.invoke(app, ["validate", domain, never, str(plan), "-q"]).exit_code == errors.EXIT_PLAN_INVALID
        assert runner.invoke(app, ["excuse", domain, never, "-q"]).exit_code == errors.EXIT_NO_EXCUSE, never
