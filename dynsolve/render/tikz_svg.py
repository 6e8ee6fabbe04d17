r"""Draw the figure modules' TikZ pictures as inline SVG: the SVG back end of the figures.

The scene figure (:mod:`dynsolve.render.scene_figure`), the free-body and kinetic
diagrams (:mod:`dynsolve.render.fbd_tikz`) and the linkage
(:mod:`dynsolve.render.linkage_figure`) compute their geometry once and write it as a
small, fixed vocabulary of one-line TikZ commands in millimetres: ``\draw`` and ``\fill``
paths of points, ``--``, ``circle``, ``rectangle`` and ``arc``, relative ``++`` steps,
``node``\ s with an anchor, and ``\node ... at``. That drawing list is read back here and
drawn as SVG (y up becomes y down), so a page shows exactly what the PDF shows. Labels
(``$I_{G} \, \alpha$``, ``\textit{drum}``, ``$\qty{0.4}{m}$``) become text with
subscripts and superscripts as ``tspan``\ s. Anything outside the vocabulary raises
:class:`ValueError`, so a new TikZ command cannot be dropped silently.

>>> svg = svg_pictures(r'''\begin{tikzpicture}[x=1mm,y=1mm]
... \draw[thick,->] (0,0) -- (10,0) node[anchor=180] {$F_{A}$};
... \end{tikzpicture}''')[0]
>>> svg.tag, [e.tag for e in svg.iter()][1:]
('svg', ['path', 'polygon', 'text', 'tspan', 'tspan'])
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass, field

Point = tuple[float, float]
PT_MM = 25.4 / 72.27  # one TeX point in millimetres
FONT_MM = 3.6  # the labels' size (TeX's 10 pt)
SEP_MM = 0.3333 * FONT_MM  # TikZ's default inner sep
PX_PER_MM = 4.2  # the figure on screen: a little larger than print
WIDTHS = {
    "ultra thin": 0.1, "very thin": 0.2, "thin": 0.4, "semithick": 0.6, "thick": 0.8,
    "very thick": 1.2, "ultra thick": 1.6,
}  # fmt: skip  # TikZ line widths in pt
STYLES = {  # fbd_tikz's named styles
    "force": ["thick", "->"],
    "pin": ["thick", "fill=white"],
    "spin": ["semithick", "->"],
    "dimension": ["thin", "<->"],
    "unknown": ["dashed", "red"],
    "kinetic": ["thick", "blue", "->"],
}
COLOURS = {"red": "#d00000", "blue": "#0044cc", "gray": "#808080", "black": "#000", "white": "#fff"}
ANCHORS = {
    "east": 0, "north east": 45, "north": 90, "north west": 135, "west": 180,
    "south west": 225, "south": 270, "south east": 315,
}  # fmt: skip
PLACES = {  # node[left], node[above right]: the anchor they set
    "left": "east", "right": "west", "above": "south", "below": "north",
    "above right": "south west", "above left": "south east", "below right": "north west",
    "below left": "north east",
}  # fmt: skip


def svg_pictures(tikz: str, ident: str = "f") -> list[ET.Element]:
    """Each ``tikzpicture`` in ``tikz`` as an ``<svg>`` element (``ident`` makes the ids
    of its hatch patterns unique on a page)."""
    pictures = re.findall(r"\\begin\{tikzpicture\}.*?\n(.*?)\\end\{tikzpicture\}", tikz, re.S)
    return [_picture(body, f"{ident}-{k}") for k, body in enumerate(pictures)]


# ---- reading the commands


@dataclass
class _Style:
    """What a command's options ask for."""

    width: float = 0.4 * PT_MM
    colour: str = "#000"
    dashed: str = ""  # the SVG dash pattern, "" for a solid line
    fill: str | None = None
    hatch: bool = False
    arrows: str = ""  # "->", "<-", "<->" or ""
    rounded: float = 0.0
    rotate: tuple[float, Point] | None = None
    zigzag: float = 0.0  # the zigzag's amplitude (mm), 0 for a straight line
    stroke: bool = True  # \draw and \filldraw stroke; \fill and \path do not


