r"""The problem's figure on a solution sheet: a planar scene drawn as a TikZ picture.

Bodies at their places (a disk or drum a circle with its hub, a rod a bar along its
points, a block or plate a rectangle square on its contact, a particle a dot), with G
marked; the ground hatched where a contact presses, a fixed pin on a small hatched
support; cords and links as lines, springs as zigzags, applied forces and couples as
arrows with their names, paths as curves, and the direction of gravity. The scene is
scaled to fit 90 mm by 45 mm. Every command is one line.

>>> from dynsolve.results import SceneSketch
>>> floor = (("C", 0.0, 0.0, 0.0, 1.0, 0.8),)
>>> crate = SceneSketch((("crate", "block", 0.0, 0.25, (1.0, 0.5), 0.0, ()),), (), floor,
...                     (), (), (), (("P", -0.5, 0.3, 1.0, 0.0),), (), (), True)
>>> tex = scene_picture(crate)
>>> tex.count("pattern=north east lines"), "rectangle" in tex, "{$P$}" in tex
(1, True, True)
"""

from __future__ import annotations

import math
from collections.abc import Callable

from dynsolve.names import latex_name
from dynsolve.render.fbd_tikz import fit, num, polar, reach_of, shape_lines
from dynsolve.results import SceneSketch

Point = tuple[float, float]
WIDTH_MM, HEIGHT_MM = 90.0, 45.0
SURFACE_MM = 18.0  # a contact's ground line, this long
HATCH_MM = 2.0  # the hatched band under it
GUIDE_MM = 1.5  # a guide's two lines, this far either side of its contact point
PIN_MM = 1.2
ARROW_MM = 10.0
CORD_MM = 14.0
DOT_MM = 1.3
LIMIT_MM = 400.0


def scene_picture(sketch: SceneSketch) -> str:
    """The TikZ drawing of ``sketch`` (see the module docstring)."""
    at, scale = _frame(sketch)
    lines = [r"\begin{tikzpicture}[x=1mm,y=1mm,>=Stealth]"]
    for _name, curve in sketch.paths:
        if len(curve) > 1:
            points = " -- ".join(_xy(at(p)) for p in curve)
            lines.append(f"\\draw[thick,gray] {points};")
    for _name, x, y, nx, ny, half in sketch.surfaces:
        half_mm = half * scale if half > 0 else 0.35 * WIDTH_MM  # a particle: a long floor
        lines += _surface(at((x, y)), (nx, ny), max(SURFACE_MM / 2, half_mm))
    for _name, x, y, nx, ny, half in sketch.guides:
        lines += _guide(at((x, y)), (nx, ny), max(SURFACE_MM / 2, half * scale))
    for body in sketch.bodies:
        lines += _body(body, at, scale)
    for name, x, y in sketch.pins:
        lines += _pin(at((x, y)), name)
    for name, x, y, dx, dy, reach in sketch.cords:
        start = at((x, y))
        length = reach * scale if reach > 0 else CORD_MM
        end = (start[0] + length * dx, start[1] + length * dy)
        lines.append(
            f"\\draw[thin] {_xy(start)} -- {_xy(end)} node[pos=0.6,auto,swap] {{{_math(name)}}};"
        )
    for name, x1, y1, x2, y2 in sketch.springs:
        lines.append(
            f"\\draw[decorate,decoration={{zigzag,amplitude=1.2mm,segment length=2mm}}] "
            f"{_xy(at((x1, y1)))} -- {_xy(at((x2, y2)))} "
            f"node[midway,above=1.5mm] {{{_math(name)}}};"
        )
    for name, x1, y1, x2, y2 in sketch.links:
        lines.append(
            f"\\draw[thick] {_xy(at((x1, y1)))} -- {_xy(at((x2, y2)))} "
            f"node[midway,auto] {{{_math(name)}}};"
        )
    for name, x, y, dx, dy in sketch.forces:
        tip = at((x, y))
        tail = (tip[0] - ARROW_MM * dx, tip[1] - ARROW_MM * dy)
        lines.append(
            f"\\draw[thick,->] {_xy(tail)} -- {_xy(tip)} "
            f"node[at start,anchor={_away(dx, dy)}] {{{_math(name)}}};"
        )
    for name, x, y, sense in sketch.couples:
        centre = at((x, y))
        start, end = (-45.0, 225.0) if sense > 0 else (225.0, -45.0)
        lines.append(
            f"\\draw[thick,->] {_xy(polar(centre, 5.0, start))} arc[start angle={num(start)},"
            f"end angle={num(end)},radius=5] node[above right] {{{_math(name)}}};"
        )
    if sketch.gravity:
        corner = (WIDTH_MM / 2 + 6.0, HEIGHT_MM / 2)
        lines.append(
            f"\\draw[->] {_xy(corner)} -- {_xy((corner[0], corner[1] - 8.0))} node[right] {{$g$}};"
        )
    lines.append(r"\end{tikzpicture}")
    return "\n".join(lines)


