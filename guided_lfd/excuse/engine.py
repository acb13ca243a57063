"""Finding minimal excuses: the library entry point behind ``guided-lfd excuse``.

``find_excuses`` grounds the task, builds the change space (with invariants
for the consistent semantics), runs a registered strategy, and turns every
change set found into an :class:`Excuse` with a validated robot plan from
the excuse state.  Each excuse is re-checked by :mod:`guided_lfd.excuse.check`
before it is returned.
"""

from __future__ import annotations

import gc
import math
import time
from dataclasses import dataclass, field, replace
from typing import Any

from guided_lfd.deadline import check as check_deadline
from guided_lfd.deadline import checked_time_limit, deadline_after, linger, lingering, watchdog
from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.excuse.laws import WorldLaws, derive_laws
from guided_lfd.excuse import outcome as search_outcome
from guided_lfd.excuse.lmcut import RelaxedExcuseTask
from guided_lfd.excuse.portfolio import WITHOUT_INVARIANTS
from guided_lfd.excuse.prepare import prepare
from guided_lfd.excuse.progress import ProgressCallback, ProgressMeter
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.verify import verify_excuse
from guided_lfd.excuse.space import (
    ChangeSpace, Semantics, check_cost_predicates, check_fixed, cost_predicates,
)
from guided_lfd.excuse.report import Excuse, ExcuseReport
from guided_lfd.excuse.skills import minimal_over_skills
from guided_lfd.excuse.statistics import ExcuseStatistics
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.excuse.strategies import DEFAULT_STRATEGY, STRATEGIES
from guided_lfd.excuse.outcome import Probe, SearchLimits
from guided_lfd.planning.task import GroundAction, GroundTask, bits, mask_of
from guided_lfd.planning.optimal import certified_optimal, shorten_plan
from guided_lfd.pddl.fit import check_model_fits
from guided_lfd.pddl.model import Domain, Literal, Problem
from guided_lfd.planning.validation import PlanStep, plan_steps


#: With a time limit, a search that has found no excuse when this share of its time is used pauses once for a
#: greedy search for any excuse (reported, not proven minimal, if the time runs out), for at most
#: :data:`PROBE_SHARE` of its time; the minimal-excuse search then goes on.
PROBE_AT = 0.75
PROBE_SHARE = 0.125