@dataclass
class _Label:
    """A node: its text (LaTeX), where it is, and the anchor (degrees, or None: centred)."""

    text: str
    at: Point
    anchor: float | None
    shift: float = SEP_MM
    fill: str | None = None
    colour: str = "#000"  # a node on a path takes the path's colour, as in TikZ
    corner: bool = False  # the anchor is a corner of the box (north east, …)


@dataclass
class _Drawing:
    """The SVG elements of one picture and the box they cover (mm, y up)."""

    shapes: list[ET.Element] = field(default_factory=list)
    labels: list[_Label] = field(default_factory=list)
    box: list[float] = field(default_factory=lambda: [math.inf, math.inf, -math.inf, -math.inf])

    def cover(self, *points: Point) -> None:
        for x, y in points:
            self.box = [min(self.box[0], x), min(self.box[1], y),
                        max(self.box[2], x), max(self.box[3], y)]  # fmt: skip


def _commands(body: str) -> Iterator[str]:
    """The picture's commands, split at each ``;`` outside braces."""
    depth, start = 0, 0
    for i, char in enumerate(body):
        if char == "{":
            depth += 1
        elif char == "}":
            depth -= 1
        elif char == ";" and depth == 0:
            command = body[start:i].strip()
            if command:
                yield command
            start = i + 1
    if body[start:].strip():
        raise ValueError(f"unterminated TikZ command: {body[start:].strip()[:60]}")


def _group(text: str, i: int, open_: str, close: str) -> tuple[str, int]:
    """The text inside the bracket at ``i`` (nested braces allowed) and the index after it."""
    if text[i] != open_:
        raise ValueError(f"expected {open_!r} in TikZ: {text[i : i + 40]}")
    depth = 0
    for j in range(i, len(text)):
        if text[j] in "{[(" and (text[j] == open_ or text[j] == "{"):
            depth += 1
        elif text[j] in "}])" and (text[j] == close or text[j] == "}"):
            depth -= 1
            if depth == 0:
                return text[i + 1 : j], j + 1
    raise ValueError(f"unbalanced {open_!r} in TikZ: {text[i : i + 40]}")


def _options(text: str) -> list[str]:
    """A ``[...]`` list split at its top-level commas."""
    out, depth, start = [], 0, 0
    for i, char in enumerate(text):
        depth += (char in "{(" and 1) or (char in "})" and -1) or 0
        if char == "," and depth == 0:
            out.append(text[start:i].strip())
            start = i + 1
    out.append(text[start:].strip())
    return [o for o in out if o]


# options that change nothing an SVG reader needs (fonts, spacing, the picture's frame)
COSMETIC = frozenset({
    "line cap", "line join", "decorate", "x", "y", "baseline", "font", "align", "text width",
    "outer sep", "minimum size", "minimum width", "minimum height", "opacity", "draw opacity",
    "fill opacity", "shorten >", "shorten <", "transform shape", "every node/.style",
})  # fmt: skip
DASHES = {
    "dashed": "1.2 0.8", "densely dashed": "1.2 0.5", "loosely dashed": "1.2 1.6",
    "dotted": "0.2 0.6", "densely dotted": "0.2 0.35", "loosely dotted": "0.2 1.2",
}  # fmt: skip


