r"""The linkage of a solution sheet, drawn at the instant in LaTeX picture mode.

Bars are thick lines between their joints (a bar of three or more joints, a plate, is
closed), wheels and gears circles about their centres, moving pins small open circles,
ground pins filled circles on a hatched ground line, the ground a wheel rolls on a
hatched line, sliders a small box on a dashed guide; every joint is labelled. The
figure is scaled to fit 80 mm by 60 mm.

>>> from dynsolve.results import LinkageFigure
>>> crank = LinkageFigure((("A", 0.0, 0.0, True), ("B", 0.05, 0.087, False),
...                        ("C", 0.25, 0.0, False)), (("AB", ("A", "B")), ("BC", ("B", "C"))),
...                       (("C", 1.0, 0.0),), ())
>>> tex = linkage_picture(crank)
>>> tex.count(r"\makebox(0,0)"), r"\circle*{1.6}" in tex, r"\circle{1.6}" in tex
(3, True, True)
"""

from __future__ import annotations

import itertools
import math

from dynsolve.names import latex_name
from dynsolve.render.picture import Picture, Point
from dynsolve.results import LinkageFigure

WIDTH_MM, HEIGHT_MM = 80.0, 60.0
PIN_MM = 1.6  # a pin's circle
GUIDE_MM = 12.0  # a slider's guide reaches this far either side of the joint
BOX_MM = 3.0  # a slider's block
HATCH_MM = 4.0  # the ground line under a fixed pin


def linkage_picture(figure: LinkageFigure) -> str:
    """The picture-mode drawing of ``figure`` (see the module docstring)."""
    where = {name: (x, y) for name, x, y, _ in figure.joints}
    reach = [(x, y) for x, y in where.values()]
    for _, centre, radius in figure.wheels:
        cx, cy = where[centre]
        reach += [(cx - radius, cy - radius), (cx + radius, cy + radius)]
    xs, ys = [p[0] for p in reach], [p[1] for p in reach]
    span_x, span_y = max(xs) - min(xs), max(ys) - min(ys)
    scale = min(
        WIDTH_MM / span_x if span_x > 0 else math.inf,
        HEIGHT_MM / span_y if span_y > 0 else math.inf,
    )
    scale = scale if math.isfinite(scale) else 1000.0
    origin = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)

    def at(point: Point) -> Point:
        return ((point[0] - origin[0]) * scale, (point[1] - origin[1]) * scale)

    picture = Picture()
    picture.set_thickness(0.4)
    for point, dx, dy in figure.guides:
        length = math.hypot(dx, dy) or 1.0
        unit = (dx / length, dy / length)
        centre = at(where[point])
        reach_mm = GUIDE_MM
        picture.dashed(
            (centre[0] - reach_mm * unit[0], centre[1] - reach_mm * unit[1]),
            (centre[0] + reach_mm * unit[0], centre[1] + reach_mm * unit[1]),
        )
        _box(picture, centre, unit)
    for _, centre, radius in figure.wheels:
        picture.arc(at(where[centre]), radius * scale, 0.0, 360.0, dashed=False)
    for x, y, nx, ny in figure.grounds:
        _rolling_ground(picture, at((x, y)), (nx, ny))
    picture.set_thickness(1.2)
    for _, points in figure.bars:
        corners = [at(where[p]) for p in points]
        pairs = list(itertools.pairwise(corners))
        if len(corners) > 2:
            pairs.append((corners[-1], corners[0]))
        for start, end in pairs:
            picture.line(start, end)
    picture.set_thickness(0.4)
    for name, x, y, fixed in figure.joints:
        centre = at((x, y))
        if fixed:
            _ground(picture, centre)
        picture.put(centre, f"\\circle{'*' if fixed else ''}{{{PIN_MM}}}")
        label = latex_name(name)
        picture.put((centre[0] + 1.4, centre[1] + 1.4), f"\\makebox(0,0)[lb]{{${label}$}}")
        picture.cover((centre[0] + 1.4 + 2.0 * len(name), centre[1] + 4.5))
    return picture.render()


def _box(picture: Picture, centre: Point, unit: Point) -> None:
    """A slider's block: a small square along its guide."""
    normal = (-unit[1], unit[0])
    half = BOX_MM / 2
    corners = [
        (
            centre[0] + half * (a * unit[0] + b * normal[0]),
            centre[1] + half * (a * unit[1] + b * normal[1]),
        )
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    for i, corner in enumerate(corners):
        picture.line(corner, corners[(i + 1) % 4])


def _ground(picture: Picture, centre: Point) -> None:
    """A fixed pin's ground: a short line below it, hatched."""
    left, right = centre[0] - HATCH_MM / 2, centre[0] + HATCH_MM / 2
    base = centre[1] - 2.0
    picture.line((left, base), (right, base))
    for k in range(5):
        x = left + k * HATCH_MM / 4
        picture.line((x, base), (x - 1.0, base - 1.0))


def _rolling_ground(picture: Picture, contact: Point, normal: Point) -> None:
    """The ground a wheel rolls on: a line along it through the contact point, hatched
    on the side away from the wheel."""
    tangent = (normal[1], -normal[0])
    for k in range(-4, 5):
        start = (contact[0] + 3.0 * k * tangent[0], contact[1] + 3.0 * k * tangent[1])
        if k < 4:
            picture.line(start, (start[0] + 3.0 * tangent[0], start[1] + 3.0 * tangent[1]))
        back = (start[0] - normal[0] - tangent[0], start[1] - normal[1] - tangent[1])
        picture.line(start, back)
