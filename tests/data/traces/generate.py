"""A second, independent source of labelled hand traces (issue #14).

Written without guided_lfd's renderer (``guided_lfd/demonstration/render.py``):
only the CSV formats documented in the README are shared.  Standard library
and numpy only; deterministic (every trace has its own seed).

    python tests/data/traces/generate.py [OUT_DIR]     # default: this folder

writes ``OUT_DIR/<scenario>/<condition>/<name>.{csv,state.csv,labels.csv}``
and ``OUT_DIR/manifest.csv`` (the conditions of every file).

The motion model differs from the renderer's on purpose:

* hand speed profiles are trapezoidal (acceleration, cruise, deceleration:
  the ramp share drawn per motion) or piecewise linear (random knots), not
  minimum jerk; transports lift the object along an arc; doors swing about
  their hinge;
* durations are drawn per motion, not scaled to a total;
* frame clocks run at 15-120 Hz and may start late (the first frame at a few
  seconds); frames may be dropped or duplicated; the grip may flicker; the
  hand may tremble (8-11 Hz sinusoids, 1-2 mm);
* the object detector may name the target (``act_on``) late: 0.05-0.15 s
  after the motion toward it starts;
* fluent changes are registered when they physically happen: a grasped
  object's support contact ends either while the grasp settles (0.2-0.3 s
  after the grip closes) or, with ``liftoff``, 0.12-0.19 s into the
  transport; what an object rests on after a release is registered 30-50 ms
  after the grip opens; a drawer or door counts as open (closed) 75-85 % into
  its motion; a pushed chair blocks its new place 85-95 % into the push.

Ground truth (``.labels.csv``) is the phase the generator was in at every
frame time, including frames the tracker then dropped.
"""

from __future__ import annotations

import csv
import io
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


# --------------------------------------------------------------------------- conditions


@dataclass(frozen=True)
class Condition:
    """How a trace is recorded."""

    name: str
    rate_hz: float = 60.0
    profile: str = "trapezoid"  # trapezoid | piecewise
    tremor_m: float = 0.0  # amplitude of the tremor sinusoids
    noise_m: float = 0.001  # Gaussian position noise (sd)
    drop: float = 0.0  # share of dropped frames
    duplicate: float = 0.0  # share of duplicated frames
    flicker: float = 0.0  # share of frames with a misread grip
    lag_s: tuple[float, float] = (0.0, 0.0)  # detector latency range for act_on
    liftoff: bool = False  # contact ends 0.12-0.19 s into the transport
    clock_start_s: float = 0.0  # time of the first frame
    lowercase: bool = False  # object names in the trace lowercased (the state keeps its spelling)
    # One event per trace, its length drawn from the range: the tracker loses the hand inside a take, a
    # transport or an opening (its rows missing); the hand re-grasps during a transport (grip open, nothing
    # held, the object still the target); an accidental grip near the object during a reach.
    loss_s: tuple[float, float] = (0.0, 0.0)
    regrasp_s: tuple[float, float] = (0.0, 0.0)
    brief_grip_s: tuple[float, float] = (0.0, 0.0)
    tempo: float = 1.0  # every motion's duration times this (2.5: a slow demonstrator, motions of 1-3 s)

    def describe(self) -> str:
        parts = [f"{self.rate_hz:g} Hz", self.profile]
        if self.tremor_m:
            parts.append(f"tremor {self.tremor_m * 1000:g} mm")
        if self.drop or self.duplicate:
            parts.append(f"{self.drop:.0%} dropped, {self.duplicate:.0%} duplicated frames")
        if self.flicker:
            parts.append(f"{self.flicker:.0%} grip flicker")
        if self.lag_s[1]:
            parts.append(f"detector lag {self.lag_s[0]:g}-{self.lag_s[1]:g} s")
        parts.append("contact ends 0.12-0.19 s into the transport" if self.liftoff
                     else "contact ends during the grasp")
        if self.clock_start_s:
            parts.append(f"clock starts at {self.clock_start_s:g} s")
        if self.lowercase:
            parts.append("lowercase names in the trace")
        if self.tempo != 1.0:
            parts.append(f"motions {self.tempo:g} times as long")
        parts += self.events()
        return "; ".join(parts)

    def events(self) -> list[str]:
        """The condition's one-off events, in words."""
        out = []
        for what, (low, high) in (("tracking loss", self.loss_s), ("re-grasp during a transport", self.regrasp_s),
                                  ("accidental grip during a reach", self.brief_grip_s)):
            if high:
                out.append(f"{what} {low:g}-{high:g} s")
        return out


