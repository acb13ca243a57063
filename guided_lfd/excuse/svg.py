"""The excuse picture as SVG, written with :mod:`xml.etree.ElementTree` (no Graphviz, no matplotlib).

Each panel places the objects round a circle (the same places in both
panels, in :attr:`Scene.objects` order), so a change is where the eye
looks for it.  Every fact is a ``<g class="fact added|removed|same">`` whose
``<title>`` is the fact in PDDL (``+(clear pinkdrawer)``): a browser shows
it on hovering, and a program finds the changes by class.  Text widths are
estimated from the number of characters (no font is measured), generously.
"""

from __future__ import annotations

import math
import textwrap
import xml.etree.ElementTree as ET
from dataclasses import dataclass

from guided_lfd.excuse.picture import ADDED, BACKGROUNDS, COLOURS, REMOVED, SAME, Fact, Panel, Scene

__all__ = ["SVG_NAMESPACE", "scene_svg"]

SVG_NAMESPACE = "http://www.w3.org/2000/svg"
FONT = "DejaVu Sans, Verdana, Helvetica, Arial, sans-serif"
SIZE, SMALL, LINE = 13, 11, 18  # font sizes and line height (px)
PAD, GAP, MARGIN = 8, 40, 24  # inside a box, between the panels, round a panel
SPACING = 100  # between neighbouring boxes on the circle: room for an arrow and its label
EDGE_SPACING = 24  # between the labels of facts about the same two objects
MIN_RADIUS = 120  # room in the circle for the arrows' labels
#: Stroke width and dash pattern of an arrow, by mark.
_STROKES = {ADDED: ("2.5", None), REMOVED: ("1.8", "6 4"), SAME: ("1.2", None)}
#: The legend's entries.
_LEGEND = ((ADDED, "+ added by the excuse"), (REMOVED, "\u2212 removed by the excuse"), (SAME, "unchanged"))


def _text_width(text: str, size: float = SIZE, bold: bool = False) -> float:
    """An estimate of ``text``'s width in px (wide enough for DejaVu Sans, the widest usual face)."""
    return len(text) * size * (0.66 if bold else 0.6)


def _num(value: float) -> str:
    """A coordinate with at most one decimal (the same bytes on every machine)."""
    text = f"{value:.1f}"
    return text[:-2] if text.endswith(".0") else text


@dataclass(frozen=True)
class _Box:
    """An object's box: centre and size."""

    x: float
    y: float
    w: float
    h: float

    def border(self, towards_x: float, towards_y: float) -> tuple[float, float]:
        """Where the line from the centre towards a point leaves the box (a little outside it)."""
        dx, dy = towards_x - self.x, towards_y - self.y
        length = math.hypot(dx, dy) or 1.0
        ux, uy = dx / length, dy / length
        t = min(self.w / 2 / abs(ux) if ux else math.inf, self.h / 2 / abs(uy) if uy else math.inf) + 3
        return self.x + t * ux, self.y + t * uy


@dataclass(frozen=True)
class _Layout:
    """Where everything goes: the boxes (panel coordinates), the panel's size, the header's lines."""

    boxes: dict[str, _Box]
    width: float
    circle: float  # height of the circle's area
    listed: int  # lines of the longest list of other facts
    header: list[str]

    @property
    def height(self) -> float:
        """A panel's height: title, circle, list of other facts."""
        return 30 + self.circle + ((self.listed + 1) * LINE if self.listed else 0) + PAD


