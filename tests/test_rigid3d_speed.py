"""3D scenes without sympy's slow paths (issue 14): each change against a hand derivation.

- A top held at one fixed point with its precession unknown has its moments written about
  that point (Hibbeler 12e eq. 21-30, ΣM_O = Ḣ_O): the precession comes from one equation.
- sin² u + cos² u = 1 is applied as a remainder of polynomials in sin u and cos u
  (:mod:`dynsolve.rigid3d.trig`), not by ``simplify``.
- ω, α and a_G by differentiating the rotations use each rotation's second-order Taylor
  terms (R = E + q K + q²/2 K², Rodrigues expanded), multiplied with numbers.
- Symmetry about the spin axis (the Ω-frame check) is tested in body axes.
- In numeric mode the onset of a steady angle is the slope's root in numbers.
"""

import math
from pathlib import Path

import pytest
import sympy

from dynsolve.pipeline import solve_file, solve_text
from dynsolve.rigid3d.composition import by_rotations, compose, frame_form
from dynsolve.rigid3d.inertia import body_axes, tensor
from dynsolve.rigid3d.model import read_scene3d
from dynsolve.rigid3d.problem import build_3d_problem
from dynsolve.spec.parser import parse_file, parse_spec
from dynsolve.system import SolveOptions
from dynsolve.trig import pythagoras, tidied, vanishes

PROBLEMS = Path(__file__).parent.parent / "problems"
TOP = PROBLEMS / "rigid3d" / "top_steady_precession.dyn"
u, a, b = sympy.symbols("u a b", real=True)
s, c = sympy.sin(u), sympy.cos(u)


def test_pythagoras_reduces_powers_of_the_sine_and_cosine():
    # a s³ + a s c² = a s (s² + c²) = a s; sin 2u/2 = s c; a c² − a = −a s²
    assert pythagoras(a * s**3 + a * s * c**2) == a * s
    assert pythagoras(sympy.sin(2 * u) / 2 - s * c) == 0
    assert pythagoras(a * c**2 - a) == -a * s**2
    # a s² c + a c³ + b sin 2u = a c + 2 b s c, shown with 2 s c as sin 2u (shorter)
    assert tidied(a * s**2 * c + a * c**3 + b * sympy.sin(2 * u)) == a * c + b * sympy.sin(2 * u)


def test_vanishes_answers_identities_and_non_identities():
    assert vanishes(s**4 - c**4 - s**2 + c**2)  # (s² − c²)(s² + c²) − (s² − c²) = 0
    assert vanishes(sympy.cos(2 * u) - c**2 + s**2)
    assert not vanishes(s**4 - c**4)  # = s² − c², not 0 at u = 1
    assert not vanishes(a * s**2 + a * c**2 - b)  # = a − b


def test_the_body_axes_of_a_tilted_axis_are_plain():
    # z = (sin θ, cos θ, 0), x = (−cos θ, sin θ, 0): y = z × x = (0, 0, sin² θ + cos² θ) = (0, 0, 1)
    x_axis, y_axis, _ = body_axes((s, c, sympy.Integer(0)), None)
    assert x_axis == (-c, s, 0) and y_axis == (0, 0, 1)


def test_a_tilted_rod_has_the_hand_inertia_tensor():
    # a rod along z = (sin θ, −cos θ, 0): I_G = (m L²/12)(E − z zᵀ), so I_xx = (m L²/12) cos² θ,
    # I_xy = (m L²/12) sin θ cos θ, I_yy = (m L²/12) sin² θ, I_zz = m L²/12
    m, L = sympy.symbols("m L", positive=True)
    I_t = m * L**2 / 12
    axes = body_axes((s, -c, sympy.Integer(0)), None)
    I_G = tensor((I_t, I_t, sympy.Integer(0)), axes)
    expected = I_t * sympy.Matrix([[c**2, s * c, 0], [s * c, s**2, 0], [0, 0, 1]])
    assert all(vanishes(e) for e in I_G - expected)


def test_the_top_writes_its_moments_about_the_fixed_point():
    """Hibbeler eq. 21-30 about O: m g r_G sin θ = −I ω_p² sin θ cos θ
    + I_z ω_p sin θ (ω_p cos θ + ω_s), I = m k_t² and I_z = m k_z² about O; the scene's
    ΣM_O,z differs from it by its sign only (z out of the page, the top leaning to +x)."""
    problem = build_3d_problem(parse_file(TOP))
    about_O = [e for e in problem.system.equations if e.note.startswith("ΣM_O,z")]
    assert len(about_O) == 1 and problem.moment_point == "O"
    sym = problem.symbols
    m, g, r_G, k_t, k_z = (sym[n] for n in ("m", "g", "r_G", "k_t", "k_z"))
    W, w_s, theta = sym["W_p"], sym["w_s"], sym["theta"]
    st, ct = sympy.sin(theta), sympy.cos(theta)
    hibbeler = m * g * r_G * st - (
        -m * k_t**2 * W**2 * st * ct + m * k_z**2 * W * st * (W * ct + w_s)
    )
    assert about_O[0].residual.free_symbols & {sym["O_x"], sym["O_y"], sym["O_z"]} == set()
    assert vanishes(about_O[0].residual + hibbeler)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_the_top_solves_its_precession_from_one_equation(mode):
    """The file's hand derivation: W_p = 2.445479 rad/s (slow root of
    −0.00039375 ω_p² + 0.10125 ω_p − 0.24525 = 0), O_x = −m ω_p² r_G sin θ = −0.129479 N,
    O_y = m g = 4.905 N; W_p from the moment equation alone, with its formula in exact mode
    (the symbolic solve no longer runs out of its time budget)."""
    solution = solve_file(TOP, SolveOptions(mode=mode))
    assert solution.passed
    found = {answer.name: answer.value for answer in solution.answers}
    slow = (0.10125 - math.sqrt(0.10125**2 - 4 * 0.00039375 * 0.24525)) / (2 * 0.00039375)
    assert found["W_p"] == pytest.approx(slow, rel=1e-12)
    assert found["O_x"] == pytest.approx(0.129479, rel=1e-5)  # the key's word: left
    assert found["O_y"] == pytest.approx(0.5 * 9.81, rel=1e-12)
    step = next(step for step in solution.steps if step.unknowns == ("W_p",))
    assert "budget" not in step.note
    if mode == "exact":
        assert "sqrt" in step.results[0].formula