def _style(options: list[str], filled: bool) -> _Style:
    style = _Style(fill="#000" if filled else None)
    expanded = [o for option in options for o in STYLES.get(option, [option])]
    for option in expanded:
        key, _, value = (part.strip() for part in option.partition("="))
        if option in WIDTHS:
            style.width = WIDTHS[option] * PT_MM
        elif _ARROWS.fullmatch(option):
            start, end = option.split("-", 1)
            style.arrows = {(True, True): "<->", (False, True): "->", (True, False): "<-"}.get(
                (bool(start), bool(end)), ""
            )
        elif option in DASHES:
            style.dashed = DASHES[option]
        elif _colour(option) is not None:
            style.colour = _colour(option) or style.colour
        elif key == "fill":
            style.fill = _colour(value) or "#fff"
        elif key == "pattern":
            style.hatch, style.fill = True, None
        elif key == "line width":
            style.width = float(value.removesuffix("pt")) * PT_MM
        elif key == "rounded corners":
            style.rounded = float(value.removesuffix("mm") or 1.0)
        elif key == "rotate around":
            angle, _, centre = value.strip("{}").partition(":")
            style.rotate = (float(angle), _pair(centre))
        elif key == "decoration":
            amplitude = re.search(r"amplitude=([\d.]+)mm", value)
            style.zigzag = float(amplitude[1]) if amplitude else 1.0
        elif key in COSMETIC or key.startswith(">") or option.startswith(">"):
            continue
        else:
            raise ValueError(f"TikZ option not drawn as SVG: {option}")
    return style


# an arrow tip option: ->, <->, <-, -{Stealth[...]}, {Stealth}-{Stealth}, -latex, -stealth
_ARROWS = re.compile(r"(<|\{[^{}]*\}|latex|stealth)?-(>|\{[^{}]*\}|latex|stealth)?")


def _colour(option: str) -> str | None:
    """``red``, ``blue!70`` or ``gray!50!black`` as an SVG colour (the first named
    colour), or None when ``option`` names none."""
    name = option.split("!", 1)[0].strip()
    return COLOURS.get(name) if name else None


def _pair(text: str) -> Point:
    x, y = text.strip().strip("()").split(",")
    return (float(x), float(y))


# ---- drawing


def _picture(body: str, ident: str) -> ET.Element:
    drawing = _Drawing()
    for command in _commands(body):
        if command.startswith("\\node"):
            _node_command(command, drawing)
        elif command.startswith(("\\draw", "\\fill", "\\filldraw", "\\path")):
            _path_command(command, drawing, ident)
        elif command.startswith("\\coordinate"):
            continue  # a named point: the commands that use it give their own coordinates
        else:
            raise ValueError(f"TikZ command not drawn as SVG: {command[:60]}")
    return _svg(drawing, ident)


def _node_command(command: str, drawing: _Drawing) -> None:
    """``\\node[OPTIONS] at (x,y) {TEXT}``."""
    options, i = _group(command, len("\\node"), "[", "]")
    match = re.match(r"\s*at\s*(\([^)]*\))\s*", command[i:])
    if match is None:
        raise ValueError(f"TikZ node without a place: {command[:60]}")
    text, _ = _group(command, i + match.end(), "{", "}")
    drawing.labels.append(_label(text, _pair(match[1]), _options(options), None))


def _label(text: str, at: Point, options: list[str], normal: Point | None) -> _Label:
    """A node's label from its options: ``anchor=``, ``left=1.5mm``, ``auto`` (beside the
    path, to its left, or right with ``swap``), ``inner sep=``, ``fill=``."""
    label = _Label(text, at, None)
    places = [o for o in options if o.partition("=")[0] in PLACES]
    for option in options:
        key, _, value = option.partition("=")
        if key == "anchor":
            label.anchor = float(ANCHORS[value]) if value in ANCHORS else float(value)
            label.corner = " " in value
        elif key == "inner sep":
            label.shift = float(value.removesuffix("pt")) * PT_MM
        elif key == "fill":
            label.fill = COLOURS.get(value, "#fff")
        elif _colour(option) is not None:
            label.colour = _colour(option) or label.colour
    for option in places:
        key, _, value = option.partition("=")
        label.anchor = ANCHORS[PLACES[key]]
        label.corner = " " in PLACES[key]
        if value:
            label.shift += float(value.removesuffix("mm"))
    if "auto" in options and normal is not None:
        side = (normal[0], normal[1]) if "swap" in options else (-normal[0], -normal[1])
        label.anchor = math.degrees(math.atan2(side[1], side[0]))
    return label


