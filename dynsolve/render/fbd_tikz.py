r"""Free-body and kinetic diagrams of a solution sheet as TikZ pictures, in millimetres.

Each body is drawn by its outline (a disk, drum or wheel as a circle with its hub, a rod
as a bar, a block or plate as a rectangle, a particle as a dot; a body given without a
shape, by its radius of gyration, as a circle with a hub through its farthest force
point, or a small box when every force acts at G), 35 mm across whatever its size, with
G marked. Every force is an arrow 10 mm long at its point: from the point, or into it
when it pushes on the body there (a normal force under a block), an arrow from G kept
inside the outline; friction 1.5 mm outside the surface it acts along; unknown forces dashed
and red; couples as arcs around their point. A pin off G is drawn as a hole with its name,
and the distance from it to G as a dimension line (in the sheet's units, when the caller
gives ``length_label``).
Beside it, after "=", the kinetic diagram: the same outline with m (a_G)_x, m (a_G)_y and
I_G α drawn in blue (their assumed senses: +x, +y, counterclockwise), as the textbook
sets ΣF = m a_G beside its picture.

Every command is one line, ``\draw[OPTIONS] (x,y) -- (x,y) node[...] {LABEL};`` for an
arrow, so that a test can read the geometry back.

>>> from dynsolve.results import ForceRow, FreeBody
>>> weight = ForceRow("W", "weight", "G", 0.0, 0.0, "down", 0.0, -1.0, True, "")
>>> ball = FreeBody("ball", "particle", (), "translation", (weight,), (), "")
>>> print([line for line in free_body_tikz(ball, lambda f: f.name).splitlines()
...        if "->" in line][0])
\draw[force,->] (0,0) -- (0,-10) node[anchor=90] {W};
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from dynsolve.results import ForceRow, FreeBody

Point = tuple[float, float]
ROUND_SHAPES = frozenset({"disk", "ring", "cylinder", "sphere", "shell", "hollow"})
HUBBED = frozenset({"disk", "ring", "cylinder", "hollow"})  # wheels and drums: a hub
BODY_MM = 35.0  # a body is drawn this wide (or its force points this far apart), any size
ARROW_MM = 10.0  # every force arrow, whatever its magnitude
COUPLE_MM = 6.0  # the radius of a body's first couple arc; the next ones 3 mm wider
SQUARE_MM = 8.0  # the side of the box drawn for a body with nothing to size it
SURFACE_MM = 1.5  # friction is drawn this far outside the surface it acts along
PIN_MM = 1.1  # the radius of a pin's hole
DIMENSION_MM = 5.0  # a dimension line's offset from the points it measures
STYLES = (
    r"force/.style={thick,-{Stealth[length=2.4mm,width=1.8mm]}},"
    r"pin/.style={thick,fill=white},"
    r"spin/.style={semithick,-{Stealth[length=2mm,width=1.6mm]}},"
    r"dimension/.style={thin,{Stealth[length=1.6mm]}-{Stealth[length=1.6mm]}},"
    r"unknown/.style={dashed,red},"
    r"kinetic/.style={thick,blue,-{Stealth[length=2.4mm,width=1.8mm]}},"
    r"baseline=(current bounding box.center)"  # "=" between the diagrams sits mid-height
)


def free_body_tikz(
    body: FreeBody,
    label: Callable[[ForceRow], str],
    kinetic_label: Callable[[str], str] | None = None,
    length_label: Callable[[float], str] | None = None,
) -> str:
    """The body's free-body diagram, and its kinetic diagram beside it when it has terms
    (``label`` typesets a force's name, ``kinetic_label`` a kinetic term, ``length_label`` a
    length in metres in the sheet's units)."""
    footprint = footprint_of(body)
    points = [(_finite(f.x), _finite(f.y)) for f in body.forces]
    half = max([*(footprint or (0.0, 0.0)), *(abs(c) for p in points for c in p)])

    def at(point: Point) -> Point:
        """A body point (metres from G) on the page (mm from G): never beyond 17.5 mm."""
        if half <= 0:
            return (0.0, 0.0)
        return (point[0] / half * BODY_MM / 2, point[1] / half * BODY_MM / 2)

    outline = _outline(body, footprint, at)
    lines = [f"\\begin{{tikzpicture}}[x=1mm,y=1mm,{STYLES}]", *outline, *_centre()]
    lines += _pin_and_distance(body, at, length_label)
    corner = at(footprint) if footprint else (0.0, 0.0)
    round_ = body.shape.strip().lower() in ROUND_SHAPES
    extent = max(
        [math.hypot(*at(p)) for p in points] + [corner[0] if round_ else math.hypot(*corner)]
    )
    lines += _spin(body.omega, extent)
    couples = 0
    for force, point in zip(body.forces, points, strict=True):
        if force.kind == "couple":
            lines.append(_couple(force, at(point), COUPLE_MM + 3.0 * couples, label(force)))
            couples += 1
            continue
        unit = unit_of(force.dx, force.dy)
        room = _room(body.shape, at(footprint) if footprint else None, unit)
        start = _off_surface(body, force, at(point))
        lines.append(_arrow(force, point, start, unit, room, label(force)))
    lines.append(r"\end{tikzpicture}")
    picture = "\n".join(lines)
    if kinetic_label is None or not body.kinetic:
        return picture
    kinetic = _kinetic(body, outline, at, kinetic_label)
    return picture if kinetic is None else f"{picture}\n\\quad$=$\\quad\n{kinetic}"


def footprint_of(body: FreeBody) -> Point | None:
    """Half the width and height of the body's outline (metres), or None without one.

    >>> from dynsolve.results import FreeBody
    >>> footprint_of(FreeBody("crate", "block", (1.0, 0.5), "translation", (), (), ""))
    (0.5, 0.25)
    """
    if body.parts:  # a composite: the box around its parts, centred on G
        corners = [
            (abs(x) + reach, abs(y) + reach)
            for shape, x, y, sizes, *_ in body.parts
            for reach in (reach_of(shape, sizes),)
        ]
        return (max(c[0] for c in corners), max(c[1] for c in corners))
    sizes = [abs(_finite(v)) for v in body.size]
    first = sizes[0] if sizes else 0.0
    shape = body.shape.strip().lower()
    if shape == "particle":
        return (0.0, 0.0)
    if not first:
        return None
    if shape in ROUND_SHAPES:
        return (first, first)
    if shape == "rod":
        return (first / 2, 0.0)
    if shape in ("block", "plate"):
        height = sizes[1] if len(sizes) > 1 and sizes[1] else first
        return (first / 2, height / 2)
    return None


def reach_of(shape: str, sizes: tuple) -> float:
    """How far a shape reaches from its own centre (in the units of ``sizes``): a block's or
    plate's half diagonal, a rod's half length, a round body's radius.

    >>> reach_of("block", (6.0, 8.0)), reach_of("rod", (2.0,)), reach_of("disk", (0.3,))
    (5.0, 1.0, 0.3)
    """
    first = abs(sizes[0]) if sizes else 0.0
    if shape in ("block", "plate"):
        return math.hypot(first, abs(sizes[1]) if len(sizes) > 1 else first) / 2
    return first / 2 if shape == "rod" else first


def num(value: float) -> str:
    """A coordinate in millimetres, to 0.01 mm, without trailing zeros.

    >>> num(17.5), num(-0.001), num(2.0)
    ('17.5', '0', '2')
    """
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def polar(centre: Point, radius: float, degrees: float) -> Point:
    """The point at ``radius`` from ``centre`` in the direction ``degrees`` (ccw from +x)."""
    angle = math.radians(degrees)
    return (centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle))