def test_the_rotations_give_the_hand_acceleration_of_g():
    """A frame turning about y at Ω = 3 rad/s, speeding up at α = 2 rad/s², G at d = 0.5 m
    on x: ω = (0, 3, 0), α = (0, 2, 0), a_G = α × r + Ω × (Ω × r) = (−Ω² d, 0, −α d)
    = (−4.5, 0, −1)."""
    spec = parse_spec(
        "given:\n  m = 1 kg\n  r = 0.1 m\n  d = 0.5 m\n  W = 3 rad/s\n  A = 2 rad/s^2\n"
        "scene:\n  body rotor: mass m, disk r, at (d, 0, 0)\n"
        "  rotates rotor: about (0, 1, 0), through (0, 0, 0), omega W, alpha A\n"
        "find: w = omega_y(rotor)\n",
        "frame.dyn",
    )
    scene = read_scene3d(spec)
    omega, alpha, a_G = by_rotations(scene, scene.values)
    for found, hand in ((omega, (0, 3, 0)), (alpha, (0, 2, 0)), (a_G, (-4.5, 0, -1))):
        assert [float(v) for v in found] == pytest.approx(hand, rel=1e-15, abs=1e-25)


def test_the_rotations_give_the_gyrotops_textbook_alpha():
    """Hibbeler 12e Example 20.2: α = {−41.3 i + 5.20 j + 33.0 k} rad/s² (the scene's z, x, y),
    by hand 2 − 50 sin 60°, 6 sin 60° − 30 cos 60° + 15, 6 cos 60° + 30 sin 60° + 4."""
    scene = read_scene3d(parse_file(PROBLEMS / "rigid3d" / "gyrotop_nutation.dyn"))
    _, alpha, _ = by_rotations(scene, scene.values)
    s60, c60 = math.sin(math.pi / 3), math.cos(math.pi / 3)
    hand = (6 * s60 - 30 * c60 + 15, 6 * c60 + 30 * s60 + 4, 2 - 50 * s60)  # x, y, z
    assert [float(v) for v in alpha] == pytest.approx(hand, rel=1e-14)


PLATE = """\
given:
  m = 2 kg
  a = 0.3 m
  W = 4 rad/s
  w_s = 50 rad/s
scene:
  body plate: mass m, plate a by {b}, at (0, 0, 0)
  axes plate: (1, 0, 0), (0, 1, 0)
  rotates plate: about (0, 1, 0), through (0, 0, 0), omega W
  spins plate: about (0, 0, 1), omega w_s
find: w = omega_z(plate)
"""


@pytest.mark.parametrize(("b", "symmetric"), [("a", True), ("a/2", False)])
def test_the_omega_frame_form_needs_symmetry_about_the_spin_axis(b, symmetric):
    """A plate a by b spinning about its normal z: I_x = m b²/12, I_y = m a²/12, so I_G is
    constant in the turning frame only when b = a (a square); Hibbeler 21.4."""
    scene = read_scene3d(parse_spec(PLATE.format(b=b), "plate.dyn"))
    assert (frame_form(scene, compose(scene)) is not None) is symmetric


@pytest.mark.parametrize("name", ["bar_on_shaft_steady.dyn", "bar_on_shaft_seed.dyn"])
def test_the_onset_in_numbers_is_the_formulas_value(name):
    """Ω_min = √(3 g/(2 L)) (the files' hand derivation: ∂F/∂θ(0, Ω) = −m g L/2 + m L² Ω²/3),
    L = 0.8 m: 4.288794 rad/s, in both modes."""
    path = PROBLEMS / "rigid3d" / name
    exact, numeric = (solve_file(path, SolveOptions(mode=m)) for m in ("exact", "numeric"))
    onsets = [
        next(a.value for a in solution.answers if a.name == "Omega_min")
        for solution in (exact, numeric)
    ]
    assert onsets[0] == pytest.approx(math.sqrt(3 * 9.81 / (2 * 0.8)), rel=1e-12)
    assert onsets[1] == pytest.approx(onsets[0], rel=1e-12)
    assert numeric.passed and exact.passed


def test_a_symbolic_onset_is_still_a_formula_in_numeric_mode():
    # the seed's Ω_min = sqrt(3 g/(2 L)) with L and g letters
    path = PROBLEMS / "rigid3d" / "bar_on_shaft_seed-symbolic.dyn"
    solution = solve_text(path.read_text(), "seed.dyn", SolveOptions(mode="numeric"))
    onset = next(a for a in solution.answers if a.name == "Omega_min")
    assert onset.value is None and "sqrt" in onset.formula and solution.passed
