"""Learning a PDDL domain from demonstration segments (paper, section III-D-1).

Segments and trajectories share the learner core's rules for effects and
preconditions (:mod:`guided_lfd.demonstration.action_model`); what is
particular to segments is below.

Every segment that changes something (the environment or what the hand
holds) is a demonstrated action:

* its name comes from the activity and the types of the objects it handles
  (``take_item``, ``put_item_drawer``, ``open_drawer``);
* preconditions follow the *nodes of interest* principle (Zanchettin 2023):
  every fluent true before the segment that mentions an object the hand
  interacts with (the handled object, the target, what it holds, and every
  object whose fluents change), changed or not (``clear`` of the drawer),
  plus the hand's state (``in_hand``/``hand_free``, or the robot's own hand
  facts, see :mod:`guided_lfd.demonstration.vocabulary`), and fluents about
  objects a static relation ties to those (the cupboard's open door, by
  ``door_of``) where a fluent about them that varies holds, and every static
  relation among two or more of those objects, the other objects it needs
  becoming parameters (the door's two rooms: never more general than shown);
* effects are the changes over the segment to fluents of the objects the
  hand handles, and to the hand's state; what the skill makes true must have
  been false before it (a negative precondition, as action-model learners do);
* a Put (or Stack) and the Release that ends it are one skill;
* objects are lifted to typed parameters; repeated demonstrations of a skill
  (same activity, equal lifted effects) are generalised by intersecting their
  preconditions, and a demonstration whose effects disagree with the others'
  is reported and left out, see :mod:`guided_lfd.demonstration.generalise`;
* a negative precondition ``(not p)`` is dropped when a positive one ``q``
  implies it through a mutex proven by invariant synthesis (the plate in the
  hand is in no drawer), see :mod:`guided_lfd.demonstration.mutex`;
* positive preconditions holding implies (the held block is ``clear``) are
  dropped, and a grasp affordance (``graspable``) is kept only on the object
  the skill grasps, see :mod:`guided_lfd.demonstration.implied`;
* with a human model, a skill whose effects are a human action's is named
  after it, parameters in its order (:mod:`guided_lfd.demonstration.naming`);
  with ``skip_known``, a demonstrated step one of the robot's own actions
  makes (same changes) teaches nothing and is not learned again.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from guided_lfd.demonstration.action_model import changes, facts_about, static_relations
from guided_lfd.demonstration.generalise import generalise
from guided_lfd.demonstration.implied import drop_implied_preconditions
from guided_lfd.demonstration.mutex import drop_implied_negative_preconditions, proven_invariants
from guided_lfd.demonstration.vocabulary import KITCHEN, HandVocabulary, bind_arms, infer_vocabulary
from guided_lfd.errors import Location, MergeError, TraceError
from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Literal, Predicate, common_supertype

#: Activities that are never planning actions.
SKIPPED = ("Idle",)


@dataclass(frozen=True)
class DemonstratedAction:
    """A ground action read off one segment."""

    name: str
    objects: tuple[str, ...]
    precondition: frozenset[Literal]
    add: frozenset[Atom]
    delete: frozenset[Atom]
    source: str
    start: float = 0.0  # the segment's time span in its trace (s)
    end: float = 0.0
    state: frozenset[Atom] = frozenset()  # the world just before it, the acting hand's facts included


def document_vocabulary(document: dict, *domains: Domain | None, source: str = "segments") -> HandVocabulary:
    """The hand facts of a segments document: as its state file declared them, else read off the first of
    ``domains`` that shows them (the robot's, then the human's), else the kitchens' ``in_hand``/``hand_free``.
    A domain whose grasping actions are ambiguous, or arms the trace's hands cannot be tied to, is a TraceError."""
    declared = document.get("vocabulary")
    try:
        found = infer_vocabulary(*domains)
    except ValueError as exc:
        if declared is None:
            raise TraceError(str(exc), Location(source)) from None
        found = None  # the demonstration says which
    if declared is not None:
        vocabulary = HandVocabulary.from_dict(declared, f"the vocabulary of {source}")
        _check_declared(vocabulary, found, document.get("objects", {}), source)
        return vocabulary
    try:
        return KITCHEN if found is None else bind_arms(found, document.get("objects", {}))
    except ValueError as exc:
        raise TraceError(str(exc), Location(source)) from None


