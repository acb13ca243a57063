"""A picture of an excuse: the initial state and the excuse state side by side (``excuse --svg``/``--dot``).

Objects are nodes, binary facts labelled arrows between them, unary facts
lines inside their object's box, and facts of no or of three and more objects
a list under each panel.  Facts the excuse adds are green and bold (``+``),
facts it removes red and dashed (``−``), the others grey.  A large world is
cut to the objects the changes and the goal name, and their neighbours; the
caption says how many objects and facts were left out.

:func:`excuse_scene` chooses what is shown; :func:`scene_dot` writes it as
Graphviz DOT and :func:`guided_lfd.excuse.svg.scene_svg` draws it as SVG
(written directly, with a deterministic circle layout: no Graphviz needed,
and the same excuse gives the same bytes).
"""

from __future__ import annotations

import html
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from guided_lfd.excuse.change import Change, describe_change
from guided_lfd.pddl.model import Atom, Domain, Problem

if TYPE_CHECKING:
    from guided_lfd.excuse.report import ExcuseReport

__all__ = ["ADDED", "REMOVED", "SAME", "COLOURS", "MAX_OBJECTS", "Fact", "Panel", "Scene", "excuse_scene",
           "scene_dot"]

ADDED, REMOVED, SAME = "added", "removed", "same"
#: How a fact's label starts, by its mark.
PREFIX = {ADDED: "+ ", REMOVED: "\u2212 ", SAME: ""}
#: Line or text colour, by mark (GitHub's accessible green, red and grey).
COLOURS = {ADDED: "#1a7f37", REMOVED: "#cf222e", SAME: "#6e7781"}
#: Highlight behind a changed fact's label, by mark.
BACKGROUNDS = {ADDED: "#dafbe1", REMOVED: "#ffebe9", SAME: "#ffffff"}
#: Worlds with more objects than this show only those near the changes and the goal.
MAX_OBJECTS = 16


@dataclass(frozen=True)
class Fact:
    """A fact drawn in a panel, and whether the excuse adds it, removes it, or leaves it (``mark``)."""

    atom: Atom
    mark: str

    @property
    def title(self) -> str:
        """The fact in PDDL, as a change when it is one: ``+(clear pinkdrawer)``."""
        return {ADDED: "+", REMOVED: "-"}.get(self.mark, "") + str(self.atom)

    @property
    def shape(self) -> str:
        """Where it is drawn: ``edge`` (two objects), ``node`` (one object, or one object twice), ``list``."""
        args = self.atom.args
        if len(args) == 2 and args[0] != args[1]:
            return "edge"
        return "node" if len(args) in (1, 2) else "list"


@dataclass
class Panel:
    """One side of the picture: its title and the facts drawn in it."""

    title: str
    facts: list[Fact]

    @property
    def listed(self) -> list[Fact]:
        """The facts listed under the panel (no object, or more than two)."""
        return [f for f in self.facts if f.shape == "list"]

    @property
    def inside(self) -> dict[str, list[Fact]]:
        """Each object's facts drawn inside its box (its unary facts)."""
        out: dict[str, list[Fact]] = {}
        for fact in self.facts:
            if fact.shape == "node":
                out.setdefault(fact.atom.args[0], []).append(fact)
        return out


@dataclass
class Scene:
    """What the picture shows: a headline, notes, the objects (in layout order) and one or two panels."""

    headline: str
    notes: list[str]
    objects: list[str]
    types: dict[str, str]
    panels: list[Panel]
    hidden_objects: int = 0
    hidden_facts: int = 0
    spellings: dict[str, str] = field(default_factory=dict)
    #: Objects a change of the excuse names (their boxes are drawn darker).
    touched: frozenset[str] = frozenset()

    def name(self, obj: str) -> str:
        """An object or predicate as the files write it (``PinkDrawer``)."""
        return self.spellings.get(obj, obj)

    def label(self, fact: Fact) -> str:
        """A fact's text in the picture: ``+ clear``, ``on_top``, ``− blocking itself``, ``at(A, B, C)``."""
        pred = self.name(fact.atom.predicate)
        args = fact.atom.args
        if fact.shape == "node" and len(args) == 2:
            text = f"{pred} itself"
        elif fact.shape == "list" and args:
            text = f"{pred}({', '.join(self.name(a) for a in args)})"
        else:
            text = pred
        return PREFIX[fact.mark] + text

    @property
    def caption(self) -> str | None:
        """What was left out, in one line (None when every object is shown)."""
        if not self.hidden_objects:
            return None
        objects = "object" if self.hidden_objects == 1 else "objects"
        return (f"Not shown: {self.hidden_objects} {objects} and {self.hidden_facts} fact(s) about them, unchanged "
                f"by the excuse (shown: the objects the changes and the goal name, and their neighbours)")


