"""The scene as the textbook's figure, in numbers: where each body, support and load is.

A planar scene's bodies (their shape, G and, for a block or rod, the angle it sits at),
its pins, the surfaces its contacts press on (point and normal), cords, springs, links,
applied forces and couples, and its paths (sampled), all in SI metres with the givens'
values put in, for :mod:`dynsolve.render.scene_figure` to draw. Anything whose position
has no number (a symbolic given) leaves the sketch out: None.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.modes.scene_mode import build_scene_problem
>>> spec = parse_spec('''
... given:
...   m = 10 kg
...   b = 1 m
...   h = 0.5 m
...   P = 100 N
... scene:
...   body crate: mass m, block b by h, at (0, h/2)
...   point C on crate: (0, -h/2)
...   contact crate at C: normal up, mu_k 0.2
...   force P on crate at (-b/2, 0.1*h): right
...   gravity
... find: a = a_G(crate)
... ''', "crate.dyn")
>>> sketch = sketch_of(build_scene_problem(spec).scene)
>>> sketch.bodies[0][:4], sketch.surfaces[0][1:]  # the floor under G, 0.9 m either side
(('crate', 'block', 0.0, 0.25), (0.0, 0.0, 0.0, 1.0, 0.9))
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import sympy

from dynsolve.model.scene import Body, Cord, Scene, Support, Vec
from dynsolve.numbers import real_value
from dynsolve.results import SceneSketch

Point = tuple[float, float]
PATH_SAMPLES = 60
SHAPES = frozenset(
    {"disk", "ring", "cylinder", "sphere", "shell", "hollow", "rod", "block", "plate", "particle"}
)


def sketch_of(scene: Scene) -> SceneSketch | None:
    """The scene's figure in numbers, or None where a position has none (or it is 3D)."""
    values = dict(scene.values)
    try:
        bodies = tuple(_body(body, scene, values) for body in scene.bodies.values())
        pins = tuple(
            (s.point_name, *_point(s.point, values)) for s in scene.supports if s.kind == "pin"
        )
        surfaces = tuple(
            _surface(s, scene, values)
            for s in scene.supports
            if s.kind in ("contact", "rolls", "base") and not s.two_sided
        )
        guides = tuple(
            _surface(s, scene, values)
            for s in scene.supports
            if s.kind == "contact" and s.two_sided and _is_straight(s)
        )
        cords = tuple(_cord(c, values) for c in scene.cords)
        springs = tuple(
            (s.name, *_point(s.point, values), *_point(s.other_point, values))
            for s in scene.springs
        )
        links = tuple(
            (k.name, *_point(k.point, values), *_point(k.other_point, values)) for k in scene.links
        )
        forces = tuple(
            (load.name, *_point(load.point, values), *_unit(load.direction, values))
            for load in scene.loads
            if load.kind == "force"
        )
        couples = tuple(
            (load.name, *_point(scene.bodies[load.body].G, values), load.sense)
            for load in scene.loads
            if load.kind == "couple" and load.body in scene.bodies
        )
    except NoNumber:
        return None
    paths = tuple(
        (name, curve)
        for name, curve in ((n, _path(p, bodies, values)) for n, p in scene.paths.items())
        if curve
    )
    return SceneSketch(
        bodies, pins, surfaces, cords, springs, links, forces, couples, paths,
        scene.gravity is not None, guides,
    )  # fmt: skip


def _is_straight(support: Support) -> bool:
    """A guide along a straight line (a collar's rod, a slot), not a curved path."""
    return (sympy.Integer(0) + support.normal_acceleration) == 0


class NoNumber(Exception):
    """A position or direction without a number: no sketch."""


def _number(expr: sympy.Expr | int, values: Mapping[sympy.Symbol, sympy.Expr]) -> float:
    value = real_value(sympy.Integer(0) + expr, values)
    if value is None or not math.isfinite(value):
        raise NoNumber
    return value


def _point(point: Vec, values: Mapping[sympy.Symbol, sympy.Expr]) -> Point:
    if len(point) != 2:
        raise NoNumber  # a 3D scene: its own figures
    return (_number(point[0], values), _number(point[1], values))


def _unit(direction: Vec, values: Mapping[sympy.Symbol, sympy.Expr]) -> Point:
    x, y = _point(direction, values)
    size = math.hypot(x, y)
    if size == 0:
        raise NoNumber
    return (x / size, y / size)


def _cord(cord: Cord, values: Mapping[sympy.Symbol, sympy.Expr]) -> tuple:
    """(name, x, y, along the cord, how far to its other end): 0 where it runs to a fixed
    support off the figure."""
    x, y = _point(cord.point, values)
    reach = 0.0
    if cord.other_point is not None:
        ox, oy = _point(cord.other_point, values)
        reach = math.hypot(ox - x, oy - y)
    return (cord.name, x, y, *_unit(cord.direction, values), reach)


def _surface(support: Support, scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]) -> tuple:
    """(name, x, y, n_x, n_y, half length): the ground under the body, centred where the
    normal through G meets it and reaching past the body either side."""
    x, y = _point(support.point, values)
    n = _unit(support.normal, values)
    t = (n[1], -n[0])
    body = scene.bodies[support.body]
    gx, gy = _point(body.G, values)
    along = (gx - x) * t[0] + (gy - y) * t[1]
    sizes = [abs(_number(v, values)) for v in body.sizes]
    round_ = body.shape.strip().lower() in ("disk", "ring", "cylinder", "sphere", "shell", "hollow")
    reach = 2 * sizes[0] if round_ and sizes else max(sizes, default=0.0)  # its width
    return (support.point_name, x + along * t[0], y + along * t[1], *n, 0.9 * reach)