CONDITIONS = [
    Condition("base"),
    Condition("rate-15hz", rate_hz=15),
    Condition("rate-20hz", rate_hz=20),
    Condition("rate-30hz", rate_hz=30),
    Condition("rate-120hz", rate_hz=120),
    Condition("piecewise-tremor", profile="piecewise", tremor_m=0.0015),
    Condition("drops-dups", tremor_m=0.001, drop=0.04, duplicate=0.02, flicker=0.01, clock_start_s=2.5,
              lowercase=True),
    Condition("lag", lag_s=(0.05, 0.15)),
    Condition("liftoff", liftoff=True),
    Condition("field-20hz", rate_hz=20, profile="piecewise", tremor_m=0.0015, drop=0.03, duplicate=0.01,
              lag_s=(0.05, 0.15), liftoff=True, clock_start_s=1.0),
    Condition("tracking-loss", tremor_m=0.001, drop=0.02, loss_s=(0.5, 2.0), tempo=2.5),
    Condition("regrasp", tremor_m=0.001, regrasp_s=(0.18, 0.28)),
    Condition("brief-grip", tremor_m=0.001, brief_grip_s=(0.05, 0.14)),
]


# --------------------------------------------------------------------------- scenarios


@dataclass
class Scenario:
    """Objects (spelling -> type), where they are, the initial fluents and scripts of actions."""

    name: str
    objects: dict[str, str]
    places: dict[str, tuple[float, float, float]]
    initial: list[str]
    scripts: dict[str, list[tuple[str, ...]]]
    # Hinged things: name -> (hinge point, handle radius, opening angle sign).
    hinges: dict[str, tuple[tuple[float, float, float], float, float]] = field(default_factory=dict)


KITCHEN_OBJECTS = {"RedPlate": "item", "Table": "surface", "Counter": "surface", "PinkDrawer": "drawer",
                   "BlueDrawer": "drawer", "Corner": "furniture", "Chair": "obstacle"}
KITCHEN_PLACES = {"RedPlate": (0.55, 0.25, 0.78), "Table": (0.55, 0.25, 0.74), "Counter": (0.95, 0.1, 0.92),
                  "PinkDrawer": (-0.05, 0.5, 0.62), "BlueDrawer": (-0.4, 0.5, 0.62), "Corner": (-0.9, -0.45, 0.55),
                  "Chair": (-0.05, 0.15, 0.55)}