def _check_declared(declared: HandVocabulary, found: HandVocabulary | None, objects: dict[str, str],
                    source: str) -> None:
    """A declared binding must be the robot's own where its grasping actions show it (``found``): the same
    predicates, arms of the robot's arm type.  TraceError otherwise."""
    if found is None:
        return
    if (declared.held, declared.free) != (found.held, found.free) or declared.by_arm != found.by_arm:
        raise TraceError(f"the demonstration declares the hand facts {declared.describe()}, but {found.origin} "
                         f"use held={found.held}, free={found.free}; expected the robot's own", Location(source))
    odd = [arm for _, arm in declared.hands if found.arm_type and objects.get(arm) != found.arm_type]
    if odd:
        raise TraceError(f"the demonstration declares {odd[0]} ({objects.get(odd[0], 'undeclared')}) an arm, but "
                         f"the robot's arms are of type {found.arm_type}; expected one of its arms", Location(source))


def skill_segments(segments: list[dict]) -> list[dict]:
    """Segments as skills: a Put or Stack and the Release that ends it are one skill.

    Putting something somewhere includes letting go of it; the Release only
    shows when the hand opens.  Idle segments are dropped.
    """
    out: list[dict] = []
    last: dict[str, dict] = {}
    for seg in segments:
        if seg["activity"] in SKIPPED:
            continue
        prev = last.get(seg["hand"])
        if seg["activity"] == "Release" and prev is not None and prev["activity"] in ("Put", "Stack"):
            # The skill's changes are the Put's and the Release's own, not
            # what the other hand changed in between.
            own_add = set(seg["after"]) - set(seg["before"])
            own_del = set(seg["before"]) - set(seg["after"])
            after = sorted((set(prev["after"]) - own_del) | own_add)
            merged = dict(prev, end=seg["end"], after=after, held_after=seg.get("held_after", ""))
            out[out.index(prev)] = merged
            last[seg["hand"]] = merged
            continue
        out.append(seg)
        last[seg["hand"]] = seg
    return out


def static_predicates(documents: list[tuple[str, dict]],
                      vocabularies: dict[str, HandVocabulary] | None = None) -> set[str]:
    """Predicates whose facts are the same in every state each document shows (``door_of``, ``graspable``);
    ``vocabularies``: each source's hand facts (default: the kitchens'), never static."""
    seen: set[str] = set()
    changed: set[str] = set()
    for source, doc in documents:
        hand = (vocabularies or {}).get(source, KITCHEN).predicates
        states = [doc.get("initial", [])] + [s[k] for s in doc.get("segments", []) for k in ("before", "after")]
        parsed = [{a for a in (_atom(x, source) for x in fluents) if a.predicate not in hand}
                  for fluents in states]
        first = parsed[0]
        for state in parsed:
            seen |= {a.predicate for a in state}
            changed |= {a.predicate for a in state ^ first}
    return seen - changed


def _tied(before: set[Atom], roles: set[str], interest: set[str], static: set[str]) -> set[str]:
    """Objects a static relation ties to what the hand acts on (``roles``: the doors of the cupboard the mug
    goes into), kept only where a fact about them that varies holds (the door is open): a relation alone is
    no evidence the skill needs that object.  Not through objects the action only changes (the table a
    plate leaves is not a way to the counter beside it)."""
    tied = {x for a in before if a.predicate in static and len(a.args) >= 2 and set(a.args) & roles
            for x in a.args} - interest
    return {x for x in tied if any(x in a.args and a.predicate not in static and set(a.args) <= interest | {x}
                                   for a in before)}