def excuse_scene(report: ExcuseReport, max_objects: int = MAX_OBJECTS) -> Scene:
    """The picture of ``report``'s first excuse: the initial state | the excuse state.

    Without an excuse (already solvable, none found, out of time) the scene
    has the initial state alone, and its headline says why.  A world of more
    than ``max_objects`` objects is cut to those the changes and the goal
    name (all of them) and their neighbours (up to ``max_objects`` in all).
    """
    problem = report.problem
    if problem is None:
        raise ValueError("a report made without its problem has no picture")
    spellings = report.spellings
    excuse = report.excuse
    changes = excuse.changes if excuse is not None else []
    added = {c.atom for c in changes if c.added}
    removed = {c.atom for c in changes if not c.added}
    after = excuse.state if excuse is not None else problem.init
    both = problem.init | after
    every = _objects(report.domain, problem, both)
    seeds = [a for c in changes for a in c.atom.args] + [a for g in problem.goal for a in g.atom.args]
    shown = _layout_order(sorted(every), [s for s in seeds if s in every], _links(both), max_objects)
    visible = set(shown)
    mark = {**dict.fromkeys(added, ADDED), **dict.fromkeys(removed, REMOVED)}

    def facts(atoms: frozenset[Atom] | set[Atom]) -> list[Fact]:
        return [Fact(a, mark.get(a, SAME)) for a in sorted(atoms) if visible.issuperset(a.args)]

    panels = [Panel("Initial state", facts(problem.init))]
    if excuse is not None:
        panels.append(Panel("Excuse state (the initial state with the changes)", facts(after | removed)))
    hidden = sum(1 for a in both if not visible.issuperset(a.args))
    return Scene(_headline(report, problem), _notes(report, problem), shown, every, panels,
                 hidden_objects=len(every) - len(shown), hidden_facts=hidden, spellings=spellings,
                 touched=frozenset(a for c in changes for a in c.atom.args))


def _objects(domain: Domain | None, problem: Problem, atoms: frozenset[Atom]) -> dict[str, str]:
    """Every object of the task (constants included, and any an atom names) and its type."""
    types = {**(domain.constants if domain is not None else {}), **problem.objects}
    for atom in atoms:
        for arg in atom.args:
            types.setdefault(arg, "object")
    return types


def _links(atoms: frozenset[Atom]) -> dict[str, set[str]]:
    """Which objects share a fact with which."""
    out: dict[str, set[str]] = {}
    for atom in atoms:
        for a in atom.args:
            out.setdefault(a, set()).update(b for b in atom.args if b != a)
    return out


def _layout_order(every: list[str], seeds: list[str], links: dict[str, set[str]], max_objects: int) -> list[str]:
    """The objects shown, in the order they go round the circle: depth-first from the seeds (the objects the
    changes and the goal name), so that a chain of related objects sits side by side.

    A world of at most ``max_objects`` objects is shown whole; a larger one only the seeds and their
    neighbours, at most ``max_objects`` of them (the seeds always)."""
    small = len(every) <= max_objects
    order: list[str] = []
    seen: set[str] = set()
    for start in [*dict.fromkeys(seeds), *(every if small else [])]:
        stack = [(start, 0)]
        while stack:
            obj, depth = stack.pop()
            if obj in seen:
                continue
            seen.add(obj)
            order.append(obj)
            if small or depth == 0:
                stack += [(other, depth + 1) for other in sorted(links.get(obj, ()), reverse=True)]
    if small:
        return order
    keep = set(seeds) | set([obj for obj in order if obj not in seeds][:max(0, max_objects - len(set(seeds)))])
    return [obj for obj in order if obj in keep]