@dataclass
class ExcuseOptions:
    """Everything that selects which excuses count and how to search."""

    semantics: Semantics = Semantics.CONSISTENT
    strategy: str = DEFAULT_STRATEGY
    fixed: list[str] = field(default_factory=list)
    costs: list[str] = field(default_factory=list)
    all_minimal: bool = False
    max_size: int | None = None
    time_limit: float | None = None
    invariants_from: Domain | None = None
    fixed_from: Domain | None = None
    optimal_plans: bool = True
    #: With ``all_minimal``, also the excuses up to this much costlier than the minimum (landmark and symbolic strategies).
    slack: int = 0
    #: ``time.monotonic()`` when the run started (the time limit counts from
    #: it: a command line starts it before reading its files); None = now.
    started: float | None = None
    #: Re-verify the minimum by enumerating every cheaper change set (:mod:`guided_lfd.excuse.verify`).
    verify: bool = False
    #: Let the excuse change the world's structure (kinds of things, fixed graphs: see
    #: :mod:`guided_lfd.excuse.structure`), held fixed by default when no ``fixed_from`` model says what can change.
    change_structure: bool = False
    #: Let the excuse drop learned preconditions that no demonstration tested (skill excuses, see
    #: :mod:`guided_lfd.excuse.skills`); off: state changes alone.
    skill_changes: bool = True
    #: Skill excuses may drop preconditions of the user's own skills too (actions without evidence).
    relax_prior: bool = False
    #: Under the consistent semantics, keep an object that a static predicate puts in one place (``(at bot hall)``,
    #: no robot action moving it) in at most one (:func:`guided_lfd.excuse.structure.placing_predicates`).
    one_place: bool = True

    def __post_init__(self) -> None:
        from guided_lfd.errors import OptionError

        # A library caller may write semantics="literal"; the engine compares members.
        try:
            self.semantics = Semantics(self.semantics)
        except ValueError:
            raise OptionError(f"semantics {self.semantics!r}: expected one of "
                              f"{', '.join(repr(s.value) for s in Semantics)}") from None
        self.time_limit = checked_time_limit(self.time_limit, "time_limit")
        if self.max_size is not None and (isinstance(self.max_size, bool) or not isinstance(self.max_size, int)
                                          or self.max_size < 0):
            raise OptionError(f"max_size {self.max_size!r}: expected a number of changes >= 0 (or None)")
        if not isinstance(self.strategy, str):
            raise OptionError(f"strategy {self.strategy!r}: expected a strategy's name (a string)")
        if isinstance(self.slack, bool) or not isinstance(self.slack, int) or self.slack < 0:
            raise OptionError(f"slack {self.slack!r}: expected a whole cost >= 0")
        for name in ("all_minimal", "optimal_plans", "verify", "change_structure", "one_place", "skill_changes",
                     "relax_prior"):
            if not isinstance(getattr(self, name), bool):
                raise OptionError(f"{name} {getattr(self, name)!r}: expected True or False")
        started = self.started
        if started is not None and (isinstance(started, bool) or not isinstance(started, (int, float))
                                    or not math.isfinite(started)):
            raise OptionError(f"started {started!r}: expected a time.monotonic() value (or None)")
        if started is not None and started > time.monotonic():
            raise OptionError(f"started {started!r}: is in the future; expected when the run started "
                              "(a time.monotonic() value)")
        for name in ("fixed", "costs"):
            value = getattr(self, name)
            if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
                raise OptionError(f"{name} {value!r}: expected a list of strings (as --{name.rstrip('s')} takes them)")
        for name in ("invariants_from", "fixed_from"):
            if getattr(self, name) is not None and not isinstance(getattr(self, name), Domain):
                raise OptionError(f"{name}: expected a Domain (guided_lfd.read_task or parse_domain), got "
                                  f"{type(getattr(self, name)).__name__}")

    def fixed_predicates(self, domain: Domain, problem: Problem | None = None) -> list[str]:
        """``fixed`` plus the predicates no action of ``fixed_from`` changes (that ``domain`` has), and, given the
        ``problem``, the world's structure (:meth:`held_structure`)."""
        out = list(self.fixed)
        if self.fixed_from is not None:
            static = set(self.fixed_from.predicates) - self.fixed_from.fluent_predicates()
            out += sorted(p for p in static if p in domain.predicates and p not in out)
        if problem is not None:
            out += [p for p in self.held_structure(domain, problem) if p not in out]
        return out

    def held_structure(self, domain: Domain, problem: Problem) -> dict[str, str]:
        """The structural predicates held fixed by default, each with why: none with ``change_structure`` or a
        ``fixed_from`` model (it says what can change); a predicate given a ``--cost`` stays changeable."""
        if self.change_structure or self.fixed_from is not None:
            return {}
        from guided_lfd.excuse.structure import structural_predicates

        priced = cost_predicates(self.costs)
        models = [self.invariants_from] if self.invariants_from is not None else []
        return {p: why for p, why in structural_predicates(domain, problem, models).items() if p not in priced}


def check_option_names(domain: Domain, options: ExcuseOptions) -> None:
    """Reject unknown predicates in --fixed and --cost, and options the strategy lacks, before any expensive work."""
    check_fixed(options.fixed, domain)
    check_cost_predicates(options.costs, domain)
    for model, option in ((options.invariants_from, "--invariants-from"), (options.fixed_from, "--fixed-from")):
        if model is not None:
            check_model_fits(domain, model, option)
    listing = [name for name, s in STRATEGIES.items() if getattr(s, "lists_slack", False)]
    if options.slack < 0 or (options.slack and options.strategy not in listing):
        from guided_lfd.errors import OptionError

        raise OptionError(f"--slack {options.slack}: expected a cost >= 0, with the {' or '.join(listing)} "
                          "strategy (the baseline enumerates minimal excuses only)")


def unachievable_goals(task: GroundTask) -> list[Literal]:
    """Goal literals false in I that no robot action can make true."""
    adds = deletes = 0
    for act in task.actions:
        adds |= act.add
        deletes |= act.delete
        for eff in act.effects:
            adds |= eff.add
            deletes |= eff.delete
    adds |= task.derived  # a derived goal follows from basic atoms: no action adds it itself
    deletes |= task.derived
    out: list[Literal] = []
    for i in bits(task.goal_pos & ~task.init & ~adds):
        out.append(Literal(task.atoms[i]))
    for i in bits(task.goal_neg & task.init & ~deletes):
        out.append(Literal(task.atoms[i], False))
    return sorted(out)