def ground_actions(document: dict, source: str = "segments", static: set[str] | None = None,
                   vocabulary: HandVocabulary | None = None) -> list[DemonstratedAction]:
    """The demonstrated actions of one ``guided-lfd/segments`` document (``static``: the predicates that never
    change, by default in this document; ``vocabulary``: the hand facts, by default the document's own or the
    kitchens')."""
    types: dict[str, str] = document.get("objects", {})
    vocabulary = vocabulary or document_vocabulary(document, source=source)
    hand = vocabulary.predicates
    static = static_predicates([(source, document)], {source: vocabulary}) if static is None else static
    out: list[DemonstratedAction] = []
    skills = skill_segments(document.get("segments", []))
    acting = _Acting(skills)
    for seg in skills:
        # The hand's fluents come from the trace, never from the environment state.
        before = {a for a in (_atom(x, source) for x in seg["before"]) if a.predicate not in hand}
        after = {a for a in (_atom(x, source) for x in seg["after"]) if a.predicate not in hand}
        if vocabulary.by_arm and vocabulary.arm(seg["hand"]) is None and (seg.get("held_before") or seg.get("held_after")):
            raise TraceError(f"segment {seg['index']}: the {seg['hand']} hand holds {seg.get('held_before') or seg.get('held_after')}, "
                             f"but the vocabulary names no arm for it (only {vocabulary.describe()}); expected a "
                             f"vocabulary({seg['hand']}=ARM) row", Location(source))
        hand_before = vocabulary.fluents(seg["hand"], seg.get("held_before", ""))
        hand_after = vocabulary.fluents(seg["hand"], seg.get("held_after", ""))
        roles = [o for o in (seg.get("object", ""), seg.get("target", "")) if o]
        handled = set(roles) | {o for o in (seg.get("held_before", ""), seg.get("held_after", "")) if o}
        # Only changes to what the hand handles, or to objects a changed fluent
        # links to it (the drawer the chair stops blocking), are its effects:
        # the other hand may change something at the same time.
        changed = (after - before) | (before - after)
        linked = handled | {x for a in changed if set(a.args) & handled for x in a.args}
        if not acting.overlaps(seg):
            # One hand at work: every change the segmenter gave it is its own (walking from the hall to the
            # kitchen: the hand works on the hall, the walker arrives in the kitchen).
            linked |= {x for a in changed for x in a.args}
        # A fact without arguments (the power is on) was given to this segment by the segmenter: its effect.
        # The learner core's rule, with the objects a changed fact links to the hand's becoming parameters.
        env_add, env_del = changes(before, after, linked, any_argument=True)
        add = env_add | (hand_after - hand_before)
        delete = env_del | (hand_before - hand_after)
        if not add and not delete:
            continue  # e.g. a Reach: moves the hand, changes nothing symbolic
        interest = handled | {arg for atom in add | delete for arg in atom.args}
        interest |= _tied(before, set(roles), interest, static)
        # Nodes of interest: fluents about the objects the action involves, all
        # of whose arguments it involves (so opening a drawer does not depend on
        # which plate happens to lie in it).
        pre = {Literal(a) for a in facts_about(before, interest)} | {Literal(a) for a in hand_before}
        # Never more general than shown: static relations of those objects to others (the door's two rooms).
        relations = static_relations(before, interest, static)
        pre |= {Literal(a) for a in relations}
        # What the skill makes true was false before it (the drawer was closed).
        pre |= {Literal(a, False) for a in env_add}
        others = sorted(interest - set(roles)) + sorted({x for a in relations for x in a.args} - interest)
        objects = tuple(dict.fromkeys(roles + others))
        name = "_".join([seg["activity"].lower(), *(types.get(o, "object") for o in roles)])
        out.append(DemonstratedAction(name, objects, frozenset(pre), frozenset(add), frozenset(delete),
                                      f"{source} segment {seg['index']} ({seg['activity']} {' '.join(roles)})",
                                      float(seg.get("start", 0.0)), float(seg.get("end", 0.0)),
                                      frozenset(before | hand_before)))
    return out


#: Bindings of an action's precondition-only parameters tried at most when checking that it could run.
MAX_BINDINGS = 10_000


def robot_could(step: DemonstratedAction, robot: Domain, types: dict[str, str]) -> bool:
    """Whether an action of ``robot`` makes exactly ``step``'s changes and could have run where the step did
    (its precondition holds in ``step.state`` for some binding).  A step the robot makes only under a
    stronger precondition (opening the box with a full hand) teaches it something."""
    import itertools

    subtypes = robot.subtypes()
    objects = sorted(types)
    changed = sorted({o for a in (*step.add, *step.delete) for o in a.args})

    def admits(var_type: str, obj: str) -> bool:
        return types.get(obj, "object") in subtypes.get(var_type, {var_type})

    for schema in robot.actions:
        if len(schema.add) != len(step.add) or len(schema.delete) != len(step.delete):
            continue
        ptype = dict(schema.params)
        in_effects = [v for v, _ in schema.params if any(v in a.args for a in (*schema.add, *schema.delete))]
        rest = [v for v, _ in schema.params if v not in in_effects]
        for combo in itertools.product(changed, repeat=len(in_effects)):
            if not all(admits(ptype[v], o) for v, o in zip(in_effects, combo)):
                continue
            binding = dict(zip(in_effects, combo))
            if ({a.substitute(binding) for a in schema.add} != set(step.add)
                    or {a.substitute(binding) for a in schema.delete} != set(step.delete)):
                continue
            options = [[o for o in objects if admits(ptype[v], o)] for v in rest]
            for k, others in enumerate(itertools.product(*options)):
                if k >= MAX_BINDINGS:
                    break
                full = {**binding, **dict(zip(rest, others))}
                if all(lit.substitute(full).holds(step.state) for lit in schema.precondition):
                    return True
    return False


