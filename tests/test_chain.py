"""Open chains of bars (issue 11, motion in time): a linkage released to its loads at an
instant (α from Newton–Euler, checked by Lagrange), and in time with ``dynsolve simulate``.

Expected values are hand derivations. For two identical uniform rods (m, L) pinned at O
and end to end at A, with θ_i from +x (ccw), Δ = θ_1 − θ_2 and T, V written out:

    (4/3) α_1 + (1/2) cos Δ α_2 + (1/2) sin Δ ω_2² = −(3/2) (g/L) cos θ_1 + Q_1/(m L²)
    (1/2) cos Δ α_1 + (1/3) α_2 − (1/2) sin Δ ω_1² = −(1/2) (g/L) cos θ_2 + Q_2/(m L²)
"""

import csv
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.simulate.run import simulate_spec
from dynsolve.spec.parser import parse_spec

G = 9.81
PROBLEMS = Path(__file__).resolve().parent.parent / "problems" / "linkages"

CHAIN = """\
problem: Double pendulum of two uniform rods
units: SI
given:
  m = 2 kg
  L = 1 m
  theta_1 = {theta_1}
  theta_2 = {theta_2}
  w_1 = {w_1}
  w_2 = {w_2}
scene:
  point O: (0, 0)
  bar OA: O to A, length L, angle theta_1, mass m
  bar AB: A to B, length L, angle theta_2, mass m
  omega OA: w_1 ccw
  omega AB: w_2 ccw
  gravity
find: a_1 = alpha(OA), a_2 = alpha(AB)
"""


def chain(theta_1="0 deg", theta_2="0 deg", w_1="0 rad/s", w_2="0 rad/s") -> str:
    return CHAIN.format(theta_1=theta_1, theta_2=theta_2, w_1=w_1, w_2=w_2)


def signed(answer) -> float:
    return answer.value if answer.direction == "ccw" else -answer.value


def test_released_horizontal_rods_have_the_hand_derived_alphas():
    # Δ = 0, cos θ = 1, at rest: [4/3 1/2; 1/2 1/3] α = −(g/L) [3/2; 1/2]
    # → α_1 = −9 g/(7 L), α_2 = 3 g/(7 L)
    solution = solve_file(PROBLEMS / "double_pendulum_released.dyn")
    a_1, a_2 = (signed(a) for a in solution.answers[:2])
    assert a_1 == pytest.approx(-9 * G / (7 * 0.5), rel=1e-12)
    assert a_2 == pytest.approx(3 * G / (7 * 0.5), rel=1e-12)
    check = next(c for c in solution.checks if c.name == "second method: Lagrange")
    assert check.passed
    assert float(check.detail.rsplit("difference ", 1)[1].rstrip(")")) < 1e-12
    power = next(c for c in solution.checks if c.name == "power equation")
    assert "checks nothing" in power.detail  # at rest the power equation is 0 = 0


def test_a_force_on_hanging_rods_gives_the_textbook_alphas():
    # hanging (θ = −90°): Q = P L [1, 1]; [4/3 1/2; 1/2 1/3] α = P/(m L) [1; 1]
    # → α_1 = −6 P/(7 m L), α_2 = 30 P/(7 m L) (P = 30 N, m = 4 kg, L = 1.2 m)
    solution = solve_file(PROBLEMS / "double_pendulum_pushed.dyn")
    a_1, a_2 = (signed(a) for a in solution.answers[:2])
    assert a_1 == pytest.approx(-6 * 30 / (7 * 4 * 1.2), rel=1e-12)
    assert a_2 == pytest.approx(30 * 30 / (7 * 4 * 1.2), rel=1e-12)


def test_a_turning_rod_drags_the_hanging_one_by_its_centripetal_term():
    # θ_1 = 0, θ_2 = −90°: Δ = 90°, cos Δ = 0, sin Δ = 1, ω_2 = 0:
    # (4/3) α_1 = −(3/2) g/L; (1/3) α_2 − (1/2) ω_1² = 0 → α_1 = −9 g/(8 L), α_2 = 1.5 ω_1²
    solution = solve_file(PROBLEMS / "double_pendulum_swinging.dyn")
    a_1, a_2 = (signed(a) for a in solution.answers[:2])
    assert a_1 == pytest.approx(-9 * G / (8 * 0.5), rel=1e-12)
    assert a_2 == pytest.approx(1.5 * 16, rel=1e-12)
    assert not any(c.failed for c in solution.checks)


