"""Where every joint of a linkage is at the instant: given, built along bars, or by loop closure.

Fixed points and joints placed with ``joint P: (x, y)`` stay exact expressions of the
givens; a bar with a length and an angle from a placed point places its other end (also
exact). Any joint left is found by *loop closure*: each bar's length (and angle) and each
slider's guide is an equation in the unknown coordinates, solved numerically from many
starting points for every real solution, each polished to 30 digits. Where several
assemblies fit, the scene's rule picks one (``joint P: near (x, y)``: the nearest;
``branch open|crossed`` for a four-bar loop); without a rule the error lists them, and
with one the others are reported beside the answer.

>>> import sympy
>>> from dynsolve.linkage.model import Bar, Linkage
>>> r = sympy.Rational
>>> four_bar = Linkage("p.dyn", {"A": (0, 0), "D": (r(1), 0)}, {}, {}, {
...     "AB": Bar("AB", ("A", "B"), r(1, 2), sympy.pi / 2),
...     "BC": Bar("BC", ("B", "C"), r(1)),
...     "CD": Bar("CD", ("C", "D"), r(1, 2))}, {}, (), "open")
>>> placed = place(four_bar)
>>> [sympy.N(c, 6) for c in placed.positions["C"]], placed.rule
([1.00000, 0.500000], 'open assembly (branch open)')
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.linkage.model import Linkage
from dynsolve.model.scene import Vec
from dynsolve.numbers import tidy

DIGITS = 30  # the loop closure's working precision
STARTS = 48  # starting points of the loop-closure root search
MIRRORS = 60  # more starts, mirror images of each assembly found
NEWTON_STEPS = 60  # damped Newton steps from each start
SAME = 1e-7  # two assemblies closer than this (relative to the linkage's size) are one
AGREE = 1e-9  # a given geometry may miss its bars' lengths by this fraction


@dataclass(frozen=True)
class Placement:
    """Every joint at the instant, how each was placed, and the assemblies not taken."""

    positions: Mapping[str, Vec]
    how: Mapping[str, str]  # moving joint -> "given", "bar AB's length and angle", …
    closure: tuple[str, ...]  # the loop-closure equations, as text ("|C − B| = L_BC")
    others: tuple[Mapping[str, tuple[float, float]], ...]  # assemblies not taken
    rule: str  # how the assembly was chosen ("the only assembly", "nearest the sketch")


def place(linkage: Linkage) -> Placement:
    """Place every joint of ``linkage`` (see the module docstring)."""
    positions: dict[str, Vec] = {**linkage.fixed, **linkage.given}
    how = {p: "given" for p in linkage.given}
    _build_along_bars(linkage, positions, how)
    unknown = [p for p in linkage.joints if p not in positions]
    _check_given(linkage, positions, unknown)
    if not unknown:
        return Placement(positions, how, (), (), "")
    residuals, texts = _closure(linkage, positions, unknown)
    solutions = _solve_all(linkage, residuals, unknown, positions)
    if not solutions:
        raise SpecError(
            f"the linkage cannot be assembled: no position of {', '.join(unknown)} fits "
            f"{'; '.join(texts)}",
            linkage.where(unknown[0]),
            hint="check the lengths and the input angle (the bars are too short to close "
            "the loop, or a slider's guide is out of reach)",
        )
    taken, rule = _choose(linkage, solutions, unknown, positions)
    for point in unknown:
        x, y = solutions[taken][point]
        positions[point] = (sympy.Float(x, DIGITS), sympy.Float(y, DIGITS))
        how[point] = "loop closure"
    others = tuple(
        {p: (float(s[p][0]), float(s[p][1])) for p in unknown}
        for i, s in enumerate(solutions)
        if i != taken
    )
    return Placement(positions, how, tuple(texts), others, rule)


def _build_along_bars(linkage: Linkage, positions: dict[str, Vec], how: dict[str, str]) -> None:
    """Place the far end of every bar with a length and an angle from a placed end."""
    changed = True
    while changed:
        changed = False
        for bar in linkage.bars.values():
            if bar.length is None or bar.angle is None or len(bar.points) != 2:
                continue
            first, second = bar.points
            step = (bar.length * sympy.cos(bar.angle), bar.length * sympy.sin(bar.angle))
            if first in positions and second not in positions:
                start = positions[first]
                positions[second] = (tidy(start[0] + step[0]), tidy(start[1] + step[1]))
                how[second] = f"{bar.name}'s length and angle from {first}"
                changed = True
            elif second in positions and first not in positions:
                end = positions[second]
                positions[first] = (tidy(end[0] - step[0]), tidy(end[1] - step[1]))
                how[first] = f"{bar.name}'s length and angle to {second}"
                changed = True


def _numbers(linkage: Linkage, vector: Vec) -> tuple[float, float] | None:
    try:
        return tuple(  # type: ignore[return-value]
            float(sympy.N((sympy.Integer(0) + c).xreplace(dict(linkage.values)), 20))
            for c in vector
        )
    except TypeError:  # symbols remain
        return None


def _check_given(linkage: Linkage, positions: Mapping[str, Vec], unknown: Sequence[str]) -> None:
    """A bar whose ends are all placed must have the length and angle it states, and a
    placed slider must lie on its guide; a bar of three or more points, its shape unknown,
    must have every point placed."""
    for bar in linkage.bars.values():
        missing = [p for p in bar.points if p in unknown]
        if len(bar.points) > 2 and missing:
            raise SpecError(
                f"bar {bar.name} has {len(bar.points)} points, so its shape comes from their "
                f"positions, but {', '.join(missing)} {'is' if len(missing) == 1 else 'are'} "
                "not placed",
                linkage.where(bar.name),
                hint=f"place it with 'joint {missing[0]}: (x, y)'",
            )
        if missing or len(bar.points) != 2:
            continue
        first, second = (_numbers(linkage, positions[p]) for p in bar.points)
        if first is None or second is None:
            continue
        dx, dy = second[0] - first[0], second[1] - first[1]
        span = math.hypot(dx, dy)
        if bar.length is not None:
            length = _numbers(linkage, (bar.length, 0))
            if length is not None and abs(span - length[0]) > AGREE * max(length[0], span):
                raise SpecError(
                    f"bar {bar.name}: its ends are placed {span:.6g} apart (base units), but "
                    f"its length is {length[0]:.6g}",
                    linkage.where(bar.name),
                    hint="the positions and the length disagree: fix one, or drop the length",
                )
        if bar.angle is not None:
            angle = _numbers(linkage, (bar.angle, 0))
            if angle is not None and span > 0:
                off = abs(dx * math.sin(angle[0]) - dy * math.cos(angle[0]))
                if off > AGREE * span or dx * math.cos(angle[0]) + dy * math.sin(angle[0]) < 0:
                    raise SpecError(
                        f"bar {bar.name}: the direction from {bar.points[0]} to "
                        f"{bar.points[1]} is {math.degrees(math.atan2(dy, dx)):.4g}°, "
                        f"but its angle is {math.degrees(angle[0]):.4g}°",
                        linkage.where(bar.name),
                        hint="the angle is measured from +x, ccw, from the first point to "
                        "the second",
                    )
    for mesh in linkage.meshes:
        one, two = (linkage.bars[b].points[0] for b in (mesh.first, mesh.second))
        if one in unknown or two in unknown:
            continue
        first, second = _numbers(linkage, positions[one]), _numbers(linkage, positions[two])
        radii = _numbers(linkage, mesh.radii)
        if first is None or second is None or radii is None:
            continue
        span = math.hypot(second[0] - first[0], second[1] - first[1])
        apart = abs(radii[0] - radii[1]) if mesh.internal else sum(radii)
        if abs(span - apart) > AGREE * max(span, apart):
            how = "differ by" if mesh.internal else "add up to"
            raise SpecError(
                f"gears {mesh.first} and {mesh.second}: their centres are {span:.6g} apart "
                f"(base units), but their radii {how} {apart:.6g}",
                Position(linkage.file, mesh.line, mesh.column),
                hint="gears in external mesh have their centres r_1 + r_2 apart; in internal "
                "mesh (', internal': a ring gear) the difference of the radii",
            )
    for slider in linkage.sliders.values():
        if slider.bar:
            ends = linkage.bars[slider.bar].points[:2]
            if slider.point in unknown or set(ends) & set(unknown):
                continue
            point, first, second = (_numbers(linkage, positions[p]) for p in (slider.point, *ends))
            if point is None or first is None or second is None:
                continue
            dx, dy = second[0] - first[0], second[1] - first[1]
            off = ((point[0] - first[0]) * dy - (point[1] - first[1]) * dx) / math.hypot(dx, dy)
            if abs(off) > AGREE * max(math.hypot(dx, dy), math.hypot(*point)):
                raise SpecError(
                    f"{slider.point} is placed {abs(off):.6g} (base units) off bar "
                    f"{slider.bar}, along which it slides",
                    linkage.where(slider.point),
                    hint=f"place {slider.point} on the line through {' and '.join(ends)}",
                )
            continue
        if slider.point in unknown:
            continue
        on = positions[slider.point]
        through = positions.get(slider.through, on) if slider.through else on
        point, base = _numbers(linkage, on), _numbers(linkage, through)
        assert slider.axis is not None
        axis = _numbers(linkage, slider.axis)
        if point is None or base is None or axis is None:
            continue
        off = (point[0] - base[0]) * axis[1] - (point[1] - base[1]) * axis[0]
        size = max(math.hypot(*point), math.hypot(*base), 1e-300)
        if abs(off) > AGREE * size:
            raise SpecError(
                f"slider {slider.point} is placed {abs(off):.6g} (base units) off its guide "
                f"through {slider.through}",
                linkage.where(slider.point),
                hint="place the joint on the guide, or move the guide",
            )


def _closure(
    linkage: Linkage, positions: Mapping[str, Vec], unknown: Sequence[str]
) -> tuple[list[sympy.Expr], list[str]]:
    """The loop-closure equations (residuals, zero when met) in the coordinates of the
    unknown joints ``x_P``, ``y_P``, and how each reads."""
    coords = {
        p: (sympy.Symbol(f"x_{p}", real=True), sympy.Symbol(f"y_{p}", real=True)) for p in unknown
    }
    where = {**positions, **coords}
    residuals: list[sympy.Expr] = []
    texts: list[str] = []
    for bar in linkage.bars.values():
        if len(bar.points) != 2 or not set(bar.points) & set(unknown):
            continue
        first, second = bar.points
        dx = where[second][0] - where[first][0]
        dy = where[second][1] - where[first][1]
        if bar.angle is not None:
            c, s = sympy.cos(bar.angle), sympy.sin(bar.angle)
            residuals.append(dx * s - dy * c)
            texts.append(f"{first}{second} along angle {sympy.sstr(bar.angle)}")
            if bar.length is not None:
                residuals.append(dx * c + dy * s - bar.length)
                texts.append(f"|{second} − {first}| = {sympy.sstr(bar.length)}")
        elif bar.length is not None:
            residuals.append((dx**2 + dy**2 - bar.length**2) / bar.length)
            texts.append(f"|{second} − {first}| = {sympy.sstr(bar.length)}")
    for slider in linkage.sliders.values():
        if slider.bar:
            bar = linkage.bars[slider.bar]
            first, second = bar.points[:2]
            if not {slider.point, first, second} & set(unknown):
                continue
            px = where[slider.point][0] - where[first][0]
            py = where[slider.point][1] - where[first][1]
            qx, qy = where[second][0] - where[first][0], where[second][1] - where[first][1]
            residuals.append((px * qy - py * qx) / (bar.length or 1))
            texts.append(f"{slider.point} on bar {slider.bar}")
            continue
        if slider.point not in unknown:
            continue
        if not slider.through:
            raise SpecError(
                f"slider {slider.point}'s guide needs a point it passes through",
                linkage.where(slider.point),
                hint=f"write 'slider {slider.point}: along DIR, through POINT'",
            )
        base = positions[slider.through]
        dx = where[slider.point][0] - base[0]
        dy = where[slider.point][1] - base[1]
        assert slider.axis is not None
        residuals.append(dx * slider.axis[1] - dy * slider.axis[0])
        texts.append(f"{slider.point} on its guide through {slider.through}")
    for mesh in linkage.meshes:
        one, two = (linkage.bars[b].points[0] for b in (mesh.first, mesh.second))
        if not {one, two} & set(unknown):
            continue
        dx, dy = where[two][0] - where[one][0], where[two][1] - where[one][1]
        span = mesh.span(linkage.values, linkage.file)
        residuals.append((dx**2 + dy**2 - span**2) / span)
        texts.append(f"|{two} − {one}| = {sympy.sstr(span)} (gears in mesh)")
    if len(residuals) != 2 * len(unknown):
        count = 2 * len(unknown)
        fewer = len(residuals) < count
        raise SpecError(
            f"the positions of {', '.join(unknown)} are "
            + ("not fixed" if fewer else "over-determined")
            + f": {count} coordinates, {len(residuals)} conditions "
            f"({'; '.join(texts) or 'none'})",
            linkage.where(unknown[0]),
            hint=(
                "give the input angle ('bar AB: A to B, length L, angle theta'), the bars' "
                "lengths, or place the joints ('joint C: (x, y)')"
                if fewer
                else "drop a length or an angle that the others already fix"
            ),
        )
    return residuals, texts


def _solve_all(
    linkage: Linkage,
    residuals: list[sympy.Expr],
    unknown: Sequence[str],
    positions: Mapping[str, Vec],
) -> list[dict[str, tuple[sympy.Float, sympy.Float]]]:
    """Every real solution of the loop closure, each polished to ``DIGITS`` digits."""
    import mpmath
    import numpy

    coords = [sympy.Symbol(f"{axis}_{p}", real=True) for p in unknown for axis in "xy"]
    numeric = [r.xreplace(dict(linkage.values)) for r in residuals]
    symbolic = set().union(*(r.free_symbols for r in numeric)) - set(coords)
    if symbolic:
        names = ", ".join(sorted(s.name for s in symbolic))
        raise SpecError(
            f"placing {', '.join(unknown)} needs a loop closure, solved with numbers, but "
            f"{names} {'is' if len(symbolic) == 1 else 'are'} symbolic",
            linkage.where(unknown[0]),
            hint="give values to the givens, or place the joints at the instant "
            "('joint C: (x, y)') to keep the answer symbolic",
        )
    f_np = sympy.lambdify(coords, numeric, "numpy")
    known = [p for p in (_numbers(linkage, v) for v in positions.values()) if p is not None]
    lengths = [
        v[0]
        for v in (_numbers(linkage, (b.length, 0)) for b in linkage.bars.values() if b.length)
        if v is not None
    ]
    size = max([*lengths, *(math.hypot(*p) for p in known), 1e-300])
    centre = numpy.mean(known, axis=0) if known else numpy.zeros(2)
    rng = numpy.random.default_rng(0)
    sketch = [_numbers(linkage, linkage.near[p]) if p in linkage.near else None for p in unknown]
    starts = [
        numpy.array([c for xy in sketch for c in xy], dtype=float)  # type: ignore[union-attr]
        for _ in (0,)
        if all(xy is not None for xy in sketch)
    ]
    starts += [
        numpy.tile(centre, len(unknown)) + rng.uniform(-2 * size, 2 * size, 2 * len(unknown))
        for _ in range(STARTS)
    ]
    found: list[list[mpmath.mpf]] = []
    f_mp = sympy.lambdify(coords, numeric, "mpmath")
    with mpmath.workdps(DIGITS + 5):
        for start in starts:
            found_at = _newton(
                lambda z: numpy.asarray(f_np(*z), dtype=float),
                lambda z: _step_jacobian(f_np, z, size),
                start,
                size,
            )
            if found_at is None or any(
                max(abs(float(a) - float(b)) for a, b in zip(found_at, other, strict=True))
                < SAME * size
                for other in found
            ):
                continue
            try:
                polished = mpmath.findroot(
                    lambda *z: f_mp(*z),
                    [mpmath.mpf(float(v)) for v in found_at],
                    J=lambda *z: _step_jacobian_mp(f_mp, z, size),
                    tol=mpmath.mpf(10) ** (-2 * DIGITS),
                    maxsteps=60,
                    verify=False,
                )
            except (ValueError, ZeroDivisionError):  # singular: a toggle or dead position
                polished = [mpmath.mpf(float(v)) for v in found_at]
            values = [polished[i] for i in range(len(coords))]
            if any(
                max(abs(float(a) - float(b)) for a, b in zip(values, other, strict=True))
                < SAME * size
                for other in found
            ):
                continue
            found.append(values)
            if len(starts) < STARTS + MIRRORS:  # the other assemblies are mirror images
                starts += _mirrors(found_at, known)
    found.sort(key=lambda v: [round(float(c) / size, 6) for c in v])

    def snapped(value: mpmath.mpf) -> sympy.Float:  # on a guide through the origin: 0
        if abs(value) < 10 ** (5 - DIGITS) * size:
            return sympy.Float(0, DIGITS)
        return sympy.Float(mpmath.nstr(value, DIGITS + 5, strip_zeros=False), DIGITS)

    return [
        {p: (snapped(v[2 * i]), snapped(v[2 * i + 1])) for i, p in enumerate(unknown)}
        for v in found
    ]


def _step_jacobian(f: Callable[..., Any], z: Any, size: float) -> Any:
    """The Jacobian of the loop-closure residuals ``f`` at ``z`` in float64 by complex
    steps: column j is Im f(z + i h e_j)/h. The residuals are polynomials in the
    coordinates, so this is their derivative to the last digit (no difference cancels,
    whatever h; h = 1e-30 of the linkage's size), without sympy's symbolic Jacobian.

    >>> import numpy
    >>> f = lambda x, y: [x**2 + y**2 - 1, x - y]
    >>> _step_jacobian(f, numpy.array([0.6, 0.8]), 1.0).round(12).tolist()
    [[1.2, 1.6], [1.0, -1.0]]
    """
    import numpy

    step = 1e-30 * size
    columns = []
    for j in range(len(z)):
        point = numpy.array(z, dtype=complex)
        point[j] += 1j * step
        columns.append(numpy.asarray(f(*point), dtype=complex).imag / step)
    return numpy.array(columns).T


def _step_jacobian_mp(f: Callable[..., Any], z: Sequence[Any], size: float) -> Any:
    """:func:`_step_jacobian` in mpmath at the working precision (h 10 digits below it).

    >>> import mpmath
    >>> f = lambda x, y: [x**2 + y**2 - 1, x - y]
    >>> J = _step_jacobian_mp(f, [mpmath.mpf("0.6"), mpmath.mpf("0.8")], 1.0)
    >>> [mpmath.nstr(J[i, j], 12) for i in range(2) for j in range(2)]
    ['1.2', '1.6', '1.0', '-1.0']
    """
    import mpmath

    step = mpmath.mpf(10) ** -(mpmath.mp.dps + 10) * size
    columns = []
    for j in range(len(z)):
        point = [mpmath.mpc(v) + (mpmath.mpc(0, step) if k == j else 0) for k, v in enumerate(z)]
        columns.append([mpmath.im(v) / step for v in f(*point)])
    return mpmath.matrix(columns).T


def _mirrors(solution: Any, known: Sequence[tuple[float, float]]) -> list[Any]:
    """Starting points for the assemblies not yet found: the solution's unknown joints
    reflected in each line through two placed joints (a four-bar's two assemblies are
    mirror images in the line BD)."""
    import numpy

    starts = []
    points = numpy.asarray(solution, dtype=float).reshape(-1, 2)
    for a, b in itertools.combinations(known[:6], 2):
        base, direction = numpy.array(a), numpy.array(b) - numpy.array(a)
        length = float(numpy.hypot(*direction))
        if length == 0:
            continue
        unit = direction / length
        offsets = points - base
        along = offsets @ unit
        mirrored = base + 2 * numpy.outer(along, unit) - offsets
        starts.append(mirrored.reshape(-1))
    return starts


def _newton(
    f: Callable[[Any], Any], jac: Callable[[Any], Any], start: Any, size: float
) -> Any | None:
    """A root of ``f`` near ``start`` by damped Newton steps (halved until |f| falls), or
    None when it does not converge; residuals are lengths, so the tolerance is relative
    to the linkage's ``size``."""
    import numpy

    z = numpy.array(start, dtype=float)
    value = f(z)
    for _ in range(NEWTON_STEPS):
        norm = float(numpy.max(numpy.abs(value)))
        if norm < 1e-12 * size:
            return z
        try:
            step = numpy.linalg.lstsq(jac(z), -value, rcond=None)[0]
        except numpy.linalg.LinAlgError:
            return None
        scale = 1.0
        while scale > 1e-6:
            trial = z + scale * step
            trial_value = f(trial)
            if float(numpy.max(numpy.abs(trial_value))) < norm:
                break
            scale /= 2
        else:
            return None
        z, value = trial, trial_value
    return z if float(numpy.max(numpy.abs(value))) < 1e-8 * size else None


def _choose(
    linkage: Linkage,
    solutions: list[dict[str, tuple[sympy.Float, sympy.Float]]],
    unknown: Sequence[str],
    positions: Mapping[str, Vec],
) -> tuple[int, str]:
    """Which assembly to take, and the rule that took it."""
    if len(solutions) == 1 and not linkage.branch:
        return 0, "the only assembly"
    sketched = [p for p in unknown if p in linkage.near]
    if sketched:
        near = {p: _numbers(linkage, linkage.near[p]) for p in sketched}
        if any(v is None for v in near.values()):
            raise SpecError(
                "a rough position ('joint P: near (x, y)') needs numbers",
                linkage.where(sketched[0]),
                hint="give the givens it uses values",
            )
        distances = [
            sum(
                (float(s[p][0]) - near[p][0]) ** 2 + (float(s[p][1]) - near[p][1]) ** 2  # type: ignore[index]
                for p in sketched
            )
            for s in solutions
        ]
        best = min(range(len(solutions)), key=distances.__getitem__)
        return best, "the assembly nearest the sketch position" + (
            "s" if len(sketched) > 1 else ""
        ) + f" of {', '.join(sketched)}"
    if linkage.branch:
        loop = _four_bar_loop(linkage, unknown)
        if loop is None:
            raise SpecError(
                f"'branch {linkage.branch}' picks the assembly of a four-bar loop, and this "
                "linkage has none",
                linkage.where(unknown[0]),
                hint=f"place a joint roughly instead: 'joint {unknown[0]}: near (x, y)'",
            )
        wanted = linkage.branch == "crossed"
        placed = _floats(linkage, positions)
        fitting = [
            i
            for i, s in enumerate(solutions)
            if _crossed(loop, unknown, {**placed, **_floats(linkage, s)}) == wanted
        ]
        if len(fitting) != 1:
            raise SpecError(
                f"{'no' if not fitting else 'more than one'} {linkage.branch} assembly of "
                f"loop {'-'.join(loop)} exists here",
                linkage.where(unknown[0]),
                hint="place a joint roughly instead: "
                f"'joint {unknown[0]}: near (x, y)' from the figure",
            )
        return fitting[0], f"{linkage.branch} assembly (branch {linkage.branch})"
    listed = "; ".join(
        ", ".join(f"{p} at ({float(s[p][0]):.4g}, {float(s[p][1]):.4g})" for p in unknown)
        for s in solutions
    )
    raise SpecError(
        f"the linkage can be assembled {len(solutions)} ways: {listed} (base units)",
        linkage.where(unknown[0]),
        hint=f"say which: 'joint {unknown[0]}: near (x, y)' with a rough position from the "
        "figure"
        + (", or 'branch open' / 'branch crossed'" if _four_bar_loop(linkage, unknown) else ""),
    )


def _floats(linkage: Linkage, positions: Mapping[str, Vec]) -> dict[str, tuple[float, float]]:
    out = {}
    for name, vector in positions.items():
        numbers = _numbers(linkage, vector)
        if numbers is not None:
            out[name] = numbers
    return out


def _four_bar_loop(linkage: Linkage, unknown: Sequence[str]) -> tuple[str, ...] | None:
    """A loop of four joints A-B-C-D joined by two-point bars (the ground joining two
    fixed points) through an unknown joint, if the linkage has one."""
    edges = {frozenset(b.points) for b in linkage.bars.values() if len(b.points) == 2}
    edges |= {frozenset(pair) for pair in itertools.combinations(linkage.fixed, 2)}
    joints = linkage.joints
    for loop in itertools.permutations(joints, 4):
        if not set(loop) & set(unknown):
            continue
        if all(frozenset((loop[i], loop[(i + 1) % 4])) in edges for i in range(4)):
            return loop
    return None


def _crossed(
    loop: tuple[str, ...], unknown: Sequence[str], at: Mapping[str, tuple[float, float]]
) -> bool:
    """Whether ``loop``'s assembly is the crossed one: its first unknown joint lies on the
    same side as the opposite joint of the line through its two neighbours (the mirror
    image of the open, convex assembly ABCD, in which C and A lie across BD)."""
    i = next(k for k, p in enumerate(loop) if p in unknown)
    point, before, after, opposite = (at[loop[(i + k) % 4]] for k in (0, -1, 1, 2))
    return _side(before, after, point) * _side(before, after, opposite) > 0


def _side(a: Sequence[float], b: Sequence[float], p: Sequence[float]) -> float:
    """Positive when ``p`` is to the left of the line from ``a`` to ``b``."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