def _changes_of(task: GroundTask, changes: int) -> list[Change]:
    out = [Change(task.atoms[i], not (task.init >> i) & 1) for i in bits(changes)]
    return sorted(out, key=lambda c: (c.atom, c.added))


#: The most a search for the robot's optimal plan may take, and the least
#: it is given; in between, as long as the run took so far.
ROBOT_PLAN_MAX_S = 10.0
ROBOT_PLAN_MIN_S = 1.0


def robot_plan_deadline(started: float) -> float:
    """When the search for the robot's optimal plans must end: as long again as the run took (1-10 s)."""
    now = time.monotonic()
    return now + min(ROBOT_PLAN_MAX_S, max(ROBOT_PLAN_MIN_S, now - started))


def _robot_plan(task: GroundTask, space: ChangeSpace, oracle: ReachabilityOracle, state: int,
                fallback: list[GroundAction], optimal: bool, deadline: float | None,
                plans_until: float) -> tuple[list[GroundAction], bool]:
    """An optimal robot plan from ``state`` if it can be had in time, else ``fallback``.

    The search's witness is shortened first; when its length meets LM-cut's
    lower bound it is optimal without a planner run (household tasks, most
    small ones).  Otherwise A* + LM-cut plans from scratch until
    ``plans_until`` (:func:`robot_plan_deadline`, one for all the run's
    excuses): the excuse is what the user waits for, and optimal plans may
    not double the wait.
    """
    task_goal = (task.goal_pos, task.goal_neg)
    fallback = shorten_plan(fallback, state, *task_goal)
    if not optimal or (deadline is not None and time.monotonic() >= deadline):
        return fallback, False
    try:
        with watchdog(deadline, "optimality check", grace=0.0):
            if certified_optimal(fallback, state, oracle.relaxed_task()):
                return fallback, True
    except SearchTimeout:
        return fallback, False
    from guided_lfd.planning import find_plan

    now = time.monotonic()
    budget = plans_until - now
    if deadline is not None:
        budget = min(budget, deadline - now)
    if budget <= 0:
        return fallback, False
    try:
        result = find_plan(task, init=state, search="astar-lmcut", time_limit_s=budget,
                           actions=space.relevant_actions)
    except SearchTimeout:
        return fallback, False
    if result.plan is None:  # cannot happen for a found excuse; keep the witness
        return fallback, False
    return result.plan, True


def find_excuses(
    domain: Domain,
    problem: Problem,
    options: ExcuseOptions | None = None,
    on_progress: ProgressCallback | None = None,
) -> ExcuseReport:
    """Find minimal excuses for the robot's task ``(domain, problem)``.

    ``options.time_limit`` bounds the whole call (counted from
    ``options.started`` when the caller's clock started earlier, e.g. before
    parsing): the searches stop cooperatively at the deadline, and a watchdog
    ends any other phase shortly after it.  A run that times out returns a
    ``timeout`` report holding the excuses completed by then, or else the
    search's proven lower bound (``statistics.lower_bound``) and the cheapest
    excuse found (``best_candidate``, landmark strategy), if any.

    ``on_progress`` gets a :class:`~guided_lfd.excuse.progress.Progress` at
    each phase and, while the search runs, a few times a second.
    """
    _check_arguments(domain, problem, options, on_progress)
    options = options or ExcuseOptions()
    if options.strategy not in STRATEGIES:
        from guided_lfd.errors import OptionError

        raise OptionError(f"unknown strategy '{options.strategy}' (expected one of: {', '.join(STRATEGIES)})")
    start = time.monotonic() if options.started is None else options.started
    check_option_names(domain, options)
    if options.skill_changes:  # without learned preconditions to drop, the state search's report as it is
        return minimal_over_skills(domain, replace(options, started=start),
                                   lambda relaxed, opts: _state_excuses(relaxed, problem, opts, on_progress))
    return _state_excuses(domain, problem, replace(options, started=start), on_progress)