@settings(max_examples=5, deadline=None)  # each an exact solve of 14 equations: ~2 s
@given(
    theta_1=st.integers(-180, 180),
    theta_2=st.integers(-180, 180),
    w_1=st.integers(-5, 5),
    w_2=st.integers(-5, 5),
)
def test_newton_euler_and_lagrange_agree_in_any_state(theta_1, theta_2, w_1, w_2):
    # two methods with nothing in common but the physics: Newton–Euler per bar (pin forces,
    # relative accelerations) and Lagrange's equations of the chain's T and V
    text = chain(f"{theta_1} deg", f"{theta_2} deg", f"{w_1} rad/s", f"{w_2} rad/s")
    solution = solve_text(text, "chain.dyn")
    lagrange = next(c for c in solution.checks if c.name == "second method: Lagrange")
    assert lagrange.passed, lagrange.detail
    d = math.radians(theta_1 - theta_2)
    t1, t2 = math.radians(theta_1), math.radians(theta_2)
    a_1, a_2 = (signed(a) for a in solution.answers)
    # the hand-written equations above, with the answers put in (L = 1 m)
    first = 4 / 3 * a_1 + math.cos(d) * a_2 / 2 + math.sin(d) * w_2**2 / 2 + 1.5 * G * math.cos(t1)
    second = math.cos(d) * a_1 / 2 + a_2 / 3 - math.sin(d) * w_1**2 / 2 + 0.5 * G * math.cos(t2)
    assert abs(first) < 1e-9 * (1 + abs(a_1)) and abs(second) < 1e-9 * (1 + abs(a_2))


def test_a_load_to_find_beside_a_released_bar_is_refused():
    text = chain().replace("  gravity", "  couple M on OA: ccw\n  gravity")
    with pytest.raises(SpecError, match="left to its loads") as caught:
        solve_text(text, "chain.dyn")
    assert "alpha" in caught.value.hint


def test_without_masses_a_missing_alpha_is_still_asked_for():
    text = chain().replace(", mass m", "").replace("  gravity\n", "")
    with pytest.raises(SpecError, match="gives only its omega"):
        solve_text(text, "chain.dyn")


def _mode() -> tuple[float, float]:
    # small oscillations about hanging: M0 = m L² [4/3 1/2; 1/2 1/3], K = m g L [3/2 0; 0 1/2]
    # det(K − ω² M0) = 0 with λ = ω² L/g: 7 λ² − 42 λ + 27 = 0 → λ = 3 ± √1008/14;
    # the slow mode's shape θ_2/θ_1 = (3/2 − 4λ/3)/(λ/2)
    slow = 3 - math.sqrt(1008) / 14
    return math.sqrt(slow * G), (1.5 - 4 * slow / 3) / (slow / 2)


def test_small_oscillations_in_the_slow_mode_have_the_normal_mode_frequency():
    omega, ratio = _mode()
    amplitude = 1e-4  # rad: the nonlinear error is of order amplitude² ≈ 1e-8
    text = chain(
        f"{-90 + math.degrees(amplitude)} deg", f"{-90 + math.degrees(amplitude * ratio)} deg"
    )
    history = simulate_spec(parse_spec(text, "mode.dyn"), t_end=3.0, samples=31)
    for t, q in zip(history.run.t, history.run.q, strict=True):
        expected = amplitude * (math.cos(omega * t) - 1)  # q: the turn from as drawn
        assert q[0] == pytest.approx(expected, abs=1e-6 * amplitude)
        assert q[1] == pytest.approx(ratio * expected, abs=1e-6 * amplitude * abs(ratio))