_TOKEN = re.compile(
    r"\s*(?:(?P<rel>\+\+)?\((?P<a>[-\d.]+)(?P<sep>[,:])(?P<b>[-\d.]+)\)"
    r"|(?P<line>--)|(?P<cycle>cycle)|(?P<rect>rectangle)"
    r"|(?P<circle>circle)\[radius=(?P<r>[-\d.]+)\]"
    r"|(?P<arc>arc)\[start angle=(?P<s>[-\d.]+),end angle=(?P<e>[-\d.]+),radius=(?P<ar>[-\d.]+)\]"
    r"|(?P<node>node))"
)


def _path_command(command: str, drawing: _Drawing, ident: str) -> None:
    r"""``\draw[OPTIONS] PATH`` or ``\fill[OPTIONS] PATH``: each piece of the path drawn."""
    verb = re.match(r"\\(filldraw|fill|draw|path)", command)
    assert verb is not None
    i = verb.end()
    options: list[str] = []
    if command[i : i + 1] == "[":
        inside, i = _group(command, i, "[", "]")
        options = _options(inside)
    style = _style(options, verb[1].startswith("fill"))
    style.stroke = verb[1] in ("draw", "filldraw")
    subpaths: list[list[Point]] = []  # polylines (and closed polygons)
    closed: list[bool] = []
    current: Point | None = None
    pending = ""  # "--" or "rectangle" waiting for its point
    last: tuple[str, tuple] = ("point", ((0.0, 0.0),))  # for a node: the piece it follows
    while i < len(command):
        match = _TOKEN.match(command, i)
        if match is None:
            if command[i:].strip():
                raise ValueError(f"TikZ path not drawn as SVG: {command[i : i + 60]}")
            break
        i = match.end()
        if match["a"] is not None:
            a, b = float(match["a"]), float(match["b"])
            point = (a, b) if match["sep"] == "," else _polar((0.0, 0.0), b, a)
            if match["rel"]:
                assert current is not None
                point = (current[0] + point[0], current[1] + point[1])
            if pending == "--":
                assert current is not None
                subpaths[-1].append(point)
                last = ("line", (current, point))
            elif pending == "rectangle":
                assert current is not None
                drawing.shapes.append(_rectangle(current, point, style, ident))
                drawing.cover(*_rotated_corners(current, point, style.rotate))
                subpaths.pop()
                closed.pop()
                last = ("line", (current, point))
            else:
                subpaths.append([point])
                closed.append(False)
                last = ("point", (point,))
            current, pending = point, ""
        elif match["line"] or match["rect"]:
            pending = "--" if match["line"] else "rectangle"
        elif match["cycle"]:
            closed[-1], pending = True, ""
        elif match["circle"]:
            assert current is not None
            radius = float(match["r"])
            drawing.shapes.append(_circle(current, radius, style, ident))
            drawing.cover((current[0] - radius, current[1] - radius),
                          (current[0] + radius, current[1] + radius))  # fmt: skip
            subpaths.pop()
            closed.pop()
            last = ("point", (current,))
        elif match["arc"]:
            assert current is not None
            start, end, radius = float(match["s"]), float(match["e"]), float(match["ar"])
            centre = _polar(current, -radius, start)
            current = _polar(centre, radius, end)
            drawing.shapes += _arc(centre, radius, start, end, style)
            drawing.cover((centre[0] - radius, centre[1] - radius),
                          (centre[0] + radius, centre[1] + radius))  # fmt: skip
            subpaths.pop()
            closed.pop()
            subpaths.append([current])
            closed.append(False)
            last = ("arc", (centre, radius, start, end))
        elif match["node"]:
            i = _path_node(command, i, last, drawing, style.colour)
    for points, shut in zip(subpaths, closed, strict=True):
        if len(points) > 1:
            drawing.shapes += _polyline(points, shut, style, ident)
            drawing.cover(*points)


