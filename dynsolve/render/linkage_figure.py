r"""The linkage of a solution sheet, drawn at the instant as a TikZ picture in millimetres.

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
>>> tex.count("node[anchor=south west"), "fill=black" in tex, "fill=white" in tex
(3, True, True)
"""

from __future__ import annotations

import math

from dynsolve.names import latex_name
from dynsolve.render.fbd_tikz import fit, num
from dynsolve.results import LinkageFigure

Point = tuple[float, float]
WIDTH_MM, HEIGHT_MM = 80.0, 60.0
PIN_MM = 0.8  # a pin's circle (radius)
GUIDE_MM = 12.0  # a slider's guide reaches this far either side of the joint
BOX_MM = 3.0  # a slider's block
HATCH_MM = 4.0  # the ground line under a fixed pin


def linkage_picture(figure: LinkageFigure) -> str:
    """The TikZ drawing of ``figure`` (see the module docstring)."""
    where = {name: (x, y) for name, x, y, _ in figure.joints}
    reach = [(x, y) for x, y in where.values()]
    for _, centre, radius in figure.wheels:
        cx, cy = where[centre]
        reach += [(cx - radius, cy - radius), (cx + radius, cy + radius)]
    to_page, scale = fit(reach, WIDTH_MM, HEIGHT_MM)

    def at(point: Point) -> str:
        return _xy(to_page(point))

    lines = [r"\begin{tikzpicture}[x=1mm,y=1mm]"]
    for point, dx, dy in figure.guides:
        angle = math.degrees(math.atan2(dy, dx))
        centre = at(where[point])
        lines.append(
            f"\\draw[dashed,thin] {centre} ++({num(angle)}:{num(-GUIDE_MM)}) -- "
            f"++({num(angle)}:{num(2 * GUIDE_MM)});"
        )
        lines.append(
            f"\\draw[thin,rotate around={{{num(angle)}:{centre}}}] {centre} "
            f"++({num(-BOX_MM / 2)},{num(-BOX_MM / 2)}) rectangle ++({num(BOX_MM)},{num(BOX_MM)});"
        )
    for _, centre, radius in figure.wheels:
        lines.append(f"\\draw[thick] {at(where[centre])} circle[radius={num(radius * scale)}];")
    for x, y, nx, ny in figure.grounds:
        lines += _rolling_ground(at((x, y)), (nx, ny))
    for _, points in figure.bars:
        path = " -- ".join(at(where[p]) for p in points)
        closed = " -- cycle" if len(points) > 2 else ""
        lines.append(f"\\draw[line width=1.2pt,line join=round] {path}{closed};")
    for name, x, y, fixed in figure.joints:
        centre = at((x, y))
        if fixed:
            lines += _ground(centre)
        fill = "black" if fixed else "white"
        lines.append(
            f"\\draw[fill={fill}] {centre} circle[radius={num(PIN_MM)}] "
            f"node[anchor=south west,inner sep=2pt] {{${latex_name(name)}$}};"
        )
    lines.append(r"\end{tikzpicture}")
    return "\n".join(lines)


def _xy(point: Point) -> str:
    return f"({num(point[0])},{num(point[1])})"


def _ground(centre: str) -> list[str]:
    """A fixed pin's ground: a short line below it, hatched."""
    half = HATCH_MM / 2
    return [
        f"\\draw {centre} ++({num(-half)},-2) -- ++({num(HATCH_MM)},0);",
        *(
            f"\\draw[thin] {centre} ++({num(-half + k * HATCH_MM / 4)},-2) -- ++(-1,-1);"
            for k in range(5)
        ),
    ]


def _rolling_ground(contact: str, normal: Point) -> list[str]:
    """The ground a wheel rolls on: a line along it through the contact point, hatched
    on the side away from the wheel."""
    tangent = (normal[1], -normal[0])
    angle = math.degrees(math.atan2(tangent[1], tangent[0]))
    back = _xy((-normal[0] - tangent[0], -normal[1] - tangent[1]))
    out = [f"\\draw {contact} ++({num(angle)}:-12) -- ++({num(angle)}:24);"]
    out += [
        f"\\draw[thin] {contact} ++({num(angle)}:{num(3.0 * k)}) -- ++{back};" for k in range(-4, 5)
    ]
    return out