SCENARIOS = [
    Scenario(
        "kitchen-1", KITCHEN_OBJECTS, KITCHEN_PLACES,
        ["graspable(RedPlate)", "on_top(RedPlate,Table)", "clear(Table)", "clear(Counter)", "clear(PinkDrawer)",
         "clear(BlueDrawer)", "blocking(Chair,Corner)"],
        {"D1": [("open", "PinkDrawer"), ("take", "RedPlate", "Table"), ("put_inside", "RedPlate", "PinkDrawer")],
         "D2": [("take", "RedPlate", "Table"), ("put_on", "RedPlate", "Counter"), ("open", "PinkDrawer"),
                ("take", "RedPlate", "Counter"), ("put_inside", "RedPlate", "PinkDrawer"), ("close", "PinkDrawer")]},
    ),
    Scenario(
        "kitchen-2", KITCHEN_OBJECTS, KITCHEN_PLACES,
        ["graspable(RedPlate)", "on_top(RedPlate,Table)", "clear(Table)", "clear(Counter)", "clear(Corner)",
         "clear(BlueDrawer)", "blocking(Chair,PinkDrawer)"],
        {"D1": [("push", "Chair", "PinkDrawer", "Corner"), ("open", "PinkDrawer"), ("take", "RedPlate", "Table"),
                ("put_inside", "RedPlate", "PinkDrawer")],
         "D2": [("push", "Chair", "PinkDrawer", "Corner"), ("open", "PinkDrawer"), ("take", "RedPlate", "Table"),
                ("put_inside", "RedPlate", "PinkDrawer"), ("close", "PinkDrawer")]},
    ),
    Scenario(
        "stacking",
        {"RedBlock": "block", "GreenBlock": "block", "BlueBlock": "block", "Table": "surface"},
        {"RedBlock": (0.3, 0.3, 0.78), "GreenBlock": (0.5, 0.3, 0.78), "BlueBlock": (0.7, 0.3, 0.78),
         "Table": (0.5, 0.3, 0.75)},
        ["graspable(RedBlock)", "graspable(GreenBlock)", "graspable(BlueBlock)", "on_top(RedBlock,Table)",
         "on_top(GreenBlock,Table)", "on_top(BlueBlock,Table)", "clear(RedBlock)", "clear(GreenBlock)",
         "clear(BlueBlock)"],
        {"D1": [("take", "RedBlock", "Table"), ("stack", "RedBlock", "GreenBlock"), ("take", "BlueBlock", "Table"),
                ("stack", "BlueBlock", "RedBlock"), ("unstack", "BlueBlock", "RedBlock"),
                ("put_on", "BlueBlock", "Table")],
         "D2": [("take", "GreenBlock", "Table"), ("stack", "GreenBlock", "BlueBlock"),
                ("unstack", "GreenBlock", "BlueBlock"), ("stack", "GreenBlock", "RedBlock"),
                ("take", "BlueBlock", "Table"), ("stack", "BlueBlock", "GreenBlock")]},
    ),
    Scenario(
        "cupboard",
        {"Mug": "item", "Table": "surface", "Cupboard": "cupboard", "LeftDoor": "door", "RightDoor": "door"},
        {"Mug": (0.5, 0.2, 0.8), "Table": (0.5, 0.2, 0.75), "Cupboard": (0.0, 0.55, 1.25),
         "LeftDoor": (-0.12, 0.35, 1.25), "RightDoor": (0.12, 0.35, 1.25)},
        ["graspable(Mug)", "on_top(Mug,Table)", "door_of(LeftDoor,Cupboard)", "door_of(RightDoor,Cupboard)"],
        {"D1": [("open", "RightDoor"), ("take", "Mug", "Table"), ("put_inside", "Mug", "Cupboard"),
                ("close", "RightDoor")],
         "D2": [("open", "LeftDoor"), ("open", "RightDoor"), ("take", "Mug", "Table"),
                ("put_inside", "Mug", "Cupboard"), ("close", "RightDoor"), ("close", "LeftDoor")]},
        hinges={"LeftDoor": ((-0.3, 0.35, 1.25), 0.18, 1.0), "RightDoor": ((0.3, 0.35, 1.25), 0.18, -1.0)},
    ),
]


# --------------------------------------------------------------------------- motion


def speed_profile(kind: str, n: int, rng: np.random.Generator) -> np.ndarray:
    """Path phase s in [0, 1] at ``n`` equally spaced times, from a trapezoidal or piecewise-linear speed."""
    u = np.linspace(0.0, 1.0, 2001)
    if kind == "trapezoid":
        ramp = rng.uniform(0.2, 0.35)
        speed = np.minimum(1.0, np.minimum(u / ramp, (1.0 - u) / ramp))
    else:
        knots = np.concatenate([[0.0], np.sort(rng.uniform(0.1, 0.9, 3)), [1.0]])
        values = np.concatenate([[0.0], rng.uniform(0.5, 1.0, 3), [0.0]])
        speed = np.interp(u, knots, values)
    s = np.concatenate([[0.0], np.cumsum((speed[1:] + speed[:-1]) / 2 * np.diff(u))])
    s /= s[-1]
    return np.interp(np.linspace(0.0, 1.0, n), u, s)


