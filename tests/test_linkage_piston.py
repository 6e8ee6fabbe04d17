"""A slider's block with mass (a piston, a heavy block in a guide) in a linkage's kinetics.

Every expected number is a hand derivation written out below (the piston's exact
acceleration as ω² d²x/dθ², the light rod a two-force member; Newton–Euler on the rod and
the block by hand), independent of dynsolve.
"""

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.simulate.loop import loop_of
from dynsolve.spec.parser import parse_spec
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems" / "linkages"
NUMERIC = SolveOptions(mode="numeric")


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def engine_by_hand(r, rod, theta, omega, m, P):
    """Slider-crank, piston on the horizontal through the crank pin, constant ω, gas
    force P toward the crank, light crank and rod. x = r cos θ + s, s = √(rod² − r² sin²θ);
    a_C = ω² (−r cos θ − r² cos 2θ / s − r⁴ sin²θ cos²θ / s³). The rod, a two-force member
    at φ (sin φ = r sin θ / rod), in compression F: F cos φ − P = m a_C, N = F sin φ; the
    crank: M = F r sin(θ + φ) (cw). Returns (a_C, F, N, M)."""
    s = math.sqrt(rod * rod - (r * math.sin(theta)) ** 2)
    second = (
        -r * math.cos(theta)
        - r * r * math.cos(2 * theta) / s
        - r**4 * (math.sin(theta) * math.cos(theta)) ** 2 / s**3
    )
    a_C = omega**2 * second
    phi = math.asin(r * math.sin(theta) / rod)
    F = (P + m * a_C) / math.cos(phi)
    return a_C, F, F * math.sin(phi), F * r * math.sin(theta + phi)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_engine_piston_with_a_gas_force(mode):
    """problems/linkages/piston_gas_force.dyn: r = 0.1 m, l = 0.4 m, θ = 30°, 1500 rpm,
    m = 6 kg, P = 18 kN: a_C = −2455.10 m/s², F = 3295.26 N, N = 411.91 N, M = 199.14 N·m."""
    solution = solve_file(PROBLEMS / "piston_gas_force.dyn", SolveOptions(mode=mode))
    assert not any(c.failed for c in solution.checks)
    assert any(c.name == "power equation" for c in solution.checks)
    found = answers(solution)
    a_C, F, N, M = engine_by_hand(0.1, 0.4, math.radians(30), 50 * math.pi, 6.0, 18e3)
    assert a_C == pytest.approx(-2455.10, rel=1e-5)
    assert found["a_C"].value == pytest.approx(-a_C, rel=1e-9)
    assert found["a_C"].direction == "left"
    assert found["F_C"].value == pytest.approx(F, rel=1e-9)
    assert found["N_C"].value == pytest.approx(N, rel=1e-9)
    assert found["N_C"].direction == "up"
    assert found["M"].value == pytest.approx(M, rel=1e-9)


