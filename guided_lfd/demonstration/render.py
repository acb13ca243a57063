"""Rendering symbolic hand activities into a realistic VR hand trace.

The study's VR recordings are not public, so guided-lfd renders stand-ins:
a script of hand activities in a scene becomes a trace in the format of
:mod:`guided_lfd.demonstration.trace`, with the environment state and
per-frame ground-truth labels beside it.  Rendered, not recorded:

* 90 Hz (configurable) frames for both hands; the idle hand rests, or holds
  still what it holds; both hands may act at once (``Step.parallel``);
* reach, transport, pull and push motions follow minimum-jerk profiles
  (Flash & Hogan 1985), the standard model of human point-to-point motion;
* Gaussian position noise, dropped frames and single-frame grip flicker, as
  trackers and glove sensors produce them.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

import numpy as np

from guided_lfd.demonstration.trace import HAND_PREDICATES
from guided_lfd.demonstration.vocabulary import KITCHEN, HandVocabulary, infer_vocabulary
from guided_lfd.pddl.model import Atom

Vec = tuple[float, float, float]


@dataclass
class Step:
    """One hand activity to render.

    ``changes`` are the fluent changes the activity causes, registered at its
    end (``Release`` registers where the object now is at its start).

    A step starts once every earlier step, of either hand, has ended; a
    ``parallel`` step only waits for its own hand, so it runs alongside what
    the other hand is doing (both hands at once).
    """

    activity: str  # Idle, Reach, Take, Put, Release, Open, Close, Push, Operate
    obj: str = ""
    target: str = ""
    duration: float = 1.0
    changes: list[tuple[Atom, bool]] = field(default_factory=list)
    hand: str = "right"
    parallel: bool = False


@dataclass
class Scene:
    """Object positions (m), object types, and where the hands rest."""

    positions: dict[str, Vec]
    types: dict[str, str]
    spellings: dict[str, str] = field(default_factory=dict)
    rest: dict[str, Vec] = field(default_factory=lambda: {"right": (0.25, -0.3, 0.95), "left": (-0.25, -0.3, 0.95)})
    pull: Vec = (0.0, -0.25, 0.0)  # how far a drawer handle travels when opened


@dataclass
class Noise:
    """Sensor imperfections of the rendered trace.

    Beside position noise, dropped frames and grip flicker (every trace has some), a real tracker's events, off
    by default: ``loss_s``, one tracking loss of up to that long (drawn) inside a take, a carry or a
    manipulation of one hand (its rows missing); ``regrasp_s``, one re-grasp during a carry (the grip opens on
    the object for up to that long, drawn from half of it); ``brief_grip_s``, one grip closing on nothing
    during a reach; ``duplicate_rate``, rows written twice; ``burst_rate``, the chance per frame that a burst of
    3 to 8 frames is dropped; ``jitter_s``, timestamp noise (sd, clipped to a third of the frame period so
    the frames keep their order).  The events draw from their own random stream: a trace without them is the
    same as before they existed."""

    position_sd_m: float = 0.0015
    drop_rate: float = 0.02
    flicker_rate: float = 0.01
    seed: int = 0
    loss_s: float = 0.0
    regrasp_s: float = 0.0
    brief_grip_s: float = 0.0
    duplicate_rate: float = 0.0
    burst_rate: float = 0.0
    jitter_s: float = 0.0

    #: ``--trace-noise`` names: KEY=VALUE -> field (seconds for the events and jitter, fractions for rates).
    SPEC_KEYS = {"loss": "loss_s", "regrasp": "regrasp_s", "grip": "brief_grip_s", "drops": "drop_rate",
                 "duplicates": "duplicate_rate", "bursts": "burst_rate", "jitter": "jitter_s",
                 "flicker": "flicker_rate"}

    @classmethod
    def parse(cls, spec: str, seed: int = 0) -> "Noise":
        """``KEY=VALUE[,...]`` (keys in :data:`SPEC_KEYS`; ``loss=2,regrasp=0.25,drops=0.05``) as Noise; a
        ValueError naming what was expected otherwise."""
        import re

        values: dict[str, float] = {}
        parts = [p.strip() for p in str(spec).split(",") if p.strip()]
        if not parts:
            raise ValueError("expected KEY=VALUE[,...]: nothing given")
        for part in parts:
            match = re.fullmatch(r"([a-z]+)\s*=\s*(\S+)", part)
            if not match or match.group(1) not in cls.SPEC_KEYS:
                raise ValueError(f"'{part}': expected KEY=VALUE with KEY one of {', '.join(cls.SPEC_KEYS)}")
            try:
                value = float(match.group(2))
            except ValueError:
                value = float("nan")
            if not (0 <= value < float("inf")):  # also refuses nan
                raise ValueError(f"'{part}': expected a number >= 0 for {match.group(1)}")
            key = cls.SPEC_KEYS[match.group(1)]
            if key.endswith("_rate") and value >= 1 and key in ("drop_rate", "burst_rate"):
                raise ValueError(f"'{part}': a rate of dropped frames below 1 (a trace keeps some of its frames)")
            if key.endswith("_rate") and value > 1:
                raise ValueError(f"'{part}': a rate is a fraction from 0 to 1")
            if key == "loss_s" and value > 5:
                raise ValueError(f"'{part}': a tracking loss of at most 5 s")
            values[key] = value
        return cls(seed=seed, **values)

    @property
    def tracker(self) -> bool:
        """Whether any of the tracker's events is on."""
        return any((self.loss_s, self.regrasp_s, self.brief_grip_s, self.duplicate_rate, self.burst_rate,
                    self.jitter_s))