def fit(
    reach: Sequence[Point], width: float, height: float
) -> tuple[Callable[[Point], Point], float]:
    """The map from metres to the page (mm, the points' box centred on 0) that fits
    ``reach`` into ``width`` by ``height`` mm, and its scale (mm per metre; 1000 for a
    single point).

    >>> at, scale = fit([(0.0, 0.0), (2.0, 1.0)], 80.0, 60.0)
    >>> scale, at((2.0, 1.0))
    (40.0, (40.0, 20.0))
    """
    xs, ys = [p[0] for p in reach] or [0.0], [p[1] for p in reach] or [0.0]
    span_x, span_y = max(xs) - min(xs), max(ys) - min(ys)
    scale = min(
        width / span_x if span_x > 0 else math.inf,
        height / span_y if span_y > 0 else math.inf,
    )
    scale = scale if math.isfinite(scale) else 1000.0
    middle = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)

    def at(point: Point) -> Point:
        return ((point[0] - middle[0]) * scale, (point[1] - middle[1]) * scale)

    return at, scale


def unit_of(dx: float, dy: float) -> Point | None:
    """The direction as a unit vector, or None when there is none.

    >>> unit_of(3.0, 4.0), unit_of(0.0, 0.0)
    ((0.6, 0.8), None)
    """
    dx, dy = _finite(dx), _finite(dy)
    largest = max(abs(dx), abs(dy))
    if largest == 0:
        return None
    dx, dy = dx / largest, dy / largest  # no overflow in hypot
    norm = math.hypot(dx, dy)
    return (dx / norm, dy / norm)