def _path_node(
    command: str, i: int, last: tuple[str, tuple], drawing: _Drawing, colour: str
) -> int:
    """A ``node[...] {TEXT}`` on a path: at the end of the piece it follows, or at ``pos``,
    ``midway`` or ``at start``."""
    options: list[str] = []
    rest = command[i:].lstrip()
    i = len(command) - len(rest)
    if rest.startswith("["):
        inside, i = _group(command, i, "[", "]")
        options = _options(inside)
    while command[i] == " ":
        i += 1
    text, i = _group(command, i, "{", "}")
    pos = 1.0
    for option in options:
        key, _, value = option.partition("=")
        if key == "pos":
            pos = float(value)
        elif option == "midway":
            pos = 0.5
        elif option == "at start":
            pos = 0.0
    kind, data = last
    normal: Point | None = None
    if kind == "line":
        (x1, y1), (x2, y2) = data
        at = (x1 + pos * (x2 - x1), y1 + pos * (y2 - y1))
        length = math.hypot(x2 - x1, y2 - y1) or 1.0
        normal = ((y2 - y1) / length, -(x2 - x1) / length)  # to the right of the path
    elif kind == "arc":
        centre, radius, start, end = data
        at = _polar(centre, radius, start + pos * (end - start))
    else:
        at = data[0]
    label = _label(text, at, options, normal)
    label.colour = colour if label.colour == "#000" else label.colour
    drawing.labels.append(label)
    return i


def _polar(centre: Point, radius: float, degrees: float) -> Point:
    angle = math.radians(degrees)
    return (centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle))


def _xy(point: Point) -> str:
    """A page point (mm, y up) as SVG coordinates (y down)."""
    return f"{_n(point[0])},{_n(-point[1])}"


def _n(value: float) -> str:
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _paint(element: ET.Element, style: _Style, ident: str, filled: bool = True) -> ET.Element:
    """Stroke, width, dashes and fill (a colour, a hatch pattern or none)."""
    fill = style.fill if filled else None
    if style.hatch:
        fill = f"url(#{ident}-hatch)"
    element.set("fill", fill or "none")
    if style.stroke:
        element.set("stroke", style.colour)
        element.set("stroke-width", _n(style.width) if style.width >= 0.01 else "0.01")
    else:  # \fill: no outline
        element.set("stroke", "none")
    if style.dashed:
        element.set("stroke-dasharray", style.dashed)
    if style.rotate is not None:
        angle, centre = style.rotate
        element.set("transform", f"rotate({_n(-angle)},{_xy(centre)})")
    return element


def _rotated_corners(a: Point, b: Point, rotate: tuple[float, Point] | None) -> list[Point]:
    corners = [a, (a[0], b[1]), b, (b[0], a[1])]
    if rotate is None:
        return corners
    angle, (cx, cy) = math.radians(rotate[0]), rotate[1]
    c, s = math.cos(angle), math.sin(angle)
    return [
        (cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy)) for x, y in corners
    ]


def _rectangle(a: Point, b: Point, style: _Style, ident: str) -> ET.Element:
    x, y = min(a[0], b[0]), max(a[1], b[1])
    element = ET.Element(
        "rect",
        {"x": _n(x), "y": _n(-y), "width": _n(abs(b[0] - a[0])), "height": _n(abs(b[1] - a[1]))},
    )
    if style.rounded:
        element.set("rx", _n(style.rounded))
    return _paint(element, style, ident)


def _circle(centre: Point, radius: float, style: _Style, ident: str) -> ET.Element:
    cx, cy = _xy(centre).split(",")
    return _paint(ET.Element("circle", {"cx": cx, "cy": cy, "r": _n(radius)}), style, ident)