def _state_excuses(domain: Domain, problem: Problem, options: ExcuseOptions,
                   on_progress: ProgressCallback | None) -> ExcuseReport:
    """The minimal excuses that change the initial state alone (``options.started`` set)."""
    start = options.started
    assert start is not None
    deadline = deadline_after(options.time_limit, start)
    meter = ProgressMeter(on_progress, start) if on_progress is not None else None
    run = _Run(domain, problem, options, meter, start, deadline)
    linger(run)  # with its task, space and oracle (see guided_lfd.deadline.linger)
    # Grounding a house creates millions of small objects and no cycles that
    # matter: the cyclic collector's full passes over them cost more than the
    # rest of set-up (measured: 35 s -> 18 s on 180k ground actions).
    collecting = gc.isenabled()
    gc.disable()
    try:
        with watchdog(deadline, "excuse search"):
            report = run.execute()
            if options.verify and report.status is ExcuseStatus.FOUND and not report.statistics.incomplete:
                run.verify_minimality(report)
            return report
    except SearchTimeout:
        return run.timed_out()
    finally:
        if collecting:
            if lingering():
                # Everything the run allocated sits in the youngest generation and
                # stays alive: the first collection after enabling would walk all
                # of it (seconds on a large task, after the time limit).  Frozen,
                # the collector never looks at it again.
                gc.freeze()
            gc.enable()