def _finite(value: float) -> float:
    return value if math.isfinite(value) else 0.0


def _xy(point: Point) -> str:
    return f"({num(point[0])},{num(point[1])})"


def _outline(body: FreeBody, footprint: Point | None, at: Callable[[Point], Point]) -> list[str]:
    """The body's outline: circle (with a hub), bar, rectangle, dot, or around its points."""
    shape = body.shape.strip().lower()
    if body.parts:
        per_metre = at((1.0, 0.0))[0]
        return [
            line
            for part, x, y, sizes, angle, hole in body.parts
            for line in shape_lines(
                part, at((x, y)), tuple(abs(v) * per_metre for v in sizes), angle, hole
            )
        ]
    if footprint == (0.0, 0.0):
        return [r"\fill (0,0) circle[radius=1.25];"]
    if footprint is not None:
        hx, hy = at(footprint)
        if shape in ROUND_SHAPES:
            hub = f"\\draw[thin] (0,0) circle[radius={num(0.15 * hx)}];"
            return [f"\\draw[very thick] (0,0) circle[radius={num(hx)}];"] + (
                [hub] if shape in HUBBED else []
            )
        if shape == "rod":
            ux, uy = _rod_axis(body)
            return [
                f"\\draw[line width=2.4pt,line cap=round] {_xy((-hx * ux, -hx * uy))} -- "
                f"{_xy((hx * ux, hx * uy))};"
            ]
        return [f"\\draw[very thick] ({num(-hx)},{num(-hy)}) rectangle ({num(hx)},{num(hy)});"]
    points = [at((_finite(f.x), _finite(f.y))) for f in body.forces if f.kind != "couple"]
    reach = max((math.hypot(*p) for p in points), default=0.0)
    if reach > SQUARE_MM / 2:  # a body given by its radius of gyration: a drum, a spool
        return [
            f"\\draw[very thick] (0,0) circle[radius={num(reach)}];",
            f"\\draw[thin] (0,0) circle[radius={num(0.15 * reach)}];",
        ]
    hx = max([SQUARE_MM / 2, *(abs(p[0]) for p in points)])
    hy = max([SQUARE_MM / 2, *(abs(p[1]) for p in points)])
    return [
        f"\\draw[very thick,rounded corners=2mm] ({num(-hx)},{num(-hy)}) rectangle "
        f"({num(hx)},{num(hy)});"
    ]


def shape_lines(
    shape: str, centre: Point, sizes: tuple[float, ...], angle: float, hole: bool = False
) -> list[str]:
    r"""The outline of one shape on the page (sizes in mm, ``angle`` in degrees ccw): a
    circle with a hub (disk, drum), a bar (rod), a rectangle (block, plate), a dot
    (particle); a hole is drawn dashed and white inside.

    >>> print(*shape_lines("rod", (0.0, 0.0), (10.0,), 90.0))
    \draw[line width=2.4pt,line cap=round] (0,-5) -- (0,5);
    """
    first = sizes[0] if sizes else 0.0
    style = "thick,dashed,fill=white" if hole else "very thick,fill=white"
    if shape == "particle" or not first:
        return [f"\\fill {_xy(centre)} circle[radius=1.25];"]
    if shape in ROUND_SHAPES:
        hub = (
            []
            if hole or shape not in HUBBED
            else [f"\\draw[thin] {_xy(centre)} circle[radius={num(0.12 * first)}];"]
        )
        return [f"\\draw[{style}] {_xy(centre)} circle[radius={num(first)}];", *hub]
    if shape == "rod":
        a, b = polar(centre, first / 2, angle + 180.0), polar(centre, first / 2, angle)
        return [f"\\draw[line width=2.4pt,line cap=round] {_xy(a)} -- {_xy(b)};"]
    height = sizes[1] if len(sizes) > 1 and sizes[1] else first
    return [
        f"\\draw[{style},rotate around={{{num(angle)}:{_xy(centre)}}}] "
        f"({num(centre[0] - first / 2)},{num(centre[1] - height / 2)}) rectangle "
        f"({num(centre[0] + first / 2)},{num(centre[1] + height / 2)});"
    ]