class _Acting:
    """Each hand's segments that are not Idle, as intervals sorted by start, to ask in logarithmic time
    whether the other hand was at work during a segment (hours of demonstration have tens of thousands)."""

    def __init__(self, skills: list[dict]) -> None:
        import itertools

        self.starts: dict[str, list[float]] = {}
        self.reach: dict[str, list[float]] = {}  # the latest end among the intervals up to each one
        for hand in {s["hand"] for s in skills}:
            spans = sorted((float(s.get("start", 0.0)), float(s.get("end", 0.0))) for s in skills
                           if s["hand"] == hand and s["activity"] not in SKIPPED)
            self.starts[hand] = [a for a, _ in spans]
            self.reach[hand] = list(itertools.accumulate((b for _, b in spans), max))

    def overlaps(self, seg: dict) -> bool:
        """Whether a segment of another hand that is not Idle overlaps ``seg`` in time."""
        import bisect

        start, end = float(seg.get("start", 0.0)), float(seg.get("end", 0.0))
        for hand, starts in self.starts.items():
            if hand == seg["hand"]:
                continue
            i = bisect.bisect_right(starts, end)  # intervals starting no later than seg ends
            if i and self.reach[hand][i - 1] >= start:
                return True
        return False


def _atom(text: str, source: str) -> Atom:
    words = text.strip().strip("()").split()
    if not words:
        raise TraceError("empty fluent in segments", Location(source))
    return Atom(words[0], tuple(words[1:]))


def lift(action: DemonstratedAction, types: dict[str, str]) -> ActionSchema:
    """Objects become typed parameters ``?o1 ...`` in order of their role."""
    variables = {o: f"?o{i + 1}" for i, o in enumerate(action.objects)}
    atoms = [lit.atom for lit in action.precondition] + list(action.add) + list(action.delete)
    extra = sorted({a for atom in atoms for a in atom.args} - set(variables))
    for o in extra:
        variables[o] = f"?o{len(variables) + 1}"
    binding = dict(variables)
    params = tuple((variables[o], types.get(o, "object")) for o in variables)
    return ActionSchema(
        name=action.name,
        params=params,
        precondition=tuple(sorted(lit.substitute(binding) for lit in action.precondition)),
        add=tuple(sorted(a.substitute(binding) for a in action.add)),
        delete=tuple(sorted(a.substitute(binding) for a in action.delete)),
        origin=action.source,
    )