def _layout(scene: Scene) -> _Layout:
    """Box sizes (the larger of the two panels'), their places on the circle, and the header wrapped to fit."""
    texts = {obj: [scene.name(obj), scene.types[obj]] for obj in scene.objects}
    rows = dict.fromkeys(scene.objects, 2)  # name, type, then the most unary facts either panel has
    for panel in scene.panels:
        for obj, facts in panel.inside.items():
            rows[obj] = max(rows[obj], 2 + len(facts))
            texts[obj] += [scene.label(f) for f in facts]
    sizes = {obj: (max(_text_width(t, bold=True) for t in texts[obj]) + 2 * PAD + 8, 2 * PAD + LINE * rows[obj])
             for obj in scene.objects}
    n = len(scene.objects)
    widths = [sizes[obj][0] for obj in scene.objects]
    radius = 0.0
    if n > 1:  # adjacent boxes on the circle must not overlap, even side by side
        chord = max((widths[i] + widths[(i + 1) % n]) / 2 + SPACING for i in range(n))
        radius = max(MIN_RADIUS, chord / (2 * math.sin(math.pi / n)))
    start = math.pi if n == 2 else -math.pi / 2
    widest = max(widths, default=0.0)
    tallest = max((sizes[obj][1] for obj in scene.objects), default=0.0)
    width = 2 * radius + widest + 2 * MARGIN
    width = max([width, *(_text_width(scene.label(f)) + 2 * MARGIN for p in scene.panels for f in p.listed)])
    boxes = {}
    for i, obj in enumerate(scene.objects):
        angle = start + 2 * math.pi * i / n
        boxes[obj] = _Box(width / 2 + radius * math.cos(angle), MARGIN + tallest / 2 + radius + radius * math.sin(angle),
                          *sizes[obj])
    total = len(scene.panels) * width + (len(scene.panels) - 1) * GAP
    chars = max(60, int(total / (SIZE * 0.6)))
    header = textwrap.wrap(scene.headline, chars) + [line for note in scene.notes for line in textwrap.wrap(note, chars)]
    longest = max(len(p.listed) for p in scene.panels)
    return _Layout(boxes, width, 2 * radius + tallest + 2 * MARGIN, longest, header)


def scene_svg(scene: Scene) -> str:
    """The scene as an SVG document (UTF-8 text): the header, the panels side by side, the caption, a legend."""
    layout = _layout(scene)
    panels = len(scene.panels)
    width = 2 * MARGIN + panels * layout.width + (panels - 1) * GAP
    top = MARGIN + LINE * len(layout.header) + PAD
    caption = textwrap.wrap(scene.caption, max(60, int((width - 2 * MARGIN) / (SMALL * 0.6)))) if scene.caption else []
    height = top + layout.height + LINE * len(caption) + 2 * LINE + MARGIN
    svg = ET.Element("svg", {"xmlns": SVG_NAMESPACE, "width": _num(width), "height": _num(height),
                             "viewBox": f"0 0 {_num(width)} {_num(height)}", "font-family": FONT,
                             "font-size": str(SIZE)})
    ET.SubElement(svg, "title").text = scene.headline
    _markers(ET.SubElement(svg, "defs"))
    ET.SubElement(svg, "rect", {"width": "100%", "height": "100%", "fill": "#ffffff"})
    for i, line in enumerate(layout.header):
        _text(svg, MARGIN, MARGIN + LINE * i + SIZE, line, weight="bold" if i == 0 else None,
              cls="headline" if i == 0 else "note", size=SIZE + 2 if i == 0 else SIZE)
    for k, panel in enumerate(scene.panels):
        group = ET.SubElement(svg, "g", {"class": f"panel panel-{k + 1}",
                                         "transform": f"translate({_num(MARGIN + k * (layout.width + GAP))},{_num(top)})"})
        _panel(group, scene, panel, layout)
    y = top + layout.height
    for i, line in enumerate(caption):
        _text(svg, MARGIN, y + LINE * i + SMALL, line, fill=COLOURS[SAME], size=SMALL, cls="caption")
    _legend(svg, y + LINE * len(caption) + LINE)
    ET.indent(svg)
    text = '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(svg, encoding="unicode") + "\n"
    # Plain ASCII (the minus sign as &#8722;): any console or file encoding takes it.
    return text.encode("ascii", "xmlcharrefreplace").decode("ascii")