@dataclass
class Phase:
    """One labelled phase of the hand: positions as a function of its own phase, grip, held object, target."""

    label: str
    start: float
    duration: float
    path: object  # callable s -> (3,) position, s in [0, 1]
    grip: bool
    held: str
    act_on: str
    profile: str
    seed: int

    @property
    def end(self) -> float:
        return self.start + self.duration


def line(p0, p1, lift: float = 0.0):
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)

    def at(s):
        s = np.asarray(s, float)[..., None]
        out = p0 + (p1 - p0) * s
        return out + np.array([0.0, 0.0, lift]) * np.sin(np.pi * s)

    return at


def still(p):
    p = np.asarray(p, float)
    return lambda s: np.broadcast_to(p, np.shape(s) + (3,)).copy()


class Actor:
    """Plays a script into phases and fluent changes (times in seconds from the first frame)."""

    def __init__(self, scenario: Scenario, cond: Condition, rng: np.random.Generator):
        self.sc, self.cond, self.rng = scenario, cond, rng
        self.rest = np.array([0.3, -0.35, 1.0])
        self.pos = self.rest.copy()
        self.places = {k: np.array(v, float) for k, v in scenario.places.items()}
        self.phases: list[Phase] = []
        self.events: list[tuple[float, str, bool]] = []
        self.t = 0.0
        self.angle = {d: 0.0 for d in scenario.hinges}  # 0 closed, pi/2 open
        self.drawer_out: dict[str, float] = {}
        self.pending_lift: tuple[str, str] | None = None

    def phase(self, label, duration, path, grip=False, held="", act_on=""):
        duration *= self.cond.tempo
        ph = Phase(label, self.t, duration, path, grip, held, act_on, self.cond.profile, int(self.rng.integers(1 << 30)))
        self.phases.append(ph)
        self.t += duration
        self.pos = np.asarray(path(1.0), float)
        return ph

    def change(self, when, fluent, value):
        self.events.append((when, fluent, value))

    def u(self, a, b):
        return float(self.rng.uniform(a, b))

    def handle(self, obj):
        if obj in self.sc.hinges:
            hinge, radius, sign = self.sc.hinges[obj]
            a = self.angle[obj]
            return np.array([hinge[0] + sign * radius * math.cos(a), hinge[1] - radius * math.sin(a), hinge[2]])
        if self.sc.objects[obj] == "drawer":
            return self.places[obj] + np.array([0.0, -0.12 - self.drawer_out.get(obj, 0.0), 0.05])
        if self.sc.objects[obj] == "obstacle":
            return self.places[obj] + np.array([0.0, -0.1, 0.35])
        return self.places[obj] + np.array([0.0, 0.0, 0.03])

    def idle(self, a=0.3, b=0.5):
        self.phase("Idle", self.u(a, b), still(self.pos))

    def reach(self, obj):
        self.phase("Reach", self.u(0.8, 1.15), line(self.pos, self.handle(obj), lift=0.03), act_on=obj)

    def withdraw(self):
        goal = self.pos + (self.rest - self.pos) * 0.6
        self.phase("Release", self.u(0.45, 0.65), line(self.pos, goal))

    # --- actions of the scripts
    def take(self, obj, support):
        self.reach(obj)
        grasp = self.phase("Take", self.u(0.45, 0.65), still(self.pos), grip=True, held=obj, act_on=obj)
        self.pending_lift = (obj, support)
        if not self.cond.liftoff:
            self.lift_now(grasp.start + self.u(0.2, 0.3))

    def lift_now(self, when):
        obj, support = self.pending_lift
        self.pending_lift = None
        self.change(when, f"on_top({obj},{support})" if self.sc.objects[support] == "surface" else f"on({obj},{support})",
                    False)
        if self.sc.objects[support] == "block":
            self.change(when, f"clear({support})", True)

    def unstack(self, obj, support):
        self.take(obj, support)

    def transport(self, obj, target, goal, changes):
        move = self.phase("Stack" if self.sc.objects[target] == self.sc.objects[obj] else "Put", self.u(0.9, 1.3),
                          line(self.pos, goal, lift=0.1), grip=True, held=obj, act_on=target)
        if self.pending_lift:
            self.lift_now(move.start + self.u(0.12, 0.19))
        self.places[obj] = goal - np.array([0.0, 0.0, 0.03])
        settle = self.t + self.u(0.03, 0.05)
        for fluent, value in changes:
            self.change(settle, fluent, value)
        self.withdraw()
        self.idle()

    def put_on(self, obj, surface):
        goal = self.places[obj].copy()
        goal[:2] = self.places[surface][:2] + self.rng.uniform(-0.05, 0.05, 2)
        goal[2] = self.places[surface][2] + 0.07
        self.transport(obj, surface, goal, [(f"on_top({obj},{surface})", True)])

    def stack(self, obj, below):
        goal = self.places[below] + np.array([0.0, 0.0, 0.08])
        self.transport(obj, below, goal, [(f"on({obj},{below})", True), (f"clear({below})", False)])

    def put_inside(self, obj, container):
        goal = (self.places[container] + np.array([0.0, -self.drawer_out.get(container, 0.0), 0.06])
                if container in self.drawer_out else self.places[container] + np.array([0.0, 0.0, -0.05]))
        self.transport(obj, container, goal, [(f"inside({obj},{container})", True)])

    def open(self, obj, opening=True):
        self.reach(obj)
        label = "Open" if opening else "Close"
        if obj in self.sc.hinges:
            hinge, radius, sign = self.sc.hinges[obj]
            a0 = self.angle[obj]
            a1 = math.pi / 2 if opening else 0.0
            self.angle[obj] = a1

            def swing(s, a0=a0, a1=a1, hinge=hinge, radius=radius, sign=sign):
                a = a0 + (a1 - a0) * np.asarray(s, float)
                return np.stack([hinge[0] + sign * radius * np.cos(a), hinge[1] - radius * np.sin(a),
                                 np.full_like(a, hinge[2])], axis=-1)

            path = swing
        else:
            out = 0.28 if opening else 0.0
            start = self.pos.copy()
            self.drawer_out[obj] = out
            path = line(start, self.handle(obj))
            if not opening:
                self.drawer_out.pop(obj)
        ph = self.phase(label, self.u(0.7, 0.95), path, grip=True, act_on=obj)
        self.change(ph.start + ph.duration * self.u(0.75, 0.85), f"open({obj})", opening)
        self.withdraw()
        self.idle()

    def close(self, obj):
        self.open(obj, opening=False)

    def push(self, obstacle, old, new):
        self.reach(obstacle)
        goal = self.places[new] + np.array([0.0, -0.1, 0.35])
        ph = self.phase("Push", self.u(1.2, 1.5), line(self.pos, goal), grip=True, act_on=obstacle)
        self.places[obstacle] = self.places[new].copy()
        when = ph.start + ph.duration * self.u(0.85, 0.95)
        for fluent, value in ((f"blocking({obstacle},{old})", False), (f"clear({old})", True),
                              (f"blocking({obstacle},{new})", True), (f"clear({new})", False)):
            self.change(when, fluent, value)
        self.withdraw()
        self.idle()

    def play(self, script):
        self.idle(0.4, 0.6)
        for action, *args in script:
            getattr(self, action)(*args)
        self.idle(0.3, 0.4)