def _headline(report: ExcuseReport, problem: Problem) -> str:
    """What the picture is about, in one line."""
    from guided_lfd.excuse.document import excuse_summary
    from guided_lfd.excuse.status import ExcuseStatus

    spellings = report.spellings
    name = spellings.get(problem.name, problem.name)
    if report.excuse is not None:
        asked = "; ".join(describe_change(c, spellings) for c in report.excuse.changes)
        return f"Excuse for {name}: demonstrate how to reach {asked}"
    if report.status is ExcuseStatus.ALREADY_SOLVABLE:
        return f"{name}: already solvable, no excuse needed"
    return f"{name}: {excuse_summary(report, spellings)}"


def _notes(report: ExcuseReport, problem: Problem) -> list[str]:
    """The lines under the headline: the goal, and the excuse's size and semantics."""
    notes = ["Goal: " + "; ".join(describe_change(Change(g.atom, g.positive), report.spellings)
                                  for g in problem.goal)]
    excuse = report.excuse
    if excuse is not None:
        which = f"the first of {len(report.excuses)} excuses listed; " if len(report.excuses) > 1 else ""
        notes.append(f"{which}{excuse.size} change(s), cost {excuse.cost}, {report.semantics.value} semantics; "
                     f"then the robot's own plan of {len(excuse.plan)} step(s)")
    return notes


def _dot_string(text: str) -> str:
    """``text`` as a quoted DOT string."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


#: DOT edge attributes, by mark: added bold, removed dashed.
_DOT_EDGE = {ADDED: "style=bold, penwidth=2.5", REMOVED: "style=dashed, penwidth=1.5", SAME: "penwidth=1"}


def scene_dot(scene: Scene) -> str:
    """The scene as Graphviz DOT text: one cluster per panel, the changed facts coloured as in the SVG."""
    label = "\n".join([scene.headline, *scene.notes, *([scene.caption] if scene.caption else [])])
    lines = ["digraph excuse {",
             f"  graph [fontname=Helvetica, labelloc=t, labeljust=l, label={_dot_string(label)}];",
             '  node [fontname=Helvetica, shape=box, style="rounded,filled", fillcolor="#f6f8fa", color="#8c959f"];',
             "  edge [fontname=Helvetica, fontsize=11];"]
    for k, panel in enumerate(scene.panels):
        lines += [f"  subgraph cluster_{k} {{", f"    label={_dot_string(panel.title)};"]
        lines += _dot_nodes(scene, panel, k)
        ids = {obj: f"p{k}_{i}" for i, obj in enumerate(scene.objects)}
        for fact in panel.facts:
            if fact.shape == "edge":
                a, b = fact.atom.args
                lines.append(f"    {ids[a]} -> {ids[b]} [label={_dot_string(scene.label(fact))}, "
                             f'color="{COLOURS[fact.mark]}", fontcolor="{COLOURS[fact.mark]}", '
                             f"{_DOT_EDGE[fact.mark]}, tooltip={_dot_string(fact.title)}];")
        lines.append("  }")
    return "\n".join(lines + ["}"]) + "\n"


def _dot_nodes(scene: Scene, panel: Panel, k: int) -> list[str]:
    """The panel's object nodes (unary facts as coloured lines of an HTML label) and its list of other facts."""
    inside = panel.inside
    out = []
    for i, obj in enumerate(scene.objects):
        rows = [f"<B>{html.escape(scene.name(obj))}</B>", f'<FONT POINT-SIZE="10">{html.escape(scene.types[obj])}</FONT>']
        rows += [_dot_line(scene, f) for f in inside.get(obj, [])]
        border = ', penwidth=2, color="#24292f"' if obj in scene.touched else ""
        out.append(f"    p{k}_{i} [label=<{'<BR/>'.join(rows)}>{border}];")
    listed = panel.listed
    if listed:
        rows = ["<I>Other facts</I>", *(_dot_line(scene, f) for f in listed)]
        out.append(f"    p{k}_facts [shape=plaintext, style=solid, label=<{'<BR/>'.join(rows)}>];")
    return out


def _dot_line(scene: Scene, fact: Fact) -> str:
    """A fact as a line of an HTML-like DOT label, coloured by its mark (bold when added)."""
    text = html.escape(scene.label(fact))
    if fact.mark == ADDED:
        text = f"<B>{text}</B>"
    return f'<FONT COLOR="{COLOURS[fact.mark]}">{text}</FONT>'