class _Run:
    """One call of :func:`find_excuses`, phase by phase; keeps what it found for a timeout report."""

    def __init__(self, domain: Domain, problem: Problem, options: ExcuseOptions, progress: ProgressMeter | None,
                 start: float, deadline: float | None) -> None:
        self.domain, self.problem, self.options = domain, problem, options
        self.progress = progress
        self.start, self.deadline = start, deadline
        self.phase = "grounding"
        self.stats = ExcuseStatistics()
        self.excuses: list[Excuse] = []
        self.space: ChangeSpace | None = None
        self.unachievable: list[Literal] = []
        self.robot_plan_cost: int | None = None
        self.candidate: Excuse | None = None  # the probe's excuse, checked
        self._laws: WorldLaws | None = None
        #: What the excuse may not change (``--fixed``, ``--fixed-from``, the world's structure), worked out once.
        self.fixed: list[str] = []
        self.candidate_weight = 0

    def _enter(self, phase: str) -> None:
        self.phase = phase
        if self.progress is not None:
            self.progress.phase(phase)
        check_deadline(self.deadline, phase)

    def report(self, status: ExcuseStatus, robot_plan: list[PlanStep] | None = None, **more: Any) -> ExcuseReport:
        """The report of the run so far (``more``: statistics fields to set)."""
        for name, value in more.items():
            setattr(self.stats, name, value)
        self.stats.time_s = round(time.monotonic() - self.start, 4)
        space = self.space
        groups = space.groups if space is not None else []
        robot_cost = self.robot_plan_cost if robot_plan is not None else None
        candidate = self.candidate if status is ExcuseStatus.TIMEOUT else None
        return ExcuseReport(status, sorted(self.excuses, key=_excuse_order), self.options.semantics,
                            self.options.strategy, self.stats, self.unachievable, groups, robot_plan,
                            robot_cost, domain=self.domain, problem=self.problem, best_candidate=candidate,
                            unit_costs=space is None or not space.costs, max_size=self.options.max_size,
                            slack=self.options.slack)

    def timed_out(self) -> ExcuseReport:
        """The report when the time limit ended the run: excuses completed so far stay."""
        self.stats.phase = self.phase
        if self.excuses:  # --all ran out of time: what was found is minimal
            self.stats.incomplete = True
            return self.report(ExcuseStatus.FOUND)
        return self.report(ExcuseStatus.TIMEOUT)

    def probe(self) -> Probe | None:
        """When and how long the search may pause for a greedy search for any excuse (with a time limit)."""
        if self.deadline is None:
            return None
        now = search_outcome.clock()
        span = max(0.0, self.deadline - now)
        return Probe(now + PROBE_AT * span, now + (PROBE_AT + PROBE_SHARE) * span, self.keep_candidate)

    def keep_candidate(self, changes: int, plan: list[GroundAction]) -> None:
        """Check the probe's excuse as every excuse is checked and keep it; its plan is shortened, not optimal."""
        space = self.space
        assert space is not None
        task = space.task
        self.candidate = self.checked_excuse(changes, shorten_plan(plan, task.init ^ changes, task.goal_pos,
                                                                   task.goal_neg), False)
        self.candidate.proven_minimal = False  # until the search's lower bound meets its weight
        self.candidate_weight = space.weight(changes)
        if self.progress is not None:
            self.progress.found(self.candidate.cost)

    def checked_excuse(self, changes: int, plan: list[GroundAction], optimal: bool) -> Excuse:
        """The excuse ``changes`` with ``plan`` from its state, after the independent checker accepted both."""
        space = self.space
        assert space is not None
        change_list = _changes_of(space.task, changes)
        verify_excuse(self.domain, self.problem, change_list, plan, self.laws(), self.fixed, self.options.costs,
                space.cost(changes))
        return Excuse(change_list, space.cost(changes), excuse_state(self.problem.init, change_list), plan_steps(plan),
                      optimal, sum(a.cost for a in plan))

    def laws(self) -> WorldLaws | None:
        """The checker's own invariants for the consistent semantics, derived once per run."""
        if self.options.semantics is not Semantics.CONSISTENT:
            return None
        if self._laws is None:
            remaining = 300.0 if self.deadline is None else max(1.0, self.deadline - time.monotonic())
            self._laws = derive_laws(self.options.invariants_from or self.domain, self.problem, remaining,
                                     self.options.one_place)
        return self._laws

    def verify_minimality(self, report: ExcuseReport) -> None:
        """``--verify``: no cheaper change set is an excuse, by enumeration with the checker's own laws and
        another planner; the statistics say how it went.  A cheaper excuse is a bug, refused as one."""
        from guided_lfd.excuse.verify import verify_minimal

        try:
            found = verify_minimal(self.domain, self.problem, report.excuses[0].cost, self.laws(), self.fixed,
                                   self.options.costs, self.options.max_size, self.deadline)
        except SearchTimeout:
            report.statistics.minimality = "timeout"
            return
        report.statistics.minimality, report.statistics.minimality_sets = found.outcome, found.sets
        if found.smaller is not None:
            raise RuntimeError("internal check failed: the cheaper change set " + " ".join(map(str, found.smaller))
                               + " is an excuse too")

    def execute(self) -> ExcuseReport:
        """Ground, build the change space, check solvability, search, and plan from each excuse."""
        options = self.options
        adl = self.domain.is_adl or self.problem.goal_condition is not None
        if adl:
            from guided_lfd.excuse.adl import adl_options

            self.options = options = adl_options(options)
        self._enter("grounding")
        held = options.held_structure(self.domain, self.problem)  # once: fixed_predicates(domain, problem) adds it
        base = options.fixed_predicates(self.domain)
        self.fixed = fixed = base + [p for p in held if p not in base]
        prepared = prepare(self.domain, self.problem, options.semantics, fixed, options.costs,
                           options.invariants_from, self.deadline, self._enter, options.one_place)
        task, space, oracle = prepared.task, prepared.space, prepared.oracle
        self.space = space
        stats = self.stats
        stats.ground_atoms, stats.ground_actions = len(task.atoms), len(task.actions)
        stats.changeable_atoms, stats.relevant_atoms = space.changeable.bit_count(), space.relevant_atoms.bit_count()
        stats.relevant_actions, stats.invariant_groups = len(space.relevant_actions), len(space.groups)
        stats.fixed_predicates = fixed
        stats.structure_held = held or None
        stats.invariants_refuted_by_goal = prepared.refuted or None
        stats.kept_in_one_place = prepared.kept_in_one_place or None
        self.unachievable = unachievable_goals(task)
        if adl:
            from guided_lfd.excuse.adl import search_adl

            return search_adl(self, space)
        # Already solvable: no excuse needed.  The compiled relaxed task and the
        # oracle are built once here and handed to the search, which reuses the
        # oracle's memory of dead states.
        self._enter("relaxed task")
        relaxed = RelaxedExcuseTask(space)
        linger(task, relaxed, oracle)
        self._enter("already solvable?")
        plan0 = None
        if relaxed.reaches_goal_unchanged(task.init):  # else unsolvable without a search
            try:
                plan0 = oracle.solve(task.init)
            except SearchTimeout:
                return self.report(ExcuseStatus.TIMEOUT, candidates=0, planner_calls=1, phase=self.phase)
        if plan0 is not None:
            self._enter("robot plan")
            plan, _ = _robot_plan(task, space, oracle, task.init, plan0, options.optimal_plans, self.deadline,
                                  robot_plan_deadline(self.start))
            verify_excuse(self.domain, self.problem, [], plan)
            self.robot_plan_cost = sum(a.cost for a in plan)
            return self.report(ExcuseStatus.ALREADY_SOLVABLE, plan_steps(plan), candidates=0, planner_calls=1)
        return self.search(task, space, oracle, relaxed)

    def search(self, task: GroundTask, space: ChangeSpace, oracle: ReachabilityOracle,
               relaxed: RelaxedExcuseTask) -> ExcuseReport:
        """Search the minimal excuses of an unsolvable task, then plan from each and check it."""
        options = self.options
        self._enter("searching")
        limits = SearchLimits(all_minimal=options.all_minimal, max_size=options.max_size, deadline=self.deadline,
                              slack=options.slack, max_solutions=search_outcome.MAX_EXCUSES + 1, probe=self.probe())
        search_start = time.monotonic()
        self.stats.setup_time_s = round(search_start - self.start, 6)
        outcome = STRATEGIES[options.strategy].search(space, limits, self.progress, oracle=oracle, relaxed=relaxed)
        self.stats.search_time_s = round(time.monotonic() - search_start, 6)
        self.stats.candidates, self.stats.planner_calls = outcome.candidates, outcome.planner_calls + 1
        self.stats.nodes_expanded, self.stats.counters = outcome.expanded, dict(outcome.extra)
        self.stats.answered_by = outcome.answered_by or options.strategy
        search_outcome.cap_excuses(outcome, self.stats)
        self.phase = "robot plan"
        plans_until = robot_plan_deadline(self.start)
        for changes in outcome.solutions:
            state = task.init ^ changes
            plan, optimal = _robot_plan(task, space, oracle, state, outcome.plans[changes], options.optimal_plans,
                                        self.deadline, plans_until)
            self.excuses.append(self.checked_excuse(changes, plan, optimal))
        status = outcome.status
        if status is ExcuseStatus.TIMEOUT:
            self.stats.phase = "searching"
            if self.excuses:
                status = ExcuseStatus.FOUND  # --all ran out of time: what was found is minimal
                self.stats.incomplete = True
            else:
                self._bound_reached(space, outcome.lower_bound)
        if status is ExcuseStatus.NONE and self.stats.structure_held:
            self._structure_in_the_way()
        if (status is ExcuseStatus.NONE and space.groups and not self.unachievable
                and outcome.answered_by != WITHOUT_INVARIANTS):  # else the literal semantics has none either
            self._invariants_in_the_way(task, space)
        return self.report(status)

    def _structure_in_the_way(self) -> None:
        """No excuse keeps the world's structure: the excuse that changes it, if there is one, goes into the
        statistics (the answer names it and ``--change-structure``)."""
        excuse = self._other_excuse(change_structure=True, verify=False)
        if excuse is not None:
            self.stats.structural_excuse = [str(c) for c in excuse.changes]

    def _other_excuse(self, **options: Any) -> Excuse | None:
        """The first excuse under these ``options`` instead of the run's, in the run's time (None: none, or no
        time left); only its changes are wanted, so no optimal plan is searched for it."""
        other = replace(self.options, all_minimal=False, optimal_plans=False, started=self.start, **options)
        try:
            return _state_excuses(self.domain, self.problem, other, None).excuse
        except SearchTimeout:
            return None

    def _bound_reached(self, space: ChangeSpace, weight: int) -> None:
        """A timed-out search: its proven lower bound as a cost; whether the probe's excuse meets it."""
        self.stats.lower_bound = space.cost_bound(weight)
        if self.candidate is not None:
            self.candidate.proven_minimal = self.candidate_weight <= weight

    def _invariants_in_the_way(self, task: GroundTask, space: ChangeSpace) -> None:
        """No excuse keeps the invariants: when the literal semantics finds one, name the invariants its excuse
        state breaks (they may hold only because a skill is missing) in the statistics."""
        excuse = self._other_excuse(semantics=Semantics.LITERAL)
        if excuse is None:
            return
        state = mask_of(task.index[atom] for atom in excuse.state if atom in task.index)
        broken = sorted({g.invariant for g in space.groups if g.need(state)})
        self.stats.invariants_in_the_way = broken or None
        self.stats.literal_excuse = [str(c) for c in excuse.changes]


def _check_arguments(domain: object, problem: object, options: object, on_progress: object) -> None:
    """A library call's arguments of the wrong kind, as the documented :class:`OptionError`."""
    from guided_lfd.errors import OptionError

    for name, value, kind in (("domain", domain, Domain), ("problem", problem, Problem)):
        if not isinstance(value, kind):
            raise OptionError(f"{name}: expected a {kind.__name__} (guided_lfd.read_task), got {type(value).__name__}")
    if options is not None and not isinstance(options, ExcuseOptions):
        raise OptionError(f"options: expected ExcuseOptions (or None), got {type(options).__name__}")
    if on_progress is not None and not callable(on_progress):
        raise OptionError(f"on_progress: expected a function of one Progress (or None), got {type(on_progress).__name__}")


def _excuse_order(e: Excuse) -> tuple:
    return (e.cost, e.size, [str(c) for c in e.changes])