def _rod_axis(body: FreeBody) -> Point:
    """A rod's direction on the page: along its force points off G where they all lie on
    one line through G (a pin at its end, a load at the other), else horizontal.

    >>> from dynsolve.results import ForceRow, FreeBody
    >>> pin = ForceRow("O_n", "reaction", "O", -0.866, 0.5, "", 1.0, 0.0, False, "")
    >>> rod = FreeBody("rod", "rod", (2.0,), "rotation about O", (pin,), (), "")
    >>> tuple(round(c, 3) for c in _rod_axis(rod))
    (0.866, -0.5)
    """
    points = [(_finite(f.x), _finite(f.y)) for f in body.forces if f.kind != "couple"]
    off = [p for p in points if math.hypot(*p) > 1e-9 * (1.0 + max(map(abs, p)))]
    if not off:
        return (1.0, 0.0)
    far = max(off, key=lambda p: math.hypot(*p))
    unit = unit_of(*far)
    assert unit is not None
    for p in off:
        if abs(p[0] * unit[1] - p[1] * unit[0]) > 1e-6 * math.hypot(*far):
            return (1.0, 0.0)  # off the line through G: not a rod's axis
    return unit if unit[0] > 0 or (unit[0] == 0 and unit[1] > 0) else (-unit[0], -unit[1])


def _centre() -> list[str]:
    return [r"\fill (0,0) circle[radius=0.6] node[anchor=north east,inner sep=1pt] {$G$};"]


def _anchor(direction: Point) -> str:
    """The label's anchor for an arrow heading ``direction``: the node sits beyond its end."""
    degrees = math.degrees(math.atan2(-direction[1], -direction[0])) % 360.0
    return num(round(degrees))


def _arrow(
    force: ForceRow, point: Point, start: Point, unit: Point | None, room: float, text: str
) -> str:
    """A force arrow at its point: from it, or into it when it pushes on the body there.

    A force whose direction points back toward G from a point off G (a normal force under
    a body, a push on a face; not friction, which runs along the surface) is drawn ending
    at the point, outside the outline, as textbooks draw pushes.
    An arrow from G is shortened to stay inside the outline (``room`` mm away), if it can.
    """
    style = "force" if force.known else "force,unknown"
    if unit is None:  # no direction: a small circle at the point
        return (
            f"\\draw[{style.replace('force', 'thick')}] {_xy(start)} circle[radius=0.8] "
            f"node[anchor=south,inner sep=2pt] {{{text}}};"
        )
    length = ARROW_MM
    if point == (0.0, 0.0) and room > 0:
        length = max(6.0, min(ARROW_MM, 0.8 * room))
    # a push: the force heads back toward G (a normal force, a push on a face); friction,
    # along the surface, is drawn from its point
    toward_G = point[0] * unit[0] + point[1] * unit[1] < 0
    pushes = point != (0.0, 0.0) and toward_G and not force.kind.startswith("friction")
    outward = (-unit[0], -unit[1]) if pushes else unit
    far = (start[0] + length * outward[0], start[1] + length * outward[1])
    tail, tip = (far, start) if pushes else (start, far)
    place = "at start," if pushes else ""  # the label beyond the far end, either way
    node = f"node[{place}anchor={_anchor(outward)}] {{{text}}}"
    return f"\\draw[{style},->] {_xy(tail)} -- {_xy(tip)} {node};"