# --------------------------------------------------------------------------- sampling and writing


def sample(actor: Actor, cond: Condition, rng: np.random.Generator):
    """Frames (time, pos, grip, held, act_on, label) at the condition's clock, before drops and duplicates."""
    total = actor.t
    n = int(math.floor(total * cond.rate_hz)) + 1
    times = np.arange(n) / cond.rate_hz
    starts = np.array([p.start for p in actor.phases])
    which = np.clip(np.searchsorted(starts, times, side="right") - 1, 0, len(actor.phases) - 1)
    lag = {}
    prev_target = ""
    for k, ph in enumerate(actor.phases):
        onset = ph.act_on and ph.act_on != prev_target
        lag[k] = (float(rng.uniform(*cond.lag_s)) if onset and cond.lag_s[1] else 0.0, prev_target)
        prev_target = ph.act_on
    # Phase of the path at every frame: through the motion's speed profile.
    pos = np.zeros((n, 3))
    for k, ph in enumerate(actor.phases):
        idx = np.flatnonzero(which == k)
        if not idx.size:
            continue
        frac = np.clip((times[idx] - ph.start) / ph.duration, 0.0, 1.0)
        profile = speed_profile(ph.profile, 401, np.random.default_rng(ph.seed))
        s = np.interp(frac, np.linspace(0.0, 1.0, 401), profile)
        pos[idx] = ph.path(s)
    if cond.tremor_m:
        f = rng.uniform(8.0, 11.0, 3)
        phi = rng.uniform(0, 2 * np.pi, 3)
        pos += cond.tremor_m * np.sin(2 * np.pi * f[None, :] * times[:, None] + phi[None, :])
    pos += rng.normal(0.0, cond.noise_m, pos.shape)
    frames = []
    for i, t in enumerate(times):
        k = int(which[i])
        ph = actor.phases[k]
        delay, previous = lag[k]
        act_on = ph.act_on if t - ph.start >= delay else (previous if ph.held and previous == ph.held else "")
        frames.append((float(t) + cond.clock_start_s, pos[i], ph.grip, ph.held, act_on, ph.label))
    return frames