@dataclass
class Rendering:
    """The rendered trace, state and labels as CSV text."""

    trace_csv: str
    state_csv: str
    labels_csv: str
    steps: list[Step]


def minimum_jerk(p0: np.ndarray, p1: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Positions along the minimum-jerk path from p0 to p1 at phases s in [0, 1]."""
    shape = 10 * s**3 - 15 * s**4 + 6 * s**5
    return p0 + (p1 - p0) * shape[:, None]


def schedule(steps: list[Step]) -> list[tuple[float, float]]:
    """(start, end) of every step in seconds, as :func:`render` plays them."""
    clock = {"left": 0.0, "right": 0.0}
    out = []
    for step in steps:
        start = clock[step.hand] if step.parallel else max(clock.values())
        clock[step.hand] = start + step.duration
        out.append((start, start + step.duration))
    return out


def render(steps: list[Step], scene: Scene, initial: set[Atom], rate_hz: float = 90.0,
           noise: Noise | None = None, vocabulary: HandVocabulary | None = None) -> Rendering:
    """Render ``steps`` (scheduled as :func:`schedule` says) into trace, state and label CSVs.

    A hand without a step of its own waits where it is: holding an object
    still, which the activity model calls Take, or idle.  ``vocabulary``: the
    hand facts of the world's domain; other than the kitchens', the state
    file declares them (``vocabulary(...)`` rows) and leaves them out of its
    fluents.
    """
    noise = noise or Noise()
    rng = np.random.default_rng(noise.seed)
    dt = 1.0 / rate_hz
    hand_pos = {h: np.array(p, dtype=float) for h, p in scene.rest.items()}
    # What each hand holds as the demonstration starts (the last round may have ended holding something).
    binding = vocabulary or KITCHEN
    held: dict[str, str] = {"right": "", "left": ""}
    for atom in sorted(initial):
        if binding.held_object(atom) is not None:
            held[binding.hand_of(atom)] = binding.held_object(atom) or ""
    # Per hand, frame index -> (pos, grip, in_hand, act_on, label).
    tracks: dict[str, dict[int, tuple]] = {"right": {}, "left": {}}
    events: list[tuple[float, Atom, bool]] = []
    # Each hand's clock: seconds of its steps so far and frames rendered for
    # them; frames are counted on the cumulative time, so rounding never accumulates.
    ideal = {"right": 0.0, "left": 0.0}
    frames = {"right": 0, "left": 0}
    for step in steps:
        hand = step.hand
        if not step.parallel:
            # Wait for both hands: start where the hand furthest on stands.
            ahead = max(frames, key=lambda h: (frames[h], ideal[h]))
            _wait(tracks[hand], frames[hand], frames[ahead], hand_pos[hand], held[hand])
            ideal[hand], frames[hand] = ideal[ahead], frames[ahead]
        ideal[hand] += step.duration
        first = frames[hand]
        n = max(2, int(round(ideal[hand] * rate_hz)) - first)
        frames[hand] = first + n
        times = dt * np.arange(first, first + n)
        s = np.linspace(0.0, 1.0, n)
        path, grip, in_hand, act_on, label = _motion(step, hand, hand_pos[hand].copy(), s, n, scene, held)
        if step.activity == "Release":
            # The object is registered where it was put as the hand lets go.
            events += [(float(times[0]) + 1e-3, atom, value) for atom, value in step.changes]
        else:
            events += [(float(times[-1]), atom, value) for atom, value in step.changes]
        for k in range(n):
            tracks[hand][first + k] = (path[k], grip, in_hand, act_on, label)
        hand_pos[hand] = path[-1]
    end = max(frames.values())
    for hand in ("right", "left"):
        _wait(tracks[hand], frames[hand], end, hand_pos[hand], held[hand])
    rows: list[tuple] = []  # (time, hand, pos, grip, in_hand, act_on, label)
    for hand, track in tracks.items():
        rows += [(float(dt * k), hand, *track[k]) for k in range(end)]
    return Rendering(_trace_csv(rows, scene, noise, rng), _state_csv(scene, initial, events, vocabulary),
                     _labels_csv(rows), steps)


def _motion(step: Step, hand: str, start: np.ndarray, s: np.ndarray, n: int, scene: Scene,
            held: dict[str, str]) -> tuple[np.ndarray, bool, str, str, str]:
    """The ``n`` positions of ``hand`` during ``step`` from ``start`` (phases ``s``), its grip, held object, target
    and ground-truth label; updates ``held`` when the step takes or releases an object."""
    grip, in_hand, act_on = False, "", step.obj
    label = step.activity
    if step.activity == "Reach":
        path = minimum_jerk(start, np.array(scene.positions[step.obj]), s)
    elif step.activity == "Take":
        path = np.repeat(start[None, :], n, axis=0)
        grip, in_hand, act_on = True, step.obj, step.obj
        held[hand] = step.obj
    elif step.activity == "Put":
        # Onto the target, or (none named: put down on the table) a little aside and down.
        if step.target:
            path = minimum_jerk(start, np.array(scene.positions[step.target]) + np.array([0.0, 0.0, 0.05]), s)
        else:
            # With no target for the detector to name, the hand keeps lowering the object until it lets go
            # (at a steady speed: slowing to a stop would read as holding it still).
            path = start + np.array([0.2, 0.1, -0.15])[None, :] * s[:, None]
        grip, in_hand, act_on = True, step.obj, step.target
    elif step.activity == "Release":
        path = minimum_jerk(start, np.array(scene.rest[hand]), s)
        in_hand, act_on = "", ""
        held[hand] = ""
    elif step.activity in ("Open", "Close", "Operate"):
        # Operate: the hand works a control it holds (a switch, a valve), as far as a drawer handle goes.
        direction = np.array(scene.pull) * (-1 if step.activity == "Close" else 1)
        path = minimum_jerk(start, start + direction, s)
        grip, act_on = True, step.obj
        label = "Manipulate" if step.activity == "Operate" else label
    elif step.activity == "Push":
        # Pushed to where it goes, or (no place named: "push it aside") sideways off what it blocks.
        goal = (np.array(scene.positions[step.target]) + np.array([0.0, -0.4, 0.0]) if step.target
                else np.array(scene.positions[step.obj]) + np.array([0.4, -0.4, 0.0]))
        path = minimum_jerk(start, goal, s)
        grip, act_on = True, step.obj
    elif step.activity == "Idle":
        act_on = ""
        if held[hand]:
            # Holding still keeps the object (the activity model calls it Take).
            path = np.repeat(start[None, :], n, axis=0)
            grip, in_hand, label = True, held[hand], "Take"
        else:
            path = minimum_jerk(start, np.array(scene.rest[hand]), np.clip(s * 3, 0, 1))
            label = "Idle"
    else:
        raise ValueError(f"cannot render activity {step.activity!r}")
    return path, grip, in_hand, act_on, label


def _wait(track: dict[int, tuple], first: int, last: int, pos: np.ndarray, held: str) -> None:
    """Frames ``first`` to ``last - 1`` of a hand waiting for the other one."""
    for k in range(first, last):
        # Holding an object still is a Take in the activity model; an empty hand idles.
        track[k] = (pos, bool(held), held, "", "Take" if held else "Idle")


def _name(scene: Scene, obj: str) -> str:
    return scene.spellings.get(obj, obj) if obj else ""


def _trace_csv(rows, scene: Scene, noise: Noise, rng: np.random.Generator) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["time", "hand", "x", "y", "z", "grip", "in_hand", "act_on"])
    rows = sorted(rows, key=lambda r: (r[0], r[1]))
    lost: set[int] = set()
    events = np.random.default_rng([noise.seed, 1])  # the tracker's own stream (see Noise)
    if noise.tracker:
        rows, lost = _tracker_events(rows, noise, events)
    # The frame period bounds the jitter (frames keep their order); only a trace with jitter needs it.
    period = float(np.median(np.diff(sorted({r[0] for r in rows})))) if noise.jitter_s and len(rows) > 2 else 0.0
    burst = {"right": 0, "left": 0}
    for k, (time, hand, pos, grip, in_hand, act_on, _) in enumerate(rows):
        if rng.random() < noise.drop_rate:
            continue  # a dropped frame
        if rng.random() < noise.flicker_rate:
            grip = not grip  # a one-frame glove misreading
        x, y, z = np.asarray(pos) + rng.normal(0.0, noise.position_sd_m, 3)
        copies = 1
        if noise.tracker:
            if noise.burst_rate and not burst[hand] and events.random() < noise.burst_rate:
                burst[hand] = int(events.integers(3, 9))
            if k in lost or burst[hand]:
                burst[hand] = max(0, burst[hand] - 1)
                continue
            if noise.jitter_s:
                time = max(0.0, time + float(np.clip(events.normal(0.0, noise.jitter_s), -period / 3, period / 3)))
            copies = 2 if noise.duplicate_rate and events.random() < noise.duplicate_rate else 1
        for _ in range(copies):
            writer.writerow([f"{time:.4f}", hand, f"{x:.4f}", f"{y:.4f}", f"{z:.4f}",
                             "closed" if grip else "open", _name(scene, in_hand), _name(scene, act_on)])
    return buf.getvalue()


def _tracker_events(rows: list[tuple], noise: Noise, rng: np.random.Generator) -> tuple[list[tuple], set[int]]:
    """One tracking loss, one re-grasp and one brief grip (as ``noise`` asks) applied to the sorted rows: (rows,
    indices of the rows the tracker lost)."""
    rows, lost = list(rows), set()

    def window(labels: tuple[str, ...], length: float) -> list[int]:
        """Row indices of one hand's window of ``length`` s inside a run of one of ``labels`` (0.1 s clear of
        its ends), drawn among the runs long enough."""
        runs: list[tuple[str, float, float]] = []
        for hand in ("right", "left"):
            own = [r for r in rows if r[1] == hand]
            start = 0
            for i in range(1, len(own) + 1):
                if i == len(own) or own[i][6] != own[start][6] or own[i][4] != own[start][4]:
                    t0, t1 = own[start][0], own[i - 1][0]
                    if own[start][6] in labels and t1 - t0 >= length + 0.2:
                        runs.append((hand, t0, t1))
                    start = i
        if not runs:
            return []
        hand, t0, t1 = runs[int(rng.integers(len(runs)))]
        begin = float(rng.uniform(t0 + 0.1, max(t0 + 0.1, t1 - 0.1 - length)))
        return [i for i, r in enumerate(rows) if r[1] == hand and begin <= r[0] < begin + length]

    if noise.loss_s:
        lost = set(window(("Take", "Put", "Stack", "Manipulate"), float(rng.uniform(0.5, 1.0)) * noise.loss_s))
    if noise.regrasp_s:
        for i in window(("Put", "Stack"), float(rng.uniform(0.5, 1.0)) * noise.regrasp_s):
            time, hand, pos, _, in_hand, _, label = rows[i]
            rows[i] = (time, hand, pos, False, "", in_hand, label)  # the grip opens on the object and closes
    if noise.brief_grip_s:
        for i in window(("Reach",), float(rng.uniform(0.5, 1.0)) * noise.brief_grip_s):
            time, hand, pos, _, in_hand, act_on, label = rows[i]
            rows[i] = (time, hand, pos, True, in_hand, act_on, label)  # a grip closing on nothing
    return rows, lost


def _fluent(atom: Atom, scene: Scene) -> str:
    return f"{atom.predicate}({','.join(_name(scene, a) for a in atom.args)})"


def _state_csv(scene: Scene, initial: set[Atom], events, vocabulary: HandVocabulary | None = None) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["time", "fluent", "value"])
    for obj in sorted(scene.types):
        writer.writerow(["0", f"object({_name(scene, obj)},{scene.types[obj]})", "true"])
    hand = set(HAND_PREDICATES)
    if vocabulary is not None and vocabulary != KITCHEN:  # the kitchens' is the format's default: no rows
        hand = set(vocabulary.predicates)
        rows = [f"held={vocabulary.held}", f"free={vocabulary.free}"] if hand else ["none"]
        rows += [f"{h}={_name(scene, arm)}" for h, arm in vocabulary.hands]
        for row in rows:
            writer.writerow(["0", f"vocabulary({row.replace('=None', '=none')})", "true"])
    for atom in sorted(initial):
        if atom.predicate in hand:
            continue  # the hand's state is in the trace (in_hand), not the environment
        writer.writerow(["0", _fluent(atom, scene), "true"])
    for time, atom, value in sorted(events, key=lambda e: (e[0], e[1])):
        writer.writerow([f"{time:.4f}", _fluent(atom, scene), "true" if value else "false"])
    return buf.getvalue()


def _labels_csv(rows) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["time", "hand", "activity"])
    for time, hand, _, _, _, _, label in sorted(rows, key=lambda r: (r[0], r[1])):
        writer.writerow([f"{time:.4f}", hand, label])
    return buf.getvalue()


def frame_f1(truth: list[str], predicted: list[str]) -> float:
    """Macro-F1 of frame labels over the activities that occur in ``truth``."""
    scores = []
    for label in sorted(set(truth)):
        tp = sum(1 for a, b in zip(truth, predicted) if a == label and b == label)
        fp = sum(1 for a, b in zip(truth, predicted) if a != label and b == label)
        fn = sum(1 for a, b in zip(truth, predicted) if a == label and b != label)
        scores.append(0.0 if tp == 0 else 2 * tp / (2 * tp + fp + fn))
    return sum(scores) / len(scores) if scores else 1.0


def undrawable_actions(plan: list[tuple[str, tuple[str, ...]]], domain) -> set[str]:
    """Names of the plan's actions :func:`script_for_plan` cannot draw as hand activities: those without
    objects (the hand has nothing to act on).  Every other action is drawn (see :func:`script_for_plan`)."""
    return {name for name, args in plan if not args}


def plan_vocabulary(domain, objects: dict[str, str] | None = None, robot=None) -> HandVocabulary:
    """The hand facts a simulated demonstration of ``domain``'s plans declares: ``robot``'s where its grasping
    actions show them, else ``domain``'s (no hand facts when neither shows any); arms tied to the trace's
    hands by ``objects``' names, or in name order where the names do not tell (the simulated demonstrator
    uses whichever hand it is told).  ValueError when the hand facts are ambiguous or the arms more than two."""
    from guided_lfd.demonstration.vocabulary import NO_HAND, bind_arms

    found = None
    if robot is not None:
        try:
            found = infer_vocabulary(robot)
        except ValueError:
            found = None  # the human model's may still tell
    found = found or infer_vocabulary(domain)
    if found is None:
        return NO_HAND
    return bind_arms(found, objects or {}, choose=True) if found.by_arm else found


def _work_on(args: tuple[str, ...], env: list[tuple[Atom, bool]], held: str, hand: str,
             vocabulary: HandVocabulary, pause: float) -> list[Step]:
    """The steps of an action that neither takes nor puts down: the hand works on the first of ``args`` (not an
    arm, not what it holds) that the changes ``env`` are about.  Holding ``held`` (a tool, a carried cup), it
    brings that to the object and keeps it (opening a box with a cup in hand does not put the cup down); free,
    it pushes the object (the chair pushed away) or, no change being about it, operates it."""
    about = {x for a, _ in env for x in a.args}
    arm_objects = set(dict(vocabulary.hands).values())
    candidates = [x for x in args if x not in arm_objects and x != held] or list(args)
    moved = next((x for x in candidates if x in about), candidates[0])
    if held:
        return [Step("Put", held, moved, duration=1.2, changes=env, hand=hand), Step("Idle", duration=pause, hand=hand)]
    if moved in about:
        target = next((a.args[-1] for a, value in env if value and moved in a.args), "")
        return [Step("Reach", moved, duration=1.0, hand=hand),
                Step("Push", moved, target, duration=1.4, changes=env, hand=hand), Step("Release", duration=0.6, hand=hand)]
    return [Step("Reach", moved, duration=1.0, hand=hand), Step("Operate", moved, duration=0.8, changes=env, hand=hand),
            Step("Release", duration=0.6, hand=hand)]


def script_for_plan(plan: list[tuple[str, tuple[str, ...]]], domain, state: set[Atom],
                    pause: float = 0.4, vocabulary: HandVocabulary | None = None) -> list[Step]:
    """Hand activities that demonstrate a plan of ``domain`` from ``state``.

    Each action becomes the activities a person performs for it, read off
    its effects (``vocabulary``: the domain's hand facts, by default read off
    its grasping actions): making the held fact true is Reach + Take; giving
    it up is Put + Release; changing ``open`` is Reach + Open/Close +
    Release.  Any other action is the hand working on the action's first
    object its changes are about (the door, the switch, the room left): with
    a free hand Reach + Push (the chair pushed away) + Release, or Reach +
    Operate + Release when no change is about that object; with the hand
    holding something (a tool, a carried cup), the held object moved to that
    object (a Put without a Release), then held still.  Fluent changes are
    attached to the activity that causes them.  Idle pauses separate the
    actions.  With arms as objects, an action's arm says which hand acts.
    """
    vocabulary = vocabulary or plan_vocabulary(domain)
    hand_predicates = vocabulary.predicates
    schemas = {a.name: a for a in domain.actions}
    current = set(state)
    held = {"right": "", "left": ""}
    for atom in state:
        if vocabulary.held_object(atom) is not None:
            held[vocabulary.hand_of(atom)] = vocabulary.held_object(atom) or ""
    steps: list[Step] = [Step("Idle", duration=pause)]
    for name, args in plan:
        schema = schemas[name]
        binding = {v: a for (v, _), a in zip(schema.params, args)}
        adds = {a.substitute(binding) for a in schema.add}
        dels = {a.substitute(binding) for a in schema.delete}
        env = [(a, True) for a in sorted(adds - current) if a.predicate not in hand_predicates]
        env += [(a, False) for a in sorted(dels & current) if a.predicate not in hand_predicates]
        taken = sorted(a for a in adds if vocabulary.held_object(a) is not None)
        given = sorted(a for a in dels if vocabulary.held_object(a) is not None)
        opened = [a for a, _ in env if a.predicate == "open" and a.args]
        arms = [vocabulary.hand_of(Atom("_", (x,))) for x in args if x in dict(vocabulary.hands).values()]
        hand = arms[0] if arms else "right"
        if not args and not taken and not given:
            continue  # nothing for the hand to act on (undrawable_actions names it)
        if taken:
            obj, hand = vocabulary.held_object(taken[0]) or "", vocabulary.hand_of(taken[0])
            steps += [Step("Reach", obj, duration=1.0, hand=hand),
                      Step("Take", obj, duration=0.5, changes=env, hand=hand)]
            held[hand] = obj
        elif given:
            obj, hand = vocabulary.held_object(given[0]) or "", vocabulary.hand_of(given[0])
            target = next((x for a, _ in env for x in a.args if x != obj), "")
            steps += [Step("Put", obj, target, duration=1.2, hand=hand),
                      Step("Release", duration=0.6, changes=env, hand=hand)]
            held[hand] = ""
        elif held[hand] and args:
            steps += _work_on(args, env, held[hand], hand, vocabulary, pause)
        elif opened:
            obj = opened[0].args[0]
            kind = "Open" if (opened[0], True) in env else "Close"
            steps += [Step("Reach", obj, duration=1.0, hand=hand), Step(kind, obj, duration=0.8, changes=env, hand=hand),
                      Step("Release", duration=0.6, hand=hand)]
        else:
            steps += _work_on(args, env, "", hand, vocabulary, pause)
        current = (current - dels) | adds
        if not taken and steps[-1].activity != "Idle":
            steps.append(Step("Idle", duration=pause, hand=hand))
    return steps