def _off_surface(body: FreeBody, force: ForceRow, start: Point) -> Point:
    """Where a friction force is drawn: ``SURFACE_MM`` outside the surface, away from the
    normal force at the same point (which pushes into the body), so that the arrow does
    not lie on the outline; any other force at its point."""
    if not force.kind.startswith("friction"):
        return start
    for other in body.forces:
        if other is not force and other.point == force.point and other.kind == "reaction":
            normal = unit_of(other.dx, other.dy)
            along = unit_of(force.dx, force.dy)
            if (
                normal is None
                or along is None
                or abs(normal[0] * along[0] + normal[1] * along[1]) > 0.1
            ):
                continue
            return (start[0] - SURFACE_MM * normal[0], start[1] - SURFACE_MM * normal[1])
    return start


def _spin(sense: str, extent: float) -> list[str]:
    """The body's ω at the instant: an arc over its upper left, 4 mm beyond the farthest
    drawn point (``extent`` mm from G; at least 14 mm), pointing the way the body turns."""
    if sense not in ("ccw", "cw"):
        return []
    radius = max(14.0, extent + 4.0)
    start, end = (100.0, 160.0) if sense == "ccw" else (160.0, 100.0)
    return [
        f"\\draw[spin] {_xy(polar((0.0, 0.0), radius, start))} arc[start angle={num(start)},"
        f"end angle={num(end)},radius={num(radius)}] node[anchor=310,pos=0.5] {{$\\omega$}};"
    ]


def _pin_and_distance(
    body: FreeBody, at: Callable[[Point], Point], length_label: Callable[[float], str] | None
) -> list[str]:
    """A pin off G as a hole with its name, and the distance O–G as a dimension line beside
    the line from the pin to G (on the side away from the body's forces, below or left)."""
    found = _pin_force(body)
    if found is None:
        return []
    name, (px, py) = found
    pin = at((px, py))
    reach = math.hypot(*pin)
    if reach < 1.0:
        return []  # the pin is at G: the G mark stands for it
    away = unit_of(pin[0], pin[1])
    assert away is not None
    text = f"${name}$" if name.isalnum() and name.isascii() else ""
    lines = [
        f"\\draw[pin] {_xy(pin)} circle[radius={num(PIN_MM)}] "
        f"node[anchor={_anchor(away)},inner sep=2pt] {{{text}}};"
    ]
    if length_label is None:
        return lines
    side = (away[1], -away[0])  # perpendicular, clockwise of G→pin
    if side[1] > 0 or (side[1] == 0 and side[0] > 0):
        side = (-side[0], -side[1])  # below or to the left
    offset = (DIMENSION_MM * side[0], DIMENSION_MM * side[1])
    a, b = (offset[0], offset[1]), (pin[0] + offset[0], pin[1] + offset[1])
    distance = math.hypot(px, py)
    lines += [
        f"\\draw[very thin,gray] (0,0) -- {_xy((1.3 * offset[0], 1.3 * offset[1]))} "
        f"{_xy(pin)} -- {_xy((pin[0] + 1.3 * offset[0], pin[1] + 1.3 * offset[1]))};",
        f"\\draw[dimension] {_xy(a)} -- {_xy(b)} node[pos=0.5,anchor={_anchor(side)},"
        f"inner sep=1.5pt,fill=white] {{{length_label(distance)}}};",
    ]
    return lines


def _room(shape: str, half: Point | None, unit: Point | None) -> float:
    """How far (mm) the outline is from G in direction ``unit``; 0 for a rod or a dot."""
    if half is None or not half[0] or not half[1] or unit is None:
        return 0.0
    if shape.strip().lower() in ROUND_SHAPES:
        return half[0]
    return min(h / abs(u) for h, u in zip(half, unit, strict=True) if u)


def _couple(force: ForceRow, centre: Point, radius: float, text: str) -> str:
    """A couple: a 270-degree arc around its point, open at the bottom (a weight at G
    passes through the gap), its label outside, upper right (ccw) or upper left (cw)."""
    clockwise = force.direction.strip().lower() in ("cw", "clockwise")
    start, end = (225.0, -45.0) if clockwise else (-45.0, 225.0)
    style = "force" if force.known else "force,unknown"
    corner = 135.0 if clockwise else 45.0
    label_at = polar(centre, radius + 1.0, corner)
    sense = "cw" if clockwise else "ccw"
    return (
        f"\\draw[{style},->] {_xy(polar(centre, radius, start))} arc[start angle={num(start)},"
        f"end angle={num(end)},radius={num(radius)}]; "
        f"\\node[anchor={num(corner + 180)}] at {_xy(label_at)} {{{text} ({sense})}};"
    )