def _head(tip: Point, direction: Point, style: _Style) -> ET.Element:
    """An arrowhead (TikZ's Stealth, 2.4 mm by 1.8 mm) at ``tip`` pointing ``direction``."""
    length = math.hypot(*direction) or 1.0
    ux, uy = direction[0] / length, direction[1] / length
    back, half = 2.4, 0.9
    base = (tip[0] - back * ux, tip[1] - back * uy)
    inner = (tip[0] - 0.7 * back * ux, tip[1] - 0.7 * back * uy)
    left = (base[0] - half * uy, base[1] + half * ux)
    right = (base[0] + half * uy, base[1] - half * ux)
    points = " ".join(_xy(p) for p in (tip, left, inner, right))
    return ET.Element("polygon", {"points": points, "fill": style.colour, "stroke": "none"})


def _polyline(points: list[Point], shut: bool, style: _Style, ident: str) -> list[ET.Element]:
    if style.zigzag:
        points = _zigzag(points[0], points[-1], style.zigzag)
    d = "M" + " L".join(_xy(p) for p in points) + (" Z" if shut else "")
    out = [_paint(ET.Element("path", {"d": d}), style, ident, filled=shut)]
    if style.arrows.endswith(">") and len(points) > 1:
        (x1, y1), (x2, y2) = points[-2], points[-1]
        out.append(_head((x2, y2), (x2 - x1, y2 - y1), style))
    if style.arrows.startswith("<") and len(points) > 1:
        (x1, y1), (x2, y2) = points[1], points[0]
        out.append(_head((x2, y2), (x2 - x1, y2 - y1), style))
    return out


def _zigzag(a: Point, b: Point, amplitude: float, segment: float = 2.0) -> list[Point]:
    """A spring between ``a`` and ``b`` as TikZ's zigzag decoration draws it."""
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    if length == 0:
        return [a, b]
    ux, uy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    count = max(2, round(length / (segment / 2)))
    points = [a]
    for k in range(1, count):
        side = amplitude if k % 2 else -amplitude
        t = k * length / count
        points.append((a[0] + t * ux - side * uy, a[1] + t * uy + side * ux))
    return [*points, b]


def _arc(centre: Point, radius: float, start: float, end: float, style: _Style) -> list[ET.Element]:
    a, b = _polar(centre, radius, start), _polar(centre, radius, end)
    large = 1 if abs(end - start) > 180 else 0
    sweep = 0 if end > start else 1  # counterclockwise on the page is y-down's negative sense
    d = f"M{_xy(a)} A{_n(radius)},{_n(radius)} 0 {large},{sweep} {_xy(b)}"
    path = ET.Element("path", {"d": d, "fill": "none", "stroke": style.colour})
    path.set("stroke-width", _n(style.width))
    if style.dashed:
        path.set("stroke-dasharray", style.dashed)
    out = [path]
    sense = 1.0 if end > start else -1.0
    if style.arrows.endswith(">"):
        angle = math.radians(end)
        out.append(_head(b, (-sense * math.sin(angle), sense * math.cos(angle)), style))
    if style.arrows.startswith("<"):
        angle = math.radians(start)
        out.append(_head(a, (sense * math.sin(angle), -sense * math.cos(angle)), style))
    return out


# ---- labels


