"""3D inertia given directly (issue 11, part 2): products of inertia on an ``inertia`` line
and the cone of the 3D shape table, each against a hand derivation.

Hand derivation shared by the tests (Hibbeler 21.4, Eq. 21-25 with Ω = ω, α = 0): a body
with G on a shaft along z turning at a constant ω, carried by bearings A at z = −a and B
at z = +a, no gravity. With I_G = [[I_xx, −I_xy, −I_xz], [−I_xy, I_yy, −I_yz],
[−I_xz, −I_yz, I_zz]] (scene axes) and ω = (0, 0, ω):
H_G = (−I_xz ω, −I_yz ω, I_zz ω), Ḣ_G = ω × H_G = (I_yz ω², −I_xz ω², 0).
ΣF = 0 (G on the axis): A = −B across the shaft. Moments about G:
r_A × A + r_B × B = (a A_y − a B_y, −a A_x + a B_x, 0) = (2 a A_y, 2 a B_x, 0), so
A_y = I_yz ω²/(2a) = −B_y and B_x = −I_xz ω²/(2a) = −A_x.
"""

import math

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text
from dynsolve.rigid3d.inertia import physical_problem, principal

ROTOR = """\
given:
  m = 5 kg
  I_x = 0.5 kg*m^2
  I_y = 0.5 kg*m^2
  I_z = 0.4 kg*m^2
  I_xy = {xy} kg*m^2
  I_yz = {yz} kg*m^2
  I_zx = {zx} kg*m^2
  w = 10 rad/s
  a = 0.1 m
scene:
  body rotor: mass m, at (0, 0, 0)
  inertia rotor: I_x, I_y, I_z, products I_xy, I_yz, I_zx
{axes}  rotates rotor: about (0, 0, 1), through (0, 0, 0), omega w
  bearing A: at (0, 0, -a), thrust
  bearing B: at (0, 0, a), journal
find: A_x, A_y, B_x, B_y
"""


def rotor(xy: float = 0, yz: float = 0.03, zx: float = 0.02, axes: str = "") -> str:
    return ROTOR.format(xy=xy, yz=yz, zx=zx, axes=axes)


def values(solution) -> dict[str, float]:
    return {a.name: a.value for a in solution.answers}


def test_products_of_inertia_in_scene_axes_load_the_bearings():
    """Body axes = scene axes (no axis lines): I_xz = 0.02, I_yz = 0.03 kg·m², ω = 10 rad/s,
    a = 0.1 m: A_y = 0.03·100/0.2 = 15 N = −B_y, B_x = −0.02·100/0.2 = −10 N = −A_x."""
    solution = solve_text(rotor(), "rotor.dyn")
    assert solution.passed
    found = values(solution)
    assert found["A_y"] == pytest.approx(15.0, rel=1e-12)
    assert found["B_y"] == pytest.approx(-15.0, rel=1e-12)
    assert found["B_x"] == pytest.approx(-10.0, rel=1e-12)
    assert found["A_x"] == pytest.approx(10.0, rel=1e-12)
    note = next(c for c in solution.checks if c.name == "inertia of rotor")
    assert "products" in note.detail and "R J Rᵀ" in note.detail


def test_products_are_turned_with_the_body_axes():
    """Body x along scene y, body y along −x: a body point (x_b, y_b, z_b) is at
    X = −y_b, Y = x_b, Z = z_b, so I_XZ = −I_yz(body) = −0.03 and I_YZ = I_zx(body) = 0.02
    (I_xy stays 0 as I_x = I_y). Then A_y = 0.02·100/0.2 = 10 N, B_x = 0.03·100/0.2 = 15 N."""
    axes = "  axes rotor: (0, 1, 0), (-1, 0, 0)\n"
    found = values(solve_text(rotor(axes=axes), "turned.dyn"))
    assert found["A_y"] == pytest.approx(10.0, rel=1e-12)
    assert found["B_y"] == pytest.approx(-10.0, rel=1e-12)
    assert found["B_x"] == pytest.approx(15.0, rel=1e-12)
    assert found["A_x"] == pytest.approx(-15.0, rel=1e-12)


