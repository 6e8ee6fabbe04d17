"""Inertia of a rigid body in 3D: the shape table about G, rotated into the scene's axes.

Body axes: for a disk, cylinder, cone, ring or rod, z is the axis of symmetry (a rod
lies along z); for a plate ``a by b``, side a lies along x and side b along y (z normal).
The scene's inertia tensor about G is I_G = R J Rᵀ, R's columns the body axes written in
scene axes and J the tensor in body axes: diag(I_x, I_y, I_z) for principal axes, or
with products of inertia I_xy = ∫ x y dm, … off the diagonal with a minus sign
(Hibbeler 21.1, Eq. 21-6).

>>> import sympy
>>> m, r = sympy.symbols("m r", positive=True)
>>> principal("disk", m, (r,))
(m*r**2/4, m*r**2/4, m*r**2/2)
>>> tensor((m, m, 2 * m), ((0, 0, 1), (0, 1, 0), (-1, 0, 0)))
Matrix([
[2*m, 0, 0],
[  0, m, 0],
[  0, 0, m]])
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy

from dynsolve.numbers import surely_nonzero, tidy, tidying_lightly
from dynsolve.trig import pythagoras, shortest

Vec3 = tuple[sympy.Expr, sympy.Expr, sympy.Expr]
SHAPES_3D = ("disk", "cylinder", "cone", "ring", "rod", "plate", "sphere", "shell", "particle")


def principal(
    shape: str, m: sympy.Expr, sizes: Sequence[sympy.Expr]
) -> tuple[sympy.Expr, sympy.Expr, sympy.Expr]:
    """(I_x, I_y, I_z) about G in body axes for a shape of the table; ValueError with
    the reason for a shape it does not hold."""
    half = sympy.Rational(1, 2)
    if shape == "particle":
        return (sympy.Integer(0),) * 3  # type: ignore[return-value]
    if not sizes:
        raise ValueError(f"a {shape} needs its size (e.g. '{shape} r')")
    first = sizes[0]
    if shape == "disk":
        return (m * first**2 / 4, m * first**2 / 4, half * m * first**2)
    if shape == "cylinder":
        if len(sizes) < 2:
            raise ValueError("a 3D cylinder needs its length: 'cylinder r by h'")
        side = m * (3 * first**2 + sizes[1] ** 2) / 12
        return (side, side, half * m * first**2)
    if shape == "cone":
        # solid right circular cone, radius r at the base, height h; G on the axis h/4
        # above the base. About the apex I = (3/5) m (r²/4 + h²); parallel axis to G
        # (3h/4 away): (3/20) m r² + (3/5 − 9/16) m h² = (3/80) m (4 r² + h²).
        if len(sizes) < 2:
            raise ValueError("a cone needs its height: 'cone r by h' (r the base radius)")
        side = sympy.Rational(3, 80) * m * (4 * first**2 + sizes[1] ** 2)
        return (side, side, sympy.Rational(3, 10) * m * first**2)
    if shape == "ring":
        return (half * m * first**2, half * m * first**2, m * first**2)
    if shape == "rod":
        return (m * first**2 / 12, m * first**2 / 12, sympy.Integer(0))
    if shape == "plate":
        if len(sizes) < 2:
            raise ValueError("a plate needs both sides: 'plate a by b'")
        a, b = first, sizes[1]
        return (m * b**2 / 12, m * a**2 / 12, m * (a**2 + b**2) / 12)
    if shape == "sphere":
        return (sympy.Rational(2, 5) * m * first**2,) * 3  # type: ignore[return-value]
    if shape == "shell":
        return (sympy.Rational(2, 3) * m * first**2,) * 3  # type: ignore[return-value]
    raise ValueError(f"the 3D shape table has no '{shape}' (it has {', '.join(SHAPES_3D)})")


def tensor(
    moments: Sequence[sympy.Expr],
    axes: tuple[Vec3, Vec3, Vec3],
    products: Sequence[sympy.Expr] | None = None,
) -> sympy.Matrix:
    """I_G in scene axes: R J Rᵀ, with R's columns the body's x, y, z axes and J the tensor
    in body axes: diag(moments), less the products of inertia (I_xy, I_yz, I_zx) off the
    diagonal (J_xy = −I_xy, …: Hibbeler Eq. 21-6, I_xy = ∫ x y dm).

    >>> a, b, c = sympy.symbols("a b c")
    >>> tensor((1, 2, 3), ((1, 0, 0), (0, 1, 0), (0, 0, 1)), (a, b, c))
    Matrix([
    [ 1, -a, -c],
    [-a,  2, -b],
    [-c, -b,  3]])
    """
    R = sympy.Matrix([[axes[j][i] for j in range(3)] for i in range(3)])
    I_G = R * in_body_axes(moments, products) * R.T
    # sin² + cos² = 1 where the axes are turned by an angle, where that is shorter; in
    # numeric mode an entry surely not 0 is kept as the product wrote it (the equations
    # written with it are reduced to one form either way: trig.tidied)
    light = tidying_lightly()
    return I_G.applyfunc(lambda e: e if light and surely_nonzero(e) else shortest(e))


def in_body_axes(
    moments: Sequence[sympy.Expr], products: Sequence[sympy.Expr] | None = None
) -> sympy.Matrix:
    """J, the inertia tensor in body axes: diag(moments), less the products of inertia
    (I_xy, I_yz, I_zx) off the diagonal."""
    J = sympy.diag(*moments)
    if products is not None:
        xy, yz, zx = products
        J[0, 1] = J[1, 0] = -xy
        J[1, 2] = J[2, 1] = -yz
        J[0, 2] = J[2, 0] = -zx
    return J


def unit(vector: Sequence[sympy.Expr]) -> Vec3:
    """``vector`` divided by its length (ValueError for a zero vector); a vector already
    of unit length (cos² + sin² = 1, tested at sample values) is kept as written."""
    x, y, z = (sympy.Integer(0) + c for c in vector)  # model expressions, never text
    length_sq = x**2 + y**2 + z**2
    if length_sq == 0:
        raise ValueError("a direction cannot be (0, 0, 0)")
    if _is_one(length_sq):
        return (x, y, z)
    length = sympy.sqrt(length_sq)
    return (x / length, y / length, z / length)


def _is_one(expr: sympy.Expr) -> bool:
    """Whether ``expr`` is 1 for every value of its symbols (checked at sample points)."""
    symbols = sorted(expr.free_symbols, key=str)
    if not symbols:
        return bool(abs(sympy.N(expr - 1, 30)) < 1e-25)
    samples = ((0.3, 1.7, 2.9), (0.71, 0.12, 1.3), (2.2, 0.45, 0.8))
    for sample in samples:
        point = {s: sample[i % 3] + 0.1 * i for i, s in enumerate(symbols)}
        if abs(complex(sympy.N(expr.xreplace(point), 20)) - 1) > 1e-15:
            return False
    return True


def body_axes(z_axis: Vec3, x_axis: Vec3 | None) -> tuple[Vec3, Vec3, Vec3]:
    """Orthonormal body axes from z (and x, when the body is not symmetric about z: made
    perpendicular to z); for an axisymmetric body x is taken ⊥ z in the scene's x–y
    plane (any x ⊥ z will do)."""
    z = _plain(unit(z_axis))
    if x_axis is None:
        if z[0] == 0 and z[1] == 0:  # z along the scene's z
            x = (sympy.Integer(1), sympy.Integer(0), sympy.Integer(0))
        else:
            x = unit((-z[1], z[0], sympy.Integer(0)))
    else:
        dot = sum(a * b for a, b in zip(x_axis, z, strict=True))
        x = _plain(unit(tuple(a - dot * b for a, b in zip(x_axis, z, strict=True))))
    return (x, _plain(cross(z, x)), z)


def _plain(vector: Sequence[sympy.Expr]) -> Vec3:
    """An axis tidied in every mode, as the scene's geometry is: z × x = (0, 0, sin² + cos²)
    is (0, 0, 1), and a plate's (0, 0, a²/(a² + b²) + b²/(a² + b²)) is (0, 0, 1)."""
    return tuple(tidy(pythagoras(c), light=False) for c in vector)  # type: ignore[return-value]


def cross(a: Sequence[sympy.Expr], b: Sequence[sympy.Expr]) -> Vec3:
    """a × b."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def physical_problem(J: sympy.Matrix) -> str | None:
    """Why the inertia tensor ``J`` (numbers) cannot be a rigid body's, or None: its
    principal moments (eigenvalues) must not be negative and each must be at most the sum
    of the other two (I_x + I_y = ∫ (x² + y² + 2 z²) dm ≥ I_z, Hibbeler 21.1)."""
    import mpmath

    with mpmath.workdps(30):
        A = mpmath.matrix(
            [[mpmath.mpf(str(sympy.N(J[i, j], 30))) for j in range(3)] for i in range(3)]
        )
        values = sorted(mpmath.eigsy(A, eigvals_only=True))
    scale = max(abs(v) for v in values) or 1
    tol = 1e-12 * scale
    names = ", ".join(f"{float(v):.6g}" for v in values)
    if values[0] < -tol:
        return f"its principal moments ({names}) include a negative one"
    if values[2] > values[0] + values[1] + tol:
        return (
            f"its largest principal moment is more than the sum of the other two "
            f"(principal moments {names})"
        )
    return None