def learn_domain(documents: list[tuple[str, dict]], prior: Domain | None = None, name: str = "learned",
                 context: Domain | None = None, human: Domain | None = None, skip_known: bool = False) -> Domain:
    """A domain of the skills demonstrated in ``documents`` (source, segments document).

    With ``prior``, its type hierarchy generalises repeats and the result is
    the prior merged with the learned skills by :func:`guided_lfd.merge.merge_domains`
    (skills the prior already has are kept once, name clashes renamed).  With
    ``context`` (the robot's domain the skills will be merged into later), the
    result is the learned skills alone, simplified only where that holds beside
    the context's actions too (a robot action could break an invariant the
    learned skills alone keep).

    The hand's facts are each document's declared vocabulary, else the
    robot's (``prior`` or ``context``, then ``human``: the predicates their
    grasping actions toggle), else ``in_hand``/``hand_free``.  With ``human``,
    skills are named after the human actions with the same effects.  With
    ``skip_known``, steps the robot (``prior`` or ``context``) already makes
    are not learned.
    """
    robot = prior if prior is not None else context
    vocabularies = {source: document_vocabulary(doc, robot, human, source=source) for source, doc in documents}
    known = robot if skip_known else None
    # What an action of the robot or the human changes is no static relation, even where the demonstrations
    # never change it (the breaker that feeds a switch was up throughout: whether it is up still matters).
    dynamic = set().union(*(d.fluent_predicates() for d in (robot, human) if d is not None))
    types, lifted, spans = _lifted_demonstrations(documents, vocabularies, known, dynamic)
    notes: list[str] = []
    learned = generalise(lifted, prior.types if prior is not None else None, notes, spans)
    if human is not None:
        from guided_lfd.demonstration.naming import name_after

        learned = name_after(learned, human)
    grasped = {v.held for v in vocabularies.values() if v.held} or {"in_hand"}
    predicates = _predicates_of(learned)
    if prior is not None:  # the prior's own declaration of a predicate stands (a learned one would widen it)
        predicates = robot_declarations(predicates, prior)
    type_decl: dict[str, str | None] = {"object": None}
    for t in sorted(set(types.values())):
        type_decl[t] = "object"
    reqs = (":strips", ":typing", ":negative-preconditions")
    if prior is None:
        frame = Domain(name, reqs, type_decl, {}, predicates, [], path="<learned>")
        if context is not None:
            frame = replace(context, types={**type_decl, **context.types},
                            predicates={**predicates, **context.predicates})
        learned = _simplified(documents, learned, types, frame, context.actions if context is not None else [],
                              vocabularies, grasped)
        simplified = Domain(name=name, requirements=reqs, types=type_decl, constants={}, predicates=predicates,
                            actions=learned, path="<learned>")
    else:
        simplified = _learned_into_prior(documents, prior, name, types, type_decl, predicates, learned,
                                         vocabularies, grasped)
    # Demonstrations left out or reconciled are reported with the domain (the CLI prints them).
    return replace(simplified, warnings=(*simplified.warnings, *notes))


def _simplified(documents: list[tuple[str, dict]], learned: list[ActionSchema], types: dict[str, str],
                frame: Domain, around: list[ActionSchema], vocabularies: dict[str, HandVocabulary] | None = None,
                grasped: set[str] | None = None) -> list[ActionSchema]:
    """The learned skills with implied preconditions dropped, proven on ``frame`` holding them and ``around``.

    Mutexes and implications are proven on the whole domain (the robot's actions too): an action that
    broke one would make the dropped precondition matter.  Learned actions get provisional unique
    names for the proof only."""
    provisional = {f"{a.name}__learned": a.name for a in learned}
    reqs = tuple(dict.fromkeys([*frame.requirements, ":negative-preconditions"]))
    combined = replace(frame, requirements=reqs, path="<learned>",
                       actions=[*around, *(replace(a, name=f"{a.name}__learned") for a in learned)])
    states = observed_states(documents, vocabularies)
    invariants = proven_invariants(combined, types, states)
    simplified = drop_implied_negative_preconditions(combined, set(provisional), invariants)
    simplified = drop_implied_preconditions(simplified, set(provisional), states, invariants, types,
                                            frozenset(grasped or {"in_hand"}))
    return [replace(a, name=provisional[a.name]) for a in simplified.actions if a.name in provisional]


def _lifted_demonstrations(documents: list[tuple[str, dict]], vocabularies: dict[str, HandVocabulary] | None = None,
                           known: Domain | None = None, dynamic: set[str] | None = None,
                           ) -> tuple[dict[str, str], list[ActionSchema], dict[str, str]]:
    """Every object's type, every demonstrated action lifted and the time span of each (by origin);
    a predicate used with two arities is an error.  Steps an action of ``known`` makes are left out;
    predicates in ``dynamic`` (changed by some action of the domains at hand) are never static."""
    vocabularies = vocabularies or {}
    types: dict[str, str] = {}
    lifted: list[ActionSchema] = []
    spans: dict[str, str] = {}
    static = static_predicates(documents, vocabularies) - (dynamic or set())
    arity: dict[str, tuple[int, str]] = {}
    for source, doc in documents:
        for fluents in [doc.get("initial", [])] + [s[k] for s in doc.get("segments", []) for k in ("before", "after")]:
            for atom in (_atom(x, source) for x in fluents):
                n, where = arity.setdefault(atom.predicate, (len(atom.args), source))
                if n != len(atom.args):
                    raise TraceError(f"{atom.predicate} has {len(atom.args)} argument(s) here and {n} in {where}; "
                                     "expected the same number", Location(source))
        types.update(doc.get("objects", {}))
        for action in ground_actions(doc, source, static, vocabularies.get(source)):
            if known is not None and robot_could(action, known, doc.get("objects", {})):
                continue  # the robot's own skill, which it could have run there: nothing to learn
            lifted.append(lift(action, doc.get("objects", {})))
            spans[action.source] = f", {action.start:.2f}-{action.end:.2f} s"
    return types, lifted, spans