def test_products_without_both_body_axes_are_refused():
    with pytest.raises(SpecError) as error:
        solve_text(rotor(axes="  axis rotor: (0, 0, 1)\n"), "axis.dyn")
    assert "only its z axis is given" in str(error.value)
    assert "axes rotor" in (error.value.hint or "")


@pytest.mark.parametrize(
    ("xy", "why"),
    [
        (0.6, "negative"),  # eigenvalues of [[0.5, -0.6], [-0.6, 0.5]]: 1.1 and -0.1
    ],
)
def test_an_inertia_no_body_has_is_refused(xy, why):
    with pytest.raises(SpecError) as error:
        solve_text(rotor(xy=xy, yz=0, zx=0), "bad.dyn")
    assert "not a rigid body's" in str(error.value) and why in str(error.value)


def test_the_triangle_inequality_of_principal_moments():
    """I_x + I_y = ∫(x² + y² + 2z²) dm ≥ I_z: (1, 1, 3) is no body; (1, 1, 2) is a thin
    plate (its limit)."""
    import sympy

    assert "more than the sum" in physical_problem(sympy.diag(1, 1, 3))
    assert physical_problem(sympy.diag(1, 1, 2)) is None


def test_cone_of_the_3d_table():
    """Solid cone, base radius r, height h, about G (h/4 above the base): about the apex
    I = (3/5) m (r²/4 + h²) across the axis; G is 3h/4 from the apex, so
    I_x = (3/20) m r² + (3/5 − 9/16) m h² = (3/80) m (4 r² + h²); I_z = (3/10) m r²."""
    import sympy

    m, r, h = sympy.symbols("m r h", positive=True)
    I_x, I_y, I_z = principal("cone", m, (r, h))
    assert sympy.simplify(I_x - sympy.Rational(3, 80) * m * (4 * r**2 + h**2)) == 0
    assert I_y == I_x
    assert sympy.simplify(I_z - sympy.Rational(3, 10) * m * r**2) == 0
    with pytest.raises(ValueError, match="cone r by h"):
        principal("cone", m, (r,))


CONE = """\
given:
  m = 3 kg
  r = 0.1 m
  h = 0.4 m
  phi = 30 deg
  w = 20 rad/s
  a = 0.15 m
scene:
  body cone: mass m, cone r by h, at (0, 0, 0)
  axis cone: (sin(phi), 0, cos(phi))
  rotates cone: about (0, 0, 1), through (0, 0, 0), omega w
  bearing A: at (0, 0, -a), thrust
  bearing B: at (0, 0, a), journal
find: A_x, B_x, A_y
"""


def test_an_askew_cone_on_a_shaft():
    """Axis s = (sin φ, 0, cos φ): I_G = I_t (E − s sᵀ) + I_a s sᵀ, so
    H_G = ω (I_t e_z + (I_a − I_t) cos φ s) and Ḣ_G = ω × H_G = ω² (I_a − I_t) sin φ cos φ e_y.
    ΣM_G,y = 2 a B_x (A_x = −B_x): B_x = ω² (I_a − I_t) sin φ cos φ / (2a), A_y = 0.
    I_a = (3/10)(3)(0.1²) = 0.009, I_t = (3/80)(3)(4·0.1² + 0.4²) = 0.0225 kg·m²:
    B_x = 400 (−0.0135)(√3/4)/0.3 = −7.794 N."""
    I_a = 0.3 * 3 * 0.1**2
    I_t = 3 / 80 * 3 * (4 * 0.1**2 + 0.4**2)
    phi = math.radians(30)
    B_x = 20**2 * (I_a - I_t) * math.sin(phi) * math.cos(phi) / (2 * 0.15)
    solution = solve_text(CONE, "cone.dyn")
    assert solution.passed
    found = values(solution)
    assert found["B_x"] == pytest.approx(B_x, rel=1e-12)
    assert found["A_x"] == pytest.approx(-B_x, rel=1e-12)
    assert found["A_y"] == pytest.approx(0.0, abs=1e-12)