def _window(frames, labels: tuple[str, ...], length: float, rng: np.random.Generator, held: bool = False):
    """Frame indices of a window of ``length`` s inside one phase labelled one of ``labels`` (clear of the
    phase's ends by 0.1 s), drawn among the phases long enough; empty when none is."""
    runs, start = [], 0
    for i in range(1, len(frames) + 1):
        if i == len(frames) or frames[i][5] != frames[start][5] or frames[i][3] != frames[start][3]:
            t0, t1 = frames[start][0], frames[i - 1][0]
            if frames[start][5] in labels and t1 - t0 >= length + 0.2 and (bool(frames[start][3]) or not held):
                runs.append((t0, t1))
            start = i
    if not runs:
        return []
    t0, t1 = runs[int(rng.integers(len(runs)))]
    begin = float(rng.uniform(t0 + 0.1, max(t0 + 0.1, t1 - 0.1 - length)))
    return [i for i, f in enumerate(frames) if begin <= f[0] < begin + length]


def perturb(frames, cond: Condition, rng: np.random.Generator):
    """The condition's one-off events applied to the frames: (frames, indices of the frames the tracker lost).
    A condition without events draws nothing (the other conditions' files stay as they were)."""
    lost: set[int] = set()
    frames = list(frames)
    if cond.loss_s[1]:
        lost = set(_window(frames, ("Take", "Put", "Open"), float(rng.uniform(*cond.loss_s)), rng))
    if cond.regrasp_s[1]:
        for i in _window(frames, ("Put",), float(rng.uniform(*cond.regrasp_s)), rng, held=True):
            t, p, _, held, _, label = frames[i]
            frames[i] = (t, p, False, "", held, label)  # the grip opens on the object and closes again
    if cond.brief_grip_s[1]:
        for i in _window(frames, ("Reach",), float(rng.uniform(*cond.brief_grip_s)), rng):
            t, p, _, held, act_on, label = frames[i]
            frames[i] = (t, p, True, held, act_on, label)  # a grip that closes on nothing and opens again
    return frames, lost