def _text(parent: ET.Element, x: float, y: float, text: str, fill: str = "#24292f", size: int = SIZE,
          weight: str | None = None, anchor: str | None = None, cls: str | None = None) -> ET.Element:
    """A ``<text>`` element."""
    attrs = {"x": _num(x), "y": _num(y), "fill": fill}
    if size != SIZE:
        attrs["font-size"] = str(size)
    if weight:
        attrs["font-weight"] = weight
    if anchor:
        attrs["text-anchor"] = anchor
    if cls:
        attrs["class"] = cls
    element = ET.SubElement(parent, "text", attrs)
    element.text = text
    return element


def _markers(defs: ET.Element) -> None:
    """An arrowhead per mark, in its colour."""
    for mark, colour in COLOURS.items():
        marker = ET.SubElement(defs, "marker", {"id": f"arrow-{mark}", "viewBox": "0 0 10 10", "refX": "9",
                                                "refY": "5", "markerWidth": "7", "markerHeight": "7",
                                                "orient": "auto", "markerUnits": "userSpaceOnUse"})
        ET.SubElement(marker, "path", {"d": "M0,0 L10,5 L0,10 z", "fill": colour})


def _fact_group(parent: ET.Element, fact: Fact) -> ET.Element:
    """The ``<g class="fact MARK">`` a fact is drawn in, titled with the fact in PDDL."""
    group = ET.SubElement(parent, "g", {"class": f"fact {fact.mark}"})
    ET.SubElement(group, "title").text = fact.title
    return group


def _label(parent: ET.Element, x: float, y: float, text: str, mark: str, anchor: str = "middle") -> None:
    """A fact's label: changed ones on a highlight (solid for added, dashed for removed) in their colour."""
    width = _text_width(text, bold=mark == ADDED) + 8
    left = x - width / 2 if anchor == "middle" else x - 4
    rect = {"x": _num(left), "y": _num(y - SIZE + 1), "width": _num(width), "height": _num(SIZE + 4), "rx": "3",
            "fill": BACKGROUNDS[mark], "fill-opacity": "0.92"}
    if mark != SAME:
        rect.update({"stroke": COLOURS[mark], "stroke-width": "1"})
        if mark == REMOVED:
            rect["stroke-dasharray"] = "3 2"
    ET.SubElement(parent, "rect", rect)
    _text(parent, x, y, text, fill=COLOURS[mark] if mark != SAME else "#57606a",
          weight="bold" if mark == ADDED else None, anchor=anchor if anchor == "middle" else None)


def _panel(group: ET.Element, scene: Scene, panel: Panel, layout: _Layout) -> None:
    """A panel: its title, the arrows, the boxes with their unary facts, the list of other facts."""
    _text(group, layout.width / 2, 18, panel.title, weight="bold", anchor="middle", cls="panel-title", size=SIZE + 1)
    body = ET.SubElement(group, "g", {"transform": "translate(0,30)"})
    if not scene.objects:
        _text(body, layout.width / 2, layout.circle / 2, "(no objects)", fill=COLOURS[SAME], anchor="middle")
    inside = panel.inside
    for obj in scene.objects:
        _box(body, scene, obj, inside.get(obj, []), layout.boxes[obj])
    _arrows(body, scene, panel, layout.boxes)  # over the boxes: no box hides a label
    listed = panel.listed
    if listed:
        y = layout.circle + SIZE
        _text(body, MARGIN, y, "Other facts:", fill="#57606a", weight="bold")
        for i, fact in enumerate(listed, 1):
            _label(_fact_group(body, fact), MARGIN + 4, y + i * LINE, scene.label(fact), fact.mark, anchor="start")


