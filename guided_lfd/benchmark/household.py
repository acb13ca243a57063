"""Household excuse tasks: the paper's kitchen scaled up to a house.

A house has rooms; each room has a table and a counter (surfaces), drawers
and cupboards with doors (containers), and items (plates, cups) lying on the
tables.  Obstacles (chairs, boxes) block some furniture.  The task puts some
items into goal containers; the robot's domain lacks one or two of the
human's skills, so the robot cannot plan for it:

* ``no-push``: the robot cannot push an obstacle aside; the goal containers
  are blocked (the paper's Kitchen II), the excuse clears them;
* ``no-open``: the robot cannot open drawers; the goal drawers are closed
  (Kitchen I), the excuse opens them;
* ``no-open-no-push``: both; the goal drawers are closed and blocked;
* ``no-door``: the robot cannot open cupboard doors; the goal containers
  are closed cupboards.

Generation is deterministic: the same parameters give byte-identical PDDL.
The module only builds text; the benchmark script writes the files.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

#: The human's skills; robot domains drop some of them (see :data:`VARIANTS`).
ACTIONS: dict[str, str] = {
    "take": """
  ;; Take an item from a surface that nothing blocks.
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (clear ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))
""",
    "put_on": """
  ;; Put the held item on a surface that nothing blocks.
  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i) (clear ?s))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))
""",
    "put_inside": """
  ;; Put the held item into an open container that nothing blocks.
  (:action put_inside
    :parameters (?i - item ?c - container)
    :precondition (and (in_hand ?i) (open ?c) (clear ?c))
    :effect (and (inside ?i ?c) (hand_free) (not (in_hand ?i))))
""",
    "take_out": """
  ;; Take an item out of an open container that nothing blocks.
  (:action take_out
    :parameters (?i - item ?c - container)
    :precondition (and (graspable ?i) (inside ?i ?c) (open ?c) (clear ?c) (hand_free))
    :effect (and (in_hand ?i) (not (inside ?i ?c)) (not (hand_free))))
""",
    "open_drawer": """
  ;; Open a closed drawer that nothing blocks.
  (:action open_drawer
    :parameters (?d - drawer)
    :precondition (and (clear ?d) (hand_free) (not (open ?d)))
    :effect (open ?d))
""",
    "close_drawer": """
  ;; Close an open drawer that nothing blocks.
  (:action close_drawer
    :parameters (?d - drawer)
    :precondition (and (open ?d) (clear ?d) (hand_free))
    :effect (not (open ?d)))
""",
    "open_door": """
  ;; Open the door of a cupboard that nothing blocks.
  (:action open_door
    :parameters (?c - cupboard)
    :precondition (and (clear ?c) (hand_free) (not (open ?c)))
    :effect (open ?c))
""",
    "close_door": """
  ;; Close the door of a cupboard that nothing blocks.
  (:action close_door
    :parameters (?c - cupboard)
    :precondition (and (open ?c) (clear ?c) (hand_free))
    :effect (not (open ?c)))
""",
    "push_aside": """
  ;; Push an obstacle (a chair, a box) away from the furniture it blocks.
  (:action push_aside
    :parameters (?o - obstacle ?f - furniture)
    :precondition (and (blocking ?o ?f) (hand_free))
    :effect (and (not (blocking ?o ?f)) (clear ?f)))