def _svg(drawing: _Drawing, ident: str) -> ET.Element:
    """The picture: its shapes, then its labels (each placed by its anchor), in a viewBox
    around them all with a margin."""
    texts = []
    for label in drawing.labels:
        runs = label_runs(label.text)
        w, h = max(FONT_MM / 2, _width(runs)), FONT_MM * 1.15
        cx, cy = label.at
        if label.anchor is not None:
            angle = math.radians(label.anchor)
            c, s = math.cos(angle), math.sin(angle)
            if label.corner:  # north east, …: the box's corner at the point
                cx -= math.copysign(w / 2 + label.shift, c)
                cy -= math.copysign(h / 2 + label.shift, s)
            else:  # the box's border point in that direction at the point
                reach = min(w / 2 / abs(c) if abs(c) > 1e-9 else math.inf,
                            h / 2 / abs(s) if abs(s) > 1e-9 else math.inf)  # fmt: skip
                cx -= (reach + label.shift) * c
                cy -= (reach + label.shift) * s
        drawing.cover((cx - w / 2, cy - h / 2), (cx + w / 2, cy + h / 2))
        if label.fill:
            box = {"x": _n(cx - w / 2), "y": _n(-cy - h / 2), "width": _n(w), "height": _n(h)}
            texts.append(ET.Element("rect", {**box, "fill": label.fill}))
        texts.append(_text(runs, (cx, cy), label.colour))
    x0, y0, x1, y1 = drawing.box if math.isfinite(drawing.box[0]) else [0.0, 0.0, 1.0, 1.0]
    margin = 1.5
    view = (x0 - margin, -y1 - margin, x1 - x0 + 2 * margin, y1 - y0 + 2 * margin)
    svg = ET.Element(
        "svg",
        {
            "xmlns": "http://www.w3.org/2000/svg",
            "viewBox": " ".join(_n(v) for v in view),
            "width": _n(view[2] * PX_PER_MM),
            "height": _n(view[3] * PX_PER_MM),
            "role": "img",
            "font-size": _n(FONT_MM),
            "stroke-linecap": "round",
            "stroke-linejoin": "round",
        },
    )
    if any(e.get("fill", "").startswith("url(") for e in drawing.shapes):
        svg.append(_hatch(ident))
    svg.extend(drawing.shapes)
    svg.extend(texts)
    return svg


def _width(runs: list[tuple[str, str, bool]]) -> float:
    """About how wide a label's runs are set (mm): capitals wider than small letters, a
    subscript or superscript at 70 %."""
    em = 0.0
    for chunk, level, _italic in runs:
        size = 0.7 if level else 1.0
        for char in chunk:
            em += size * (0.72 if char.isupper() else 0.25 if char.isspace() else 0.5)
    return em * FONT_MM


def _hatch(ident: str) -> ET.Element:
    """The ``north east lines`` pattern, as a hatched support or ground."""
    defs = ET.Element("defs")
    pattern = ET.SubElement(
        defs,
        "pattern",
        {"id": f"{ident}-hatch", "width": "1", "height": "1", "patternUnits": "userSpaceOnUse",
         "patternTransform": "rotate(-45)"},
    )  # fmt: skip
    ET.SubElement(pattern, "line", {"x1": "0", "y1": "0", "x2": "0", "y2": "1",
                                    "stroke": "#000", "stroke-width": "0.15"})  # fmt: skip
    return defs


def _text(runs: list[tuple[str, str, bool]], at: Point, colour: str = "#000") -> ET.Element:
    """A label's runs as ``<text>`` in ``colour``, centred on ``at``: subscripts and
    superscripts as smaller ``tspan``\\ s shifted down or up (and back), italic where it is
    mathematics."""
    text = ET.Element(
        "text",
        {"x": _n(at[0]), "y": _n(-at[1] + 0.35 * FONT_MM), "text-anchor": "middle",
         "font-family": "'Latin Modern Roman','Computer Modern',Cambria,'Times New Roman',serif"},
    )  # fmt: skip
    if colour != "#000":
        text.set("fill", colour)
    level = ""
    for chunk, kind, italic in runs:
        span = ET.SubElement(text, "tspan")
        span.text = chunk
        shift = {("", "sub"): 0.3, ("", "sup"): -0.4, ("sub", ""): -0.3, ("sup", ""): 0.4,
                 ("sub", "sup"): -0.7, ("sup", "sub"): 0.7}.get((level, kind), 0.0)  # fmt: skip
        if shift:  # in user units (mm): an em would be the smaller span's own
            span.set("dy", _n(shift * FONT_MM))
        if kind:
            span.set("font-size", "70%")
        if italic:
            span.set("font-style", "italic")
        level = kind
    return text