def _kinetic(
    body: FreeBody,
    outline: Sequence[str],
    at: Callable[[Point], Point],
    label: Callable[[str], str],
) -> str | None:
    """The kinetic diagram: the outline with each term it can place as a blue arrow
    (m (a_G)_x along +x, m (a_G)_y along +y, m (a_G)_t and m α r down an incline,
    m (a_G)_n out of it, I α counterclockwise, m ω² r_G toward the pin, m α r_G across
    it); None when it can place none."""
    arrows = []
    directions: list[Point] = []
    couple = None
    pin = _pin(body, at)
    for term in body.kinetic:
        words = term.replace("(", " ").replace(")", " ").split()
        key = "".join(words)
        direction: Point | None = None
        if key in ("ma_Gx", "ma_G_x"):
            direction = (1.0, 0.0)
        elif key in ("ma_Gy", "ma_G_y"):
            direction = (0.0, 1.0)
        elif body.axes is not None and key in ("ma_G_t", "ma_Gt", "mαr"):
            direction = body.axes[0]  # along the incline, down the slope
        elif body.axes is not None and key in ("ma_G_n", "ma_Gn"):
            direction = body.axes[1]
        elif key.endswith("α") and key.startswith("I_"):
            couple = term
            continue
        elif pin is not None and key in ("mω²r_G", "mαr_G"):
            toward = unit_of(pin[0], pin[1])
            if toward is None:
                continue
            direction = toward if key.startswith("mω") else (-toward[1], toward[0])
        if direction is None:
            continue
        directions.append(direction)
        tip = (ARROW_MM * direction[0], ARROW_MM * direction[1])
        arrows.append(
            f"\\draw[kinetic] (0,0) -- {_xy(tip)} node[anchor={_anchor(direction)}] "
            f"{{{label(term)}}};"
        )
    if couple is not None:
        arrows.append(_kinetic_couple(label(couple), directions))
    if not arrows:
        return None
    return "\n".join(
        [f"\\begin{{tikzpicture}}[x=1mm,y=1mm,{STYLES}]", *outline, *_centre(), *arrows,
         r"\end{tikzpicture}"]
    )  # fmt: skip


def _kinetic_couple(text: str, directions: Sequence[Point]) -> str:
    """I α as a counterclockwise arc around G, its label where no kinetic arrow runs (upper
    right unless an arrow heads there; then upper left, lower right or below)."""
    corner = max(
        (45.0, 135.0, 300.0, 270.0),
        key=lambda a: (
            min(
                (
                    math.dist((math.cos(math.radians(a)), math.sin(math.radians(a))), d)
                    for d in directions
                ),
                default=2.0,
            )
            > 0.8
        ),
    )
    return (
        f"\\draw[kinetic] {_xy(polar((0.0, 0.0), COUPLE_MM, -45.0))} arc[start angle=-45,"
        f"end angle=225,radius={num(COUPLE_MM)}]; "
        f"\\node[anchor={num((corner + 180.0) % 360.0)}] at "
        f"{_xy(polar((0.0, 0.0), COUPLE_MM + 1.0, corner))} {{{text}}};"
    )


def _pin(body: FreeBody, at: Callable[[Point], Point]) -> Point | None:
    """Where the body's pin is on the page (its motion says "rotation about O" and a force
    acts at O), or None."""
    found = _pin_force(body)
    return None if found is None else at(found[1])


def _pin_force(body: FreeBody) -> tuple[str, Point] | None:
    """The body's pin, its name and where it is (metres from G), or None."""
    if "rotation about " not in body.motion:
        return None
    name = body.motion.rsplit("rotation about ", 1)[1].strip().rstrip(".")
    for force in body.forces:
        if force.point == name:
            return name, (_finite(force.x), _finite(force.y))
    return None