""",
}

#: Robot variants: the skills each lacks.
VARIANTS: dict[str, tuple[str, ...]] = {
    "no-push": ("push_aside",),
    "no-open": ("open_drawer",),
    "no-open-no-push": ("open_drawer", "push_aside"),
    "no-door": ("open_door",),
}

#: What the robot of each variant cannot do, in words (plot titles and captions).
VARIANT_TEXT: dict[str, str] = {
    "no-push": "cannot push obstacles aside",
    "no-open": "cannot open drawers",
    "no-open-no-push": "cannot open drawers or push obstacles aside",
    "no-door": "cannot open cupboard doors",
}

#: The sizes a task name carries (:attr:`House.name`), in its order: (letter, what the number counts).
NAME_PARTS: tuple[tuple[str, str], ...] = (
    ("r", "rooms"), ("i", "items"), ("d", "drawers"), ("c", "cupboards"),
    ("g", "goals (items to put into a goal container)"),
)

_NAME = re.compile(r"house-" + "-".join(rf"{letter}(\d+)" for letter, _ in NAME_PARTS) + r"-(.+)")

_HEADER = """(define (domain household)
  (:requirements :strips :typing :negative-preconditions)
  (:types item furniture obstacle - object
          surface container - furniture
          drawer cupboard - container)
  (:predicates (on_top ?i - item ?s - surface)
               (inside ?i - item ?c - container)
               (open ?c - container)
               (clear ?f - furniture)
               (graspable ?i - item)
               (in_hand ?i - item)
               (hand_free)
               (blocking ?o - obstacle ?f - furniture))
"""


def domain_pddl(variant: str | None = None) -> str:
    """The household domain: the human's (``None``) or a robot variant's (see :data:`VARIANTS`)."""
    missing = VARIANTS[variant] if variant else ()
    who = "the human: every skill" if variant is None else f"robot '{variant}': without {', '.join(missing)}"
    lines = [f";; Household domain ({who}). Generated by guided_lfd.household.\n", _HEADER]
    lines += [text for name, text in ACTIONS.items() if name not in missing]
    lines.append(")\n")
    return "".join(lines)


@dataclass(frozen=True)
class House:
    """Parameters of one household task."""

    rooms: int
    items: int
    drawers_per_room: int
    cupboards_per_room: int = 0
    goals: int = 4
    variant: str = "no-push"

    @property
    def drawers(self) -> int:
        """Drawers in the whole house."""
        return self.rooms * self.drawers_per_room

    @property
    def name(self) -> str:
        """A task name that says its size: ``house-r16-i64-d64-c0-g4-no-push``."""
        sizes = (self.rooms, self.items, self.drawers, self.rooms * self.cupboards_per_room, self.goals)
        return f"house-{size_tag(sizes)}-{self.variant}"

    def check(self) -> None:
        """Refuse parameters that make no task (ValueError)."""
        if self.variant not in VARIANTS:
            raise ValueError(f"unknown variant '{self.variant}' (expected one of: {', '.join(VARIANTS)})")
        if self.rooms < 1 or self.items < 1 or self.goals < 1:
            raise ValueError("a house needs at least one room, one item and one goal")
        if self.goals > self.items:
            raise ValueError(f"{self.goals} goals need at least as many items (got {self.items})")
        targets = self.rooms * (self.cupboards_per_room if self.variant == "no-door" else self.drawers_per_room)
        if self.goals > targets:
            raise ValueError(f"{self.goals} goals need at least as many goal containers (got {targets})")


def size_tag(sizes: tuple[int, ...]) -> str:
    """The sizes part of a task name (``r16-i64-d64-c0-g4``), sizes in :data:`NAME_PARTS` order."""
    return "-".join(f"{letter}{n}" for (letter, _), n in zip(NAME_PARTS, sizes))


def name_sizes(name: str) -> tuple[tuple[int, ...], str] | None:
    """The sizes (in :data:`NAME_PARTS` order) and the variant a task name (:attr:`House.name`) says; None for
    a name that is not a house's."""
    found = _NAME.fullmatch(name)
    return None if found is None else (tuple(int(n) for n in found.groups()[:-1]), found.groups()[-1])


def problem_pddl(house: House) -> str:
    """The household problem for ``house`` (deterministic)."""
    house.check()
    rooms = range(1, house.rooms + 1)
    tables = [f"table{r}" for r in rooms]
    counters = [f"counter{r}" for r in rooms]
    drawers = [f"drawer{r}_{k}" for r in rooms for k in range(1, house.drawers_per_room + 1)]
    cupboards = [f"cupboard{r}_{k}" for r in rooms for k in range(1, house.cupboards_per_room + 1)]
    items = [f"{'plate' if n % 2 else 'cup'}{n}" for n in range(1, house.items + 1)]
    pool = cupboards if house.variant == "no-door" else drawers
    goal_containers, goal_items = _goal_choice(house, pool, items)
    blocked = set(goal_containers) if house.variant in ("no-push", "no-open-no-push") else set()
    closed_goal = house.variant in ("no-open", "no-open-no-push", "no-door")
    obstacles = [f"chair{k}" for k in range(1, len(blocked) + 1)]
    # A few boxes block counters too: obstacles the robot can live with.
    boxes = [f"box{r}" for r in rooms if r % 4 == 0]
    chairs = dict(zip(sorted(blocked, key=pool.index), obstacles))
    init = _initial_atoms(items, tables, counters, boxes, drawers + cupboards, chairs,
                          goal_containers if closed_goal else [])
    goal = [f"(inside {i} {c})" for i, c in zip(goal_items, goal_containers)]
    objects = [(items, "item"), (tables + counters, "surface"), (drawers, "drawer"), (cupboards, "cupboard"),
               (obstacles + boxes, "obstacle")]
    return _problem_text(house, len(drawers), len(cupboards), objects, init, goal)


def _goal_choice(house: House, pool: list[str], items: list[str]) -> tuple[list[str], list[str]]:
    """The goal containers (from ``pool``) and goal items, spread evenly over the house."""
    # Goal containers spread over the house: one every few rooms.
    step = max(1, len(pool) // house.goals)
    goal_containers = [pool[k * step] for k in range(house.goals)]
    # Goal items likewise: every few items, so they lie on different tables.
    istep = max(1, len(items) // house.goals)
    goal_items = [items[k * istep] for k in range(house.goals)]
    return goal_containers, goal_items


def _initial_atoms(items: list[str], tables: list[str], counters: list[str], boxes: list[str],
                   containers: list[str], chairs: dict[str, str], closed: list[str]) -> list[str]:
    """The initial state: items on the tables, what blocks what, which containers are clear and open.

    ``chairs`` maps a blocked container to its chair; the drawers in ``closed`` start closed.
    """
    init: list[str] = ["(hand_free)"]
    for n, item in enumerate(items):
        init.append(f"(graspable {item})")
        # Items lie in blocks, room by room, so goal items are on different tables.
        init.append(f"(on_top {item} {tables[n * len(tables) // len(items)]})")
    for f in tables:
        init.append(f"(clear {f})")
    box_of = {counters[int(b[3:]) - 1]: b for b in boxes}
    for f in counters:
        if f in box_of:
            init.append(f"(blocking {box_of[f]} {f})")
        else:
            init.append(f"(clear {f})")
    for c in containers:
        if c in chairs:
            init.append(f"(blocking {chairs[c]} {c})")
        else:
            init.append(f"(clear {c})")
        # Drawers start open except the goal ones when the robot cannot open
        # them; cupboards start closed (doors), goal ones too under no-door.
        if c.startswith("drawer") and c not in closed:
            init.append(f"(open {c})")
    return init


def _problem_text(house: House, n_drawers: int, n_cupboards: int, objects: list[tuple[list[str], str]],
                  init: list[str], goal: list[str]) -> str:
    """The PDDL text: a header comment, the objects by type (``(names, type)``), the initial state and the goal."""
    def block(names: list[str], kind: str) -> str:
        return f"    {' '.join(names)} - {kind}\n" if names else ""

    text = [
        f";; {house.rooms} rooms, {house.items} items, {n_drawers} drawers, {n_cupboards} cupboards; "
        f"{house.goals} goal items; robot variant {house.variant} ({', '.join(VARIANTS[house.variant])} missing).\n",
        ";; Generated by guided_lfd.household.\n",
        f"(define (problem {house.name})\n  (:domain household)\n  (:objects\n",
        *(block(names, kind) for names, kind in objects),
        "  )\n  (:init\n",
        "".join(f"    {a}\n" for a in init),
        "  )\n  (:goal (and\n",
        "".join(f"    {g}\n" for g in goal),
        "  ))\n)\n",
    ]
    return "".join(text)


#: The scaling series: (rooms, items, drawers per room, cupboards per room, goals).
SERIES: list[tuple[int, int, int, int, int]] = [
    (1, 2, 2, 0, 1),
    (2, 4, 2, 1, 1),
    (4, 8, 2, 1, 2),
    (4, 16, 4, 1, 2),
    (8, 32, 4, 1, 4),
    (16, 64, 4, 1, 4),
    (32, 128, 4, 1, 4),
    (32, 256, 8, 1, 4),
]

#: The widest house the scaling run adds to :data:`SERIES`: 64 rooms of 4 drawers, 256 items, 8 goal drawers
#: (about 200,000 ground actions, 8 changes in its minimal excuse).
WIDE_HOUSE: tuple[int, int, int, int, int] = (64, 256, 4, 0, 8)