_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε",
    "zeta": "ζ", "eta": "η", "theta": "θ", "vartheta": "ϑ", "iota": "ι", "kappa": "κ",
    "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ",
    "tau": "τ", "upsilon": "υ", "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ",
    "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ",
    "Pi": "Π", "Sigma": "Σ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω", "cdot": "·",
    "times": "×", "circ": "°", "prime": "′", "to": "→", "pm": "±", "ell": "ℓ",
    "dot": "", "ddot": "", "hat": "", "bar": "", "vec": "", "mathrm": "", "mathit": "",
    "text": "", "textit": "", "operatorname": "", "left": "", "right": "",
}  # fmt: skip
_SPACES = {",": "\u2009", ";": "\u2005", "quad": "\u2003", " ": " ", "!": ""}
_TEXT_ESCAPES = {"&": "&", "%": "%", "$": "$", "#": "#", "_": "_", "{": "{", "}": "}"}


def label_runs(latex: str) -> list[tuple[str, str, bool]]:
    r"""A figure label's LaTeX as runs of (text, level, italic): level "" on the line,
    "sub" or "sup"; letters in mathematics italic, Greek and digits upright.

    >>> label_runs(r"$I_{G} \, \alpha$")
    [('I', '', True), ('G', 'sub', True), ('\u2009', '', False), ('α', '', True)]
    >>> label_runs(r"\textit{drum} $\qty{0.4}{m}$")
    [('drum', '', True), (' 0.4\u2009m', '', False)]
    """
    runs: list[tuple[str, str, bool]] = []

    def add(chunk: str, level: str, italic: bool) -> None:
        if not chunk:
            return
        if runs and runs[-1][1] == level and runs[-1][2] == italic:
            runs[-1] = (runs[-1][0] + chunk, level, italic)
        else:
            runs.append((chunk, level, italic))

    def walk(text: str, math: bool, level: str, italic_text: bool) -> None:
        i = 0
        while i < len(text):
            char = text[i]
            if char == "$":
                math = not math
                i += 1
            elif char == "\\":
                name = re.match(r"\\([A-Za-z]+|.)", text[i:])
                assert name is not None
                word = name[1]
                i += name.end()
                if word == "qty":
                    number, i = _group(text, i, "{", "}")
                    unit, i = _group(text, i, "{", "}")
                    add(f"{number}\u2009{_unit(unit)}", level, False)
                elif word in ("textit", "mathit"):
                    inner, i = _group(text, i, "{", "}")
                    walk(inner, False, level, True)
                elif word in ("mathrm", "text", "operatorname", "textrm"):
                    inner, i = _group(text, i, "{", "}")
                    walk(inner, False, level, False)
                elif word in _SPACES:
                    add(_SPACES[word], level, False)
                elif word in _TEXT_ESCAPES:
                    add(_TEXT_ESCAPES[word], level, italic_text)
                elif word in _GREEK:  # lowercase Greek slanted, as TeX sets it
                    add(_GREEK[word], level, math and "α" <= _GREEK[word] <= "ω")
                else:
                    add(word, level, False)
            elif char in "_^" and math:
                sub = "sub" if char == "_" else "sup"
                i += 1
                if text[i : i + 1] == "{":
                    inner, i = _group(text, i, "{", "}")
                else:
                    inner, i = text[i : i + 1], i + 1
                walk(inner, True, sub, italic_text)
            elif char in "{}" or (char == " " and math):
                i += 1
            else:
                add(char, level, (math and char.isalpha()) or italic_text)
                i += 1

    walk(latex, False, "", False)
    return runs


def _unit(unit: str) -> str:
    """A siunitx unit (``m/s^{2}``) as text (``m/s²``)."""
    powers = {"^{2}": "²", "^{3}": "³", "^{-1}": "⁻¹", "^{-2}": "⁻²"}
    for power, shown in powers.items():
        unit = unit.replace(power, shown)
    return unit.replace("\\cdot", "·").replace(" ", "")