def _arrows(parent: ET.Element, scene: Scene, panel: Panel, boxes: dict[str, _Box]) -> None:
    """Each binary fact as an arrow from its first object to its second, labelled with the predicate; facts about
    the same two objects (either way round, in either panel) bend apart, each at its own place in both panels."""
    between: dict[tuple[str, ...], list[Fact]] = {}
    for fact in sorted({f.atom: f for p in scene.panels for f in p.facts if f.shape == "edge"}.values(),
                       key=lambda f: f.atom):
        between.setdefault(tuple(sorted(fact.atom.args)), []).append(fact)
    marks = {f.atom: f.mark for f in panel.facts}
    for (first, second), facts in between.items():
        p, q = boxes[first], boxes[second]
        length = math.hypot(q.x - p.x, q.y - p.y) or 1.0
        nx, ny = -(q.y - p.y) / length, (q.x - p.x) / length  # the normal of the pair's line
        for k, fact in enumerate(facts):
            mark = marks.get(fact.atom)
            if mark is None:  # a fact of the other panel only
                continue
            offset = (k - (len(facts) - 1) / 2) * EDGE_SPACING
            mx, my = (p.x + q.x) / 2 + offset * nx, (p.y + q.y) / 2 + offset * ny
            cx, cy = 2 * mx - (p.x + q.x) / 2, 2 * my - (p.y + q.y) / 2  # the curve passes through (mx, my)
            a, b = boxes[fact.atom.args[0]], boxes[fact.atom.args[1]]
            (sx, sy), (ex, ey) = a.border(cx, cy), b.border(cx, cy)
            width, dash = _STROKES[mark]
            attrs = {"d": f"M{_num(sx)},{_num(sy)} Q{_num(cx)},{_num(cy)} {_num(ex)},{_num(ey)}", "fill": "none",
                     "stroke": COLOURS[mark], "stroke-width": width, "marker-end": f"url(#arrow-{mark})"}
            if dash:
                attrs["stroke-dasharray"] = dash
            drawn = Fact(fact.atom, mark)
            group = _fact_group(parent, drawn)
            ET.SubElement(group, "path", attrs)
            _label(group, mx, my + SIZE / 2 - 1, scene.label(drawn), mark)


def _box(parent: ET.Element, scene: Scene, obj: str, inside: list[Fact], box: _Box) -> None:
    """An object's box: its name, its type, and its unary facts one per line."""
    touched = obj in scene.touched
    group = ET.SubElement(parent, "g", {"class": "object", "data-object": obj})
    ET.SubElement(group, "title").text = f"{obj} - {scene.types[obj]}"
    left, top = box.x - box.w / 2, box.y - box.h / 2
    ET.SubElement(group, "rect", {"x": _num(left), "y": _num(top), "width": _num(box.w), "height": _num(box.h),
                                  "rx": "6", "fill": "#f6f8fa", "stroke": "#24292f" if touched else "#8c959f",
                                  "stroke-width": "2" if touched else "1"})
    _text(group, left + PAD, top + PAD + SIZE, scene.name(obj), weight="bold")
    _text(group, left + PAD, top + PAD + LINE + SMALL, scene.types[obj], fill=COLOURS[SAME], size=SMALL)
    for i, fact in enumerate(inside, 2):
        _label(_fact_group(group, fact), left + PAD + 4, top + PAD + LINE * i + SIZE, scene.label(fact), fact.mark,
               anchor="start")


def _legend(svg: ET.Element, y: float) -> None:
    """What the colours mean: a short line of each kind and its words."""
    group = ET.SubElement(svg, "g", {"class": "legend"})
    x = float(MARGIN)
    for mark, words in _LEGEND:
        width, dash = _STROKES[mark]
        attrs = {"x1": _num(x), "y1": _num(y - 4), "x2": _num(x + 36), "y2": _num(y - 4), "stroke": COLOURS[mark],
                 "stroke-width": width, "marker-end": f"url(#arrow-{mark})"}
        if dash:
            attrs["stroke-dasharray"] = dash
        ET.SubElement(group, "line", attrs)
        _text(group, x + 44, y, words, fill=COLOURS[mark], weight="bold" if mark == ADDED else None)
        x += 44 + _text_width(words) + 32