@settings(max_examples=6, deadline=None)
@given(
    theta_1=st.integers(-180, 180),
    theta_2=st.integers(-180, 180),
    w_1=st.integers(-3, 3),
)
def test_energy_is_conserved_over_ten_seconds_from_any_start(theta_1, theta_2, w_1):
    # the double pendulum is chaotic, but T + V is an invariant: its drift measures the
    # integration (issue 11's target: ≤ 1e-9 over 10 s). DOP853 at rtol 1e-11 keeps it
    # there (measured worst of 8 random starts: 3.9e-10; at the default 1e-10: 1.5e-9)
    text = chain(f"{theta_1} deg", f"{theta_2} deg", f"{w_1} rad/s")
    spec = parse_spec(text, "energy.dyn")
    history = simulate_spec(spec, t_end=10.0, samples=101, rtol=1e-11, atol=1e-13)
    assert history.run.drift <= 1e-9


def test_until_a_bar_angle_and_a_joint_height():
    # one rod released from level (AB massless and short is not a chain: use the first
    # rod's angle): the pair released level reaches θ_1 = −90° with T = −ΔV > 0
    history = simulate_spec(parse_spec(chain(), "c.dyn"), until="theta(OA) = -90 deg", t_end=5.0)
    assert history.stopped_by == "theta(OA) = -90 deg"
    assert history.run.q[-1][0] == pytest.approx(-math.pi / 2, abs=1e-9)
    low = simulate_spec(parse_spec(chain(), "c.dyn"), until="y(B) = -1.5 m", t_end=5.0)
    y_B = low.rows()[-1][low.columns().index("y_B [m]")]
    assert abs(y_B + 1.5) < 1e-9


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (("  gravity", "  bar AO2: A to O2\n  point O2: (L, 0)\n  gravity"), "rigid there"),
        (("  gravity", "  alpha OA: 0\n  gravity"), "a simulation finds the motion"),
    ],
)
def test_what_a_chain_cannot_simulate_says_why(change, message):
    text = chain().replace(*change)
    with pytest.raises(SpecError, match=message):
        simulate_spec(parse_spec(text, "c.dyn"), t_end=0.1)


def test_bad_until_for_a_chain(tmp_path: Path):
    with pytest.raises(SpecError, match="no moving bar"):
        simulate_spec(parse_spec(chain(), "c.dyn"), until="theta(XY) = 0 deg")
    with pytest.raises(SpecError, match="no moving joint"):
        simulate_spec(parse_spec(chain(), "c.dyn"), until="y(O) = 0 m")
    with pytest.raises(SpecError, match="cannot read"):
        simulate_spec(parse_spec(chain(), "c.dyn"), until="max")