def _body(body: Body, scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]) -> tuple:
    """(name, shape, x_G, y_G, sizes, angle in degrees): a block sits square on its contact
    (its base across the contact's normal), a rod lies along its farthest named point."""
    x, y = _point(body.G, values)
    sizes = tuple(_number(s, values) for s in body.sizes)
    shape = "particle" if body.particle else body.shape.strip().lower()
    if body.parts:  # drawn by its parts
        return (body.name, "composite", x, y, (), 0.0, part_outlines(body, scene, values))
    if shape not in SHAPES and not any(sizes):  # a drum given by its k_O: a circle through
        reach = _reach(body, scene, values)  # the farthest point anything acts at
        shape, sizes = ("disk", (reach,)) if reach > 0 else ("particle", ())
    angle = 0.0
    if shape in ("block", "plate"):
        normals = [s.normal for s in scene.supports if s.body == body.name and s.kind != "pin"]
        if normals:
            nx, ny = _unit(normals[0], values)
            angle = math.degrees(math.atan2(ny, nx)) - 90.0
    elif shape == "rod":
        points = [_point(p, values) for p in body.points.values()]
        points += [_point(s.point, values) for s in scene.supports if s.body == body.name]
        off = [(px - x, py - y) for px, py in points if math.hypot(px - x, py - y) > 1e-12]
        if off:
            far = max(off, key=lambda p: math.hypot(*p))
            angle = math.degrees(math.atan2(far[1], far[0]))
    return (body.name, shape, x, y, sizes, angle, ())


def part_outlines(
    body: Body, scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[tuple, ...]:
    """A composite body's parts as drawn: (shape, x, y, sizes, angle in degrees, hole) in
    metres. A rod part lies toward the point of the body (a pin, a named point, another
    part's centre) half its length from its centre, where there is one (a pendulum's rod
    ends at its pin), else level. Raises ``NoNumber`` where a size has no number.

    >>> from dynsolve.spec.parser import parse_spec
    >>> from dynsolve.modes.scene_mode import build_scene_problem
    >>> spec = parse_spec('''
    ... given:
    ...   L = 0.6 m
    ...   m = 2 kg
    ...   R = 0.1 m
    ... scene:
    ...   point O: (0, 0)
    ...   body arm: composite, at (0, 0)
    ...   part arm: mass m, rod L, at (0, -L/2)
    ...   part arm: mass m, disk R, at (0, -L)
    ...   pin arm at O
    ...   gravity
    ... find: alpha = alpha(arm)
    ... ''', "arm.dyn")
    >>> scene = build_scene_problem(spec).scene
    >>> [(p[0], round(p[2], 3), round(p[4])) for p in part_outlines(scene.bodies["arm"], scene, {})]
    [('rod', -0.3, 90), ('disk', -0.6, 0)]
    """
    values = {**scene.values, **values}
    ox, oy = _point(body.origin, values)
    centres = [
        (ox + _number(p.position[0], values), oy + _number(p.position[1], values))
        for p in body.parts
    ]
    anchors = [_point(p, values) for p in body.points.values()]
    anchors += [_point(s.point, values) for s in scene.supports if s.body == body.name]
    out = []
    for part, (x, y) in zip(body.parts, centres, strict=True):
        sizes = tuple(abs(_number(v, values)) for v in part.sizes)
        angle = 0.0
        if part.shape == "rod" and sizes:
            half = sizes[0] / 2
            near = [
                (px - x, py - y)
                for px, py in (*anchors, *centres)
                if abs(math.hypot(px - x, py - y) - half) <= 1e-6 * max(half, 1e-300)
            ]
            if near:
                angle = math.degrees(math.atan2(near[0][1], near[0][0]))
        out.append((part.shape, x, y, sizes, angle, part.hole))
    return tuple(out)


def _reach(body: Body, scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr]) -> float:
    """How far from G the farthest point is where a support, cord or load acts on ``body``."""
    x, y = _point(body.G, values)
    points = list(body.points.values())
    points += [s.point for s in scene.supports if s.body == body.name]
    points += [c.point for c in scene.cords if c.body == body.name]
    points += [c.other_point for c in scene.cords if c.other == body.name and c.other_point]
    points += [load.point for load in scene.loads if load.body == body.name]
    distances = [math.hypot(px - x, py - y) for px, py in (_point(p, values) for p in points)]
    return max(distances, default=0.0)


def _path(path: object, bodies: tuple, values: Mapping[sympy.Symbol, sympy.Expr]) -> tuple:
    """An explicit path y(x) sampled across the bodies' span (a circle x² + y² = R² as its
    circle); () where it cannot be drawn."""
    from dynsolve.model.scene import Path

    assert isinstance(path, Path)
    xs = [b[2] for b in bodies] or [0.0]
    if path.explicit is not None:
        reach = max(1.0, *(abs(x) for x in xs)) * 1.5
        f = (sympy.Integer(0) + path.explicit).xreplace(dict(values))
        if f.free_symbols - {path.x}:
            return ()
        law = sympy.lambdify(path.x, f, "math")
        out = []
        for i in range(PATH_SAMPLES + 1):
            t = -reach + 2 * reach * i / PATH_SAMPLES
            try:
                out.append((t, float(law(t))))
            except (ValueError, ZeroDivisionError, OverflowError):
                continue
        return tuple(out)
    curve = (sympy.Integer(0) + path.curve).xreplace(dict(values))
    r2 = curve - path.x**2 - path.y**2  # x² + y² − R²: −R² left
    if r2.free_symbols or not r2.is_number or float(r2) >= 0:
        return ()
    radius = math.sqrt(-float(r2))
    steps = 4 * PATH_SAMPLES
    return tuple(
        (radius * math.cos(2 * math.pi * i / steps), radius * math.sin(2 * math.pi * i / steps))
        for i in range(steps + 1)
    )