def test_heavy_block_in_a_vertical_guide():
    """problems/linkages/piston_vertical_guide.dyn, by hand in its header: B = (0.15, 0),
    C = (0, 0.2); ω_BC = 0, α_BC = −48 rad/s², a_C = 7.2 m/s² up; the block:
    C_y = 3 (9.81 + 7.2); the rod: B_y = 2 (3.6 + 9.81) + C_y, B_x − C_x = −9.6,
    0.075 (B_y + C_y) + 0.1 (B_x + C_x) = I_G α = −0.5; the crank: M = 0.15 B_y."""
    solution = solve_file(PROBLEMS / "piston_vertical_guide.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    C_y = 3 * (9.81 + 7.2)
    B_y = 2 * (3.6 + 9.81) + C_y
    total_x = (-0.5 - 0.075 * (B_y + C_y)) / 0.1  # B_x + C_x
    C_x = (total_x + 9.6) / 2
    assert found["M"].value == pytest.approx(0.15 * B_y, rel=1e-9)
    assert found["N_C"].value == pytest.approx(-C_x, rel=1e-9)
    assert found["N_C"].direction == "right"
    assert found["F_C"].value == pytest.approx(math.hypot(C_x, C_y), rel=1e-9)
    assert found["alpha_BC"].value == pytest.approx(48, rel=1e-12)
    assert found["alpha_BC"].direction == "cw"


FPS_ENGINE = """units: FPS
given:
  r = {r} in
  l = {l} in
  theta = {theta} deg
  n = {n} rpm
  W_P = {W} lb
  P = {P} lb
scene:
  point A: (0, 0)
  bar AB: A to B, length r, angle theta
  bar BC: B to C, length l
  slider C: along right, through A, mass W_P/g
  joint C: near (r + l, 0)
  omega AB: n ccw
  alpha AB: 0
  force P on C at C: left
  couple M on AB: cw
find: F_C = force(C), N_C, M
"""


def test_engine_in_us_units_weight_over_g():
    """The engine in FPS, the piston's mass its weight over g = 32.2 ft/s²: r = 4 in,
    l = 16 in, θ = 30°, 1500 rpm, W = 12 lb, P = 4000 lb (engine_by_hand in ft, slug, lb):
    F = 957.70 lb, N = 119.71 lb, M = 192.92 lb·ft."""
    text = FPS_ENGINE.format(r=4, l=16, theta=30, n=1500, W=12, P=4000)
    found = answers(solve_text(text, "engine_fps.dyn", NUMERIC))
    _, F, N, M = engine_by_hand(4 / 12, 16 / 12, math.radians(30), 50 * math.pi, 12 / 32.2, 4e3)
    assert found["F_C"].value == pytest.approx(F, rel=1e-9)
    assert found["N_C"].value == pytest.approx(N, rel=1e-9)
    assert found["M"].value == pytest.approx(M, rel=1e-9)


@settings(max_examples=6, deadline=None)
@given(
    r_in=st.integers(2, 6),
    ratio=st.integers(3, 5),
    theta=st.integers(5, 175),
    n=st.integers(300, 3000),
    W=st.integers(2, 20),
    P=st.integers(100, 5000),
)
def test_us_units_agree_with_the_hand_formula(r_in, ratio, theta, n, W, P):
    """Any engine in FPS: the answers equal engine_by_hand in ft, slug and lb (the same
    problem in SI is the first test's; the units only convert). The couple is signed (cw
    positive, as declared: ccw when the piston's inertia outweighs the gas force)."""
    text = FPS_ENGINE.format(r=r_in, l=ratio * r_in, theta=theta, n=n, W=W, P=P)
    found = answers(solve_text(text, "engine_fps.dyn", NUMERIC))
    omega = n * 2 * math.pi / 60
    _, F, N, M = engine_by_hand(
        r_in / 12, ratio * r_in / 12, math.radians(theta), omega, W / 32.2, float(P)
    )
    assert found["F_C"].value == pytest.approx(abs(F), rel=1e-8)
    up = 1 if found["N_C"].direction == "up" else -1
    assert up * found["N_C"].value == pytest.approx(N, rel=1e-8)
    assert found["M"].value == pytest.approx(M, rel=1e-8)  # signed: cw positive


def test_the_power_check_catches_a_block_without_its_inertia(monkeypatch):
    """Regression guard for the second method: with m a dropped from the block's
    equation along the guide (a wrong model), the power equation, which holds the block's
    ½ m v², fails."""
    from dynsolve.linkage import kinetics

    original = kinetics._block_equations

    def without_inertia(*args, **kwargs):
        along, across = original(*args, **kwargs)
        wrong = kinetics.Equation(along.lhs, kinetics.ZERO, along.label, along.line, along.note)
        return [wrong, across]

    monkeypatch.setattr(kinetics, "_block_equations", without_inertia)
    solution = solve_file(PROBLEMS / "piston_gas_force.dyn")
    power = next(c for c in solution.checks if c.name == "power equation")
    assert not power.passed


@pytest.mark.parametrize(
    ("line", "words"),
    [
        ("  force P on C at C: left\n", "needs the block's mass"),
        ("  force P on C at B: left\n", "needs the block's mass"),
    ],
)
def test_a_force_on_a_slider_needs_its_block(line, words):
    text = (PROBLEMS / "piston_gas_force.dyn").read_text()
    if "at B" in line:
        text = text.replace("  force P on C at C: left\n", line)
    else:
        text = text.replace(", mass m_P", "")
    with pytest.raises(SpecError) as error:
        solve_text(text, "bad.dyn")
    assert words in str(error.value)
    assert error.value.position.line > 0


RELEASED = """given:
  L_AB = 0.15 m
  L_BC = 0.25 m
  m_BC = 2 kg
  m_C = 3 kg
  th = 20 deg
  w = 3 rad/s
scene:
  point A: (0, 0)
  bar AB: A to B, length L_AB, angle th
  bar BC: B to C, length L_BC, mass m_BC
  slider C: along up, through A, mass m_C
  joint C: near (0, L_BC)
  omega AB: w cw
  gravity
find: alpha_AB = alpha(AB)
"""


def test_block_in_time_keeps_its_energy_and_matches_the_instant():
    """The heavy block in time (simulate's loop): T + V (the block's ½ m v² and m g y
    included) stays constant, and q'' at the start equals the α that Newton–Euler on the
    bars and the block gives the released crank at the same instant (two methods)."""
    loop = loop_of(parse_spec(RELEASED, "released.dyn"))
    run = solve_ivp(loop.rates, (0, 0.3), [0.0, *loop.qd0], rtol=1e-10, atol=1e-12)
    T, V = loop.energies(run.y)
    energy = T + V
    assert np.ptp(energy) < 1e-8 * abs(energy[0])
    solution = solve_text(RELEASED, "released.dyn", NUMERIC)
    alpha = answers(solution)["alpha_AB"]
    start = loop.rates(0.0, [0.0, *loop.qd0])[1]
    assert (alpha.value if alpha.direction == "ccw" else -alpha.value) == pytest.approx(
        start, rel=1e-8
    )


def test_a_loaded_slotted_link_solves_and_its_collar_can_have_mass():
    """The quick-return (problems/linkages/quick_return.dyn) with a heavy slotted bar and a
    couple on the crank: the slot's push on CD acts at the pin B, not one of CD's points
    (this raised a KeyError before). With a 2-kg collar at B its own free body adds B_x,
    B_y and two equations; both solve with the power equation (the collar's ½ m v² in T)
    holding."""
    text = (PROBLEMS / "quick_return.dyn").read_text().split("find:")[0]
    masses = "  m_CD = 4 kg\n  m_B = 2 kg\n"
    text = text.replace("  omega_0 = 3 rad/s\n", "  omega_0 = 3 rad/s\n" + masses)
    text = text.replace("length L_CD\n", "length L_CD, mass m_CD\n")
    text += "  couple M on AB: ccw\n  gravity\nfind: M, N_B\n"
    for spec in (text, text.replace("along bar CD\n", "along bar CD, mass m_B\n")):
        solution = solve_text(spec, "slotted.dyn", NUMERIC)
        power = next(c for c in solution.checks if c.name == "power equation")
        assert power.passed and not any(c.failed for c in solution.checks)
    light, heavy = (
        answers(solve_text(t, "s.dyn", NUMERIC))["M"].value
        for t in (text, text.replace("along bar CD\n", "along bar CD, mass m_B\n"))
    )
    assert light != pytest.approx(heavy, rel=1e-6)  # the collar's mass is not ignored


SI_ENGINE = FPS_ENGINE.replace("units: FPS", "units: SI").replace(" in\n", " m\n")
SI_ENGINE = SI_ENGINE.replace("W_P = {W} lb", "m_P = {W} kg").replace("W_P/g", "m_P")
SI_ENGINE = SI_ENGINE.replace("P = {P} lb", "P = {P} N")


@settings(max_examples=5, deadline=None)
@given(
    r=st.integers(50, 150),
    ratio=st.integers(3, 5),
    theta=st.integers(5, 175),
    n=st.integers(300, 3000),
    m=st.integers(1, 10),
    P=st.integers(1000, 30000),
)
def test_si_and_us_units_give_the_same_engine(r, ratio, theta, n, m, P):
    """The same engine written in SI (mm → m, kg, N) and in FPS (inches, a weight in lb
    over g = 32.2 ft/s² chosen to give the same mass, lb): the rod force and the couple
    agree after conversion (1 in = 0.0254 m, 1 lb = 4.4482216152605 N exactly)."""
    lb, inch = 4.4482216152605, 0.0254
    si = SI_ENGINE.format(r=r / 1000, l=ratio * r / 1000, theta=theta, n=n, W=m, P=P)
    slug = lb / (32.2 * 0.3048)  # kg per lb of weight over g = 32.2 ft/s²
    fps = FPS_ENGINE.format(
        r=r / 1000 / inch, l=ratio * r / 1000 / inch, theta=theta, n=n, W=m / slug, P=P / lb
    )
    a = answers(solve_text(si, "si.dyn", NUMERIC))
    b = answers(solve_text(fps, "fps.dyn", NUMERIC))
    assert b["F_C"].value * lb == pytest.approx(a["F_C"].value, rel=1e-8)
    assert b["M"].value * lb * 0.3048 == pytest.approx(a["M"].value, rel=1e-8)