def robot_declarations(predicates: dict[str, Predicate], robot: Domain) -> dict[str, Predicate]:
    """``predicates`` with the robot's own declaration where it has one of the same arity (a learned one would
    widen its argument types in a merge; another arity is left for the merge to refuse)."""
    return {name: robot.predicates[name] if name in robot.predicates
            and len(robot.predicates[name].params) == len(p.params) else p for name, p in predicates.items()}


def within_declarations(actions: list[ActionSchema], robot: Domain) -> list[ActionSchema]:
    """``actions`` with each parameter's type narrowed to the robot's declaration of an argument it fills, where
    that is narrower: skills merged under the robot's predicates (:func:`robot_declarations`) must fit them (a
    chair pushed from a drawer to a corner to a table, learned without the robot's type hierarchy, moves
    between ``object``s; the robot's ``(blocking ?c - obstacle ?f - furniture)`` says furniture)."""
    subtypes = robot.subtypes()
    out = []
    for act in actions:
        declared: dict[str, list[str]] = {}
        for atom in [l.atom for l in act.precondition] + list(act.add) + list(act.delete):
            pred = robot.predicates.get(atom.predicate)
            if pred is not None and len(pred.params) == len(atom.args):
                for arg, (_, kind) in zip(atom.args, pred.params):
                    declared.setdefault(arg, []).append(kind)
        params = []
        for var, kind in act.params:
            narrower = [d for d in declared.get(var, []) if d != kind and d in subtypes.get(kind, {kind})]
            # the narrowest declaration, when the declarations are one chain of types
            best = next((d for d in narrower if all(d in subtypes.get(o, {o}) for o in narrower)), kind)
            params.append((var, best))
        out.append(replace(act, params=tuple(params)) if tuple(params) != act.params else act)
    return out


def _predicates_of(actions: list[ActionSchema]) -> dict[str, Predicate]:
    """The predicates the actions use, each argument typed by its parameters (``object`` where they differ)."""
    predicates: dict[str, Predicate] = {}
    for act in actions:
        ptypes = dict(act.params)
        for atom in [l.atom for l in act.precondition] + list(act.add) + list(act.delete):
            if atom.predicate not in predicates:
                predicates[atom.predicate] = Predicate(
                    atom.predicate, tuple((f"?x{i}", ptypes.get(a, "object")) for i, a in enumerate(atom.args)))
            else:
                old = predicates[atom.predicate]
                merged = tuple((v, t if t == ptypes.get(a, "object") else "object")
                               for (v, t), a in zip(old.params, atom.args))
                predicates[atom.predicate] = Predicate(atom.predicate, merged)
    return predicates


def _learned_into_prior(documents: list[tuple[str, dict]], prior: Domain, name: str, types: dict[str, str],
                        type_decl: dict[str, str | None], predicates: dict[str, Predicate],
                        learned: list[ActionSchema], vocabularies: dict[str, HandVocabulary] | None = None,
                        grasped: set[str] | None = None) -> Domain:
    """The learned skills simplified with invariants proven on the prior and them, then merged into the prior."""
    sources = ", ".join(dict.fromkeys(source for source, _ in documents))
    clash = sorted((set(types.values()) - {"object"}) & set(prior.predicates) | set(predicates) & set(prior.types))
    if clash:
        raise MergeError(f"'{clash[0]}' is a type in one and a predicate in the other of the demonstrations and the "
                         f"prior {prior.path}; expected distinct names", Location(sources))
    from guided_lfd.merge import merge_domains

    reqs = tuple(dict.fromkeys([*prior.requirements, ":negative-preconditions"]))
    learned = _simplified(documents, learned, types, replace(prior, predicates={**predicates, **prior.predicates}),
                          prior.actions, vocabularies, grasped)
    alone = Domain(name=name, requirements=reqs, types=type_decl, constants={}, predicates=predicates,
                   actions=learned, path="<learned>")
    # The same rules as `guided-lfd merge`: equal skills once, clashes renamed.
    try:
        merged = merge_domains([prior, alone], name=prior.name).domain
    except MergeError as exc:
        if exc.location is not None and exc.location.path != "<learned>":
            raise
        # Name the demonstrations, not the in-memory domain learned from them.
        raise MergeError(exc.message.replace("<learned>", "the demonstrated skills")
                         + f" (demonstrations that do not fit the prior {prior.path})", Location(sources)) from None
    return replace(merged, path="<learned>")