def write(scenario: Scenario, cond: Condition, script_name: str, seed: int, folder: Path) -> dict[str, str]:
    rng = np.random.default_rng(seed)
    actor = Actor(scenario, cond, rng)
    actor.play(scenario.scripts[script_name])
    frames, lost = perturb(sample(actor, cond, rng), cond, rng)

    def name(x: str) -> str:
        return x.lower() if cond.lowercase else x

    trace, labels = io.StringIO(), io.StringIO()
    tw, lw = csv.writer(trace, lineterminator="\n"), csv.writer(labels, lineterminator="\n")
    tw.writerow(["time", "hand", "x", "y", "z", "grip", "in_hand", "act_on"])
    lw.writerow(["time", "hand", "activity"])
    for i, (t, p, grip, held, act_on, label) in enumerate(frames):
        copies = 1
        r = rng.random()
        if r < cond.drop or i in lost:
            copies = 0
        elif r < cond.drop + cond.duplicate:
            copies = 2
        if rng.random() < cond.flicker:
            grip = not grip
        for _ in range(copies):
            tw.writerow([f"{t:.4f}", "right", f"{p[0]:.3f}", f"{p[1]:.3f}", f"{p[2]:.3f}",
                         "1" if grip else "0", name(held), name(act_on)])
        for _ in range(max(1, copies)):
            lw.writerow([f"{t:.4f}", "right", label])
    state = io.StringIO()
    sw = csv.writer(state, lineterminator="\n")
    sw.writerow(["time", "fluent", "value"])
    for obj, kind in scenario.objects.items():
        sw.writerow(["0", f"object({obj},{kind})", "true"])
    for fluent in scenario.initial:
        sw.writerow(["0", fluent, "true"])
    for when, fluent, value in sorted(actor.events, key=lambda e: e[0]):
        sw.writerow([f"{when + cond.clock_start_s:.4f}", fluent, "true" if value else "false"])
    folder.mkdir(parents=True, exist_ok=True)
    stem = folder / script_name
    files = {"trace": trace.getvalue(), "state": state.getvalue(), "labels": labels.getvalue()}
    Path(f"{stem}.csv").write_text(files["trace"])
    Path(f"{stem}.state.csv").write_text(files["state"])
    Path(f"{stem}.labels.csv").write_text(files["labels"])
    return files


def generate(out: Path = HERE, seed_base: int = 14_000) -> list[Path]:
    """Write every scenario x condition x script; the manifest; the trace paths.

    ``seed_base`` other than the committed files' draws a held-out set: the same scenarios and
    conditions, every duration, speed profile, noise, drop and lag drawn anew."""
    written = []
    rows = [["file", "scenario", "condition", "rate_hz", "profile", "tremor_mm", "drop", "duplicate", "flicker",
             "lag_s", "liftoff", "clock_start_s", "lowercase", "seed", "actions", "events"]]
    for si, scenario in enumerate(SCENARIOS):
        for ci, cond in enumerate(CONDITIONS):
            for di, script in enumerate(sorted(scenario.scripts)):
                seed = seed_base + 1000 * si + 10 * ci + di
                folder = out / scenario.name / cond.name
                write(scenario, cond, script, seed, folder)
                path = folder / f"{script}.csv"
                written.append(path)
                rows.append([str(path.relative_to(out)), scenario.name, cond.name, f"{cond.rate_hz:g}", cond.profile,
                             f"{cond.tremor_m * 1000:g}", f"{cond.drop:g}", f"{cond.duplicate:g}", f"{cond.flicker:g}",
                             f"{cond.lag_s[0]:g}-{cond.lag_s[1]:g}", str(cond.liftoff).lower(),
                             f"{cond.clock_start_s:g}", str(cond.lowercase).lower(), str(seed),
                             " ".join("(" + " ".join(a) + ")" for a in scenario.scripts[script]),
                             "; ".join(cond.events())])
    with open(out / "manifest.csv", "w", encoding="utf-8", newline="") as fh:
        csv.writer(fh, lineterminator="\n").writerows(rows)
    return written


if __name__ == "__main__":
    # generate.py [OUT_DIR [SEED_BASE]]
    generate(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE, int(sys.argv[2]) if len(sys.argv) > 2 else 14_000)