def _frame(sketch: SceneSketch) -> tuple[Callable[[Point], Point], float]:
    """The map from metres to the page (mm, centred) and its scale (mm per metre)."""
    reach: list[Point] = []
    for _, shape, x, y, sizes, _angle, parts in sketch.bodies:
        for shape_, x_, y_, sizes_, *_rest in parts or ((shape, x, y, sizes),):
            r = reach_of(shape_, sizes_)
            reach += [(x_ - r, y_ - r), (x_ + r, y_ + r)]
    reach += [(x, y) for _, x, y in sketch.pins]
    reach += [(x, y) for _, x, y, _, _, _ in (*sketch.surfaces, *sketch.guides)]
    for _, x1, y1, x2, y2 in (*sketch.springs, *sketch.links):
        reach += [(x1, y1), (x2, y2)]
    for _, curve in sketch.paths:
        reach += list(curve)
    return fit(reach, WIDTH_MM, HEIGHT_MM)


def _body(body: tuple, at: Callable[[Point], Point], scale: float) -> list[str]:
    """A body's outline at its place (a composite's parts, each by its shape), its G
    marked and its name beside it."""
    name, shape, x, y, sizes, angle, parts = body
    G = at((x, y))
    label = f"\\node[anchor=south west,inner sep=1pt] at {_xy(G)} {{{_text(name)}}};"
    centre = f"\\fill {_xy(G)} circle[radius=0.5];"
    if parts:
        lines = []
        for shape_, x_, y_, sizes_, angle_, hole in parts:
            mm = tuple(abs(v) * scale for v in sizes_)
            lines += shape_lines(shape_, at((x_, y_)), mm, angle_, hole)
        return [*lines, centre, label]
    first = abs(sizes[0]) * scale if sizes else 0.0
    if shape == "particle" or not first:
        return [f"\\fill {_xy(G)} circle[radius={num(DOT_MM)}];", label]
    mm = tuple(abs(v) * scale for v in sizes)
    return [*shape_lines(shape, G, mm, angle), centre, label]


def _surface(point: Point, normal: Point, half: float) -> list[str]:
    """The ground a contact presses on: a line across the normal, ``half`` mm either side
    of ``point``, with a hatched band on the far side."""
    t = (normal[1], -normal[0])
    a = (point[0] - half * t[0], point[1] - half * t[1])
    b = (point[0] + half * t[0], point[1] + half * t[1])
    down = (-HATCH_MM * normal[0], -HATCH_MM * normal[1])
    c, d = (b[0] + down[0], b[1] + down[1]), (a[0] + down[0], a[1] + down[1])
    return [
        f"\\fill[pattern=north east lines] {_xy(a)} -- {_xy(b)} -- {_xy(c)} -- {_xy(d)} -- cycle;",
        f"\\draw[thick] {_xy(a)} -- {_xy(b)};",
    ]


def _guide(point: Point, normal: Point, half: float) -> list[str]:
    """A two-sided guide (a slot, a collar's rod): two thin lines either side of the
    contact point, ``half`` mm along the guide each way."""
    t = (normal[1], -normal[0])
    lines = []
    for side in (-GUIDE_MM, GUIDE_MM):
        o = (point[0] + side * normal[0], point[1] + side * normal[1])
        a = (o[0] - half * t[0], o[1] - half * t[1])
        b = (o[0] + half * t[0], o[1] + half * t[1])
        lines.append(f"\\draw[thin] {_xy(a)} -- {_xy(b)};")
    return lines


def _pin(point: Point, name: str) -> list[str]:
    """A fixed pin: a small open circle on a triangle with a hatched base below it."""
    x, y = point
    base = y - 4.0
    top, left, right = _xy((x, y)), _xy((x - 2.5, base)), _xy((x + 2.5, base))
    return [
        f"\\draw {top} -- {left} -- {right} -- cycle;",
        f"\\fill[pattern=north east lines] {_xy((x - 3.5, base))} rectangle "
        f"{_xy((x + 3.5, base - HATCH_MM))};",
        f"\\draw[fill=white] {top} circle[radius={num(PIN_MM)}] node[left=1.5mm] "
        f"{{{_math(name)}}};",
    ]


def _away(dx: float, dy: float) -> str:
    """The anchor that puts a force's name beyond its tail."""
    return num(round(math.degrees(math.atan2(dy, dx))) % 360)


def _math(name: str) -> str:
    return f"${latex_name(name)}$" if name else ""


def _text(name: str) -> str:
    from dynsolve.render.latex import escape_latex  # latex imports this module

    return f"\\textit{{{escape_latex(name)}}}"


def _xy(point: Point) -> str:
    """A page point, kept within ±LIMIT_MM (TikZ cannot go past about 5.7 m)."""
    x, y = (max(-LIMIT_MM, min(LIMIT_MM, c)) for c in point)
    return f"({num(x)},{num(y)})"