def observed_states(documents: list[tuple[str, dict]],
                    vocabularies: dict[str, HandVocabulary] | None = None) -> list[frozenset[Atom]]:
    """Every state the demonstrations show, as the learner sees it (the acting hand's fluents included;
    ``vocabularies``: each source's hand facts, by default the document's own or the kitchens')."""
    states: list[frozenset[Atom]] = []
    for source, doc in documents:
        vocabulary = (vocabularies or {}).get(source) or document_vocabulary(doc, source=source)
        states.append(frozenset(_atom(x, source) for x in doc.get("initial", [])))
        for seg in skill_segments(doc.get("segments", [])):
            for fluents, held in ((seg["before"], seg.get("held_before", "")),
                                  (seg["after"], seg.get("held_after", ""))):
                env = {a for a in (_atom(x, source) for x in fluents) if a.predicate not in vocabulary.predicates}
                states.append(frozenset(env | vocabulary.fluents(seg["hand"], held)))
    return states


def check_usable(merged: Domain, robot: Domain, learned: set[str], where: str) -> None:
    """MismatchError when a skill in ``learned`` (names in ``merged``) can never run beside ``robot``'s: a
    precondition on a predicate ``robot`` does not declare and no usable action makes true (``hand_free``
    where the robot says ``hand-empty``), or a parameter of a type ``robot`` lacks.  ``where``: the
    demonstrations, for the message."""
    from guided_lfd.errors import MismatchError

    usable = set(robot.predicates) | {a.predicate for act in robot.actions for a in act.add}
    pending = [a for a in merged.actions if a.name in learned]
    for action in pending:
        odd = [t for _, t in action.params if t != "object" and t not in robot.types]
        if odd:
            raise MismatchError(f"learned skill {action.name} acts on objects of type {odd[0]}, a type "
                                f"{robot.path} does not have (expected demonstrations of the robot's world)",
                                Location(where))
    grew = True
    while grew:  # a learned skill may make true what another one needs
        grew = False
        for action in list(pending):
            if all(l.atom.predicate in usable for l in action.precondition if l.positive and l.atom.predicate != "="):
                usable |= {a.predicate for a in action.add}
                pending.remove(action)
                grew = True
    for action in pending:
        missing = sorted(l.atom.predicate for l in action.precondition
                         if l.positive and l.atom.predicate != "=" and l.atom.predicate not in usable)
        raise MismatchError(f"learned skill {action.name} needs ({missing[0]} ...), a predicate {robot.path} "
                            "never makes true: the skill could never run (expected demonstrations in the robot's "
                            "vocabulary; declare the hand facts with vocabulary(held=...) rows, or "
                            "vocabulary(none) for a world without them)", Location(where))


def learned_skills(domain: Domain, known: set[str]) -> list[dict]:
    """Each action of ``domain`` not in ``known`` (the prior's) as the ``skills`` of a ``guided-lfd/learned``
    document: name, parameters, effects, origin, and each precondition's evidence (held in how many of its
    demonstrations; ``varied``: some demonstration showed it false) beside the conditions its demonstrations
    varied, which it does not require."""
    out = []
    for action in domain.actions:
        if action.name in known:
            continue
        required, varied = action.learned_evidence()
        shown = {e.literal: e.to_json() for e in required}
        unknown = {"shown": None, "demonstrations": None, "varied": None, "confirmed": None}  # a precondition of no recorded evidence
        out.append({
            "name": action.name,
            "parameters": [{"name": v, "type": t} for v, t in action.params],
            "demonstrations": max((e.demonstrations for e in action.evidence), default=None),
            "preconditions": [shown.get(l) or {"literal": str(l), **unknown} for l in action.precondition],
            "varied": [e.to_json() for e in varied],
            "add": [str(a) for a in action.add],
            "delete": [str(a) for a in action.delete],
            "origin": action.origin,
        })
    return out