def test_cli_simulates_a_chain_and_writes_every_bar(tmp_path: Path):
    spec = tmp_path / "chain.dyn"
    spec.write_text(chain())
    out, plot = tmp_path / "h.csv", tmp_path / "p.png"
    args = ["simulate", str(spec), "--t-end", "1 s", "-o", str(out), "--plot", str(plot)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "turn of OA, turn of AB" in result.output and "energy drift" in result.output
    rows = list(csv.reader(out.open()))
    assert rows[0][:5] == ["t [s]", "theta_OA [rad]", "theta_AB [rad]", "omega_OA [rad/s]",
                           "omega_AB [rad/s]"]  # fmt: skip
    assert len(rows) == 502 and plot.read_bytes()[:4] == b"\x89PNG"


# ---- closed loops: one degree of freedom in the input bar's turn

PARALLELOGRAM = """\
given:
  L = 1 m
  m = 2 kg
  tilt = {tilt} deg
  cx = {cx} m
  cy = {cy} m
scene:
  point A: (0, 0)
  point D: (L, 0)
  bar AB: A to B, length L, angle tilt, mass m
  bar BC: B to C, length L, mass m
  bar CD: C to D, length L, mass m
  joint C: near (cx, cy)
  gravity
"""


def test_a_hanging_parallelogram_swings_with_the_hand_derived_period():
    # the coupler translates on a circle of radius L: T = ½ (2 m L²/3 + m L²) θ'²,
    # V = −2 m g L cos θ, so ω² = 2 m g L / (5 m L²/3) = 6 g/(5 L) (hand derivation);
    # from a small tilt a: θ − θ_0 = a (cos ω t − 1)
    a = 0.01
    text = PARALLELOGRAM.format(tilt=-90 + math.degrees(a), cx=1 + math.sin(a), cy=-math.cos(a))
    history = simulate_spec(parse_spec(text, "p.dyn"), t_end=2.0, samples=21)
    omega = math.sqrt(6 * G / 5)
    for t, q in zip(history.run.t, history.run.q, strict=True):
        assert q[0] == pytest.approx(a * (math.cos(omega * t) - 1), abs=2e-3 * a)
    assert history.columns()[1:3] == ("theta_AB [rad]", "omega_AB [rad/s]")


SLIDER_CRANK = """\
given:
  r = 0.1 m
  l = 0.3 m
  m = 1 kg
  w_0 = 20 rad/s
  phi = 30 deg
scene:
  point A: (0, 0)
  bar AB: A to B, length r, angle phi, mass m
  bar BC: B to C, length l, mass m
  slider C: along right, through A
  joint C: near (l, 0)
  omega AB: w_0 ccw
"""


def test_a_coasting_slider_crank_keeps_its_energy_through_full_turns():
    # no load, no friction: T = ½ M(q) q'² is constant while M(q) varies along the turn,
    # so ω of the crank changes but the energy does not; it turns a full revolution
    history = simulate_spec(
        parse_spec(SLIDER_CRANK, "sc.dyn"), until="theta(AB) = 720 deg", t_end=5.0
    )
    assert history.stopped_by == "theta(AB) = 720 deg"
    assert history.run.drift < 1e-8
    speeds = history.run.qd[:, 0]
    assert speeds.min() < 0.9 * speeds.max()  # M(q) varies: the crank's speed does
    # at the same crank angle the speed repeats (one turn later)
    assert history.run.qd[-1][0] == pytest.approx(20.0, rel=1e-6)


def test_a_double_rocker_driven_past_its_limit_locks_and_says_so():
    # AB = 1.8, BC = 1, CD = 1.5, AD = 2: s + l = 3 < p + q = 3.3 with the coupler
    # shortest, a double rocker: AB cannot turn fully, and thrown hard it reaches a toggle
    text = """\
given:
  w_0 = 30 rad/s
  up = 60 deg
  AD = 2 m
  AB = 1.8 m
  BC = 1 m
  CD = 1.5 m
  m = 1 kg
  cx = 1.9 m
  cy = 1.6 m
scene:
  point A: (0, 0)
  point D: (AD, 0)
  bar AB: A to B, length AB, angle up, mass m
  bar BC: B to C, length BC, mass m
  bar CD: C to D, length CD, mass m
  joint C: near (cx, cy)
  omega AB: w_0 ccw
"""
    with pytest.raises(SpecError, match=r"locks|cannot close") as caught:
        simulate_spec(parse_spec(text, "rocker.dyn"), t_end=2.0)
    assert "until" in caught.value.hint


QUICK_RETURN = """\
given:
  L_AB = 200 mm
  h = 400 mm
  L_CD = 800 mm
  theta = 30 deg
  omega_0 = 3 rad/s
  m = 2 kg
scene:
  point A: (0, 0)
  point C: (0, -h)
  bar AB: A to B, length L_AB, angle theta, mass m
  bar CD: C to D, length L_CD, mass m
  slider B: along bar CD
  joint D: near (L_AB, L_CD - h)
  omega AB: omega_0 ccw
"""


def test_a_coasting_quick_return_comes_back_to_its_start_rate_after_a_turn():
    # the crank's pin B slides in CD's slot (the slot constraint); no loads, so T is
    # conserved and after one turn, in the same configuration, the crank turns at 3 rad/s
    history = simulate_spec(
        parse_spec(QUICK_RETURN, "qr.dyn"), until="theta(AB) = 360 deg", t_end=5.0
    )
    assert history.stopped_by == "theta(AB) = 360 deg"
    assert history.run.qd[-1][0] == pytest.approx(3.0, rel=1e-7)
    assert history.run.drift < 1e-8
