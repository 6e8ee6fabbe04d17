"""dynsolve simulate: motion in time against closed forms, energy conservation, the CLI."""

import csv
import json
import math
from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.special import ellipk
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.simulate.integrator import integrate
from dynsolve.simulate.run import simulate_spec
from dynsolve.spec.parser import parse_spec

G = 9.81

BAR = """\
problem: Bar pendulum
units: SI
given:
  m = 2 kg
  L = 1 m
  theta_0 = {theta_0}
scene:
  point O: (0, 0)
  body bar: mass m, rod L, at (L/2*sin(theta_0), -L/2*cos(theta_0))
  pin bar at O
  gravity
"""

BOB = """\
given:
  m = 1 kg
  L = 2 m
  theta_0 = {theta_0}
scene:
  point O: (0, 0)
  body bob: particle, mass m, at (-L*sin(theta_0), -L*cos(theta_0))
  link cord: bob at G to O
  gravity
"""

BLOCK = """\
given:
  m = 3 kg
  v_0 = 4 m/s
  mu_k = 0.25
  phi = {phi}
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(phi), cos(phi)), mu_k mu_k
  velocity block: v_0, (cos(phi), sin(phi))
  gravity
"""


def simulate(text: str, **options) -> object:
    return simulate_spec(parse_spec(text, "sim.dyn"), **options)


def test_bar_pendulum_small_oscillations_have_the_textbook_period():
    # Hibbeler 22.1 (compound pendulum): tau = 2 pi sqrt(I_O/(m g d)), I_O = m L^2/3,
    # d = L/2: tau = 2 pi sqrt(2 L/(3 g)) = 1.637946586 s for L = 1 m. At an amplitude of
    # 1 deg the period is longer by the factor 1 + theta_0^2/16 = 1 + 1.9e-5.
    history = simulate(BAR.format(theta_0="1 deg"), t_end=4.0)
    tau = 2 * math.pi * math.sqrt(2 * 1.0 / (3 * G))
    assert history.small_period == pytest.approx(tau, rel=1e-9)
    assert history.period == pytest.approx(tau * (1 + math.radians(1) ** 2 / 16), rel=1e-6)


def test_simple_pendulum_period_at_large_amplitude_is_the_elliptic_integral():
    # exact period of a simple pendulum: T = 4 sqrt(L/g) K(k), k = sin(theta_0/2)
    # (scipy's ellipk takes the parameter m = k^2); theta_0 = 60 deg, L = 2 m:
    # T = 4 sqrt(2/9.81) K(0.25) = 3.059... s
    history = simulate(BOB.format(theta_0="60 deg"), t_end=7.0)
    exact = 4 * math.sqrt(2.0 / G) * ellipk(math.sin(math.radians(30)) ** 2)
    assert history.period == pytest.approx(exact, rel=1e-8)
    assert history.small_period == pytest.approx(2 * math.pi * math.sqrt(2.0 / G), rel=1e-9)


def test_swing_to_the_bottom_reaches_the_energy_speed():
    # released from 60 deg, at the bottom (x = 0) v = sqrt(2 g L (1 - cos 60)) = sqrt(g L)
    history = simulate(BOB.format(theta_0="60 deg"), until="x(bob) = 0 m")
    assert history.stopped_by == "x(bob) = 0 m"
    speed = math.hypot(*history.rows()[-1][6:8])
    assert speed == pytest.approx(math.sqrt(G * 2.0), rel=1e-8)


@pytest.mark.parametrize("phi", ["0 deg", "20 deg"])
def test_sliding_block_stops_at_the_hand_derived_distance(phi):
    # a block sliding up a rough incline of angle phi at v_0 decelerates at
    # a = g (sin phi + mu_k cos phi), so it stops after d = v_0^2 / (2 g (sin phi + mu_k cos phi));
    # on the level (phi = 0): d = 16/(2 (9.81)(0.25)) = 3.261977574 m
    history = simulate(BLOCK.format(phi=phi), until="max")
    p = math.radians(float(phi.split()[0]))
    distance = 4.0**2 / (2 * G * (math.sin(p) + 0.25 * math.cos(p)))
    assert history.stopped_by == "max"
    assert history.events[-1][2] == pytest.approx(distance, rel=1e-8)
    # the work of friction is the energy lost: mu_k m g cos(phi) d
    lost = -history.rows()[-1][-1]
    assert lost == pytest.approx(0.25 * 3 * G * math.cos(p) * distance, rel=1e-8)


_PENDULUM = simulate(BAR.format(theta_0="0 deg"), t_end=0.1).motion


@settings(max_examples=8)
@given(
    q0=st.floats(min_value=-3.0, max_value=3.0),
    qd0=st.floats(min_value=-8.0, max_value=8.0),
)
def test_energy_is_conserved_from_any_start(q0, qd0):
    # no friction: T + V is an invariant, whatever the initial state (a swing large enough
    # for the relative tolerance, not the absolute one, to govern: |q0| + |q'0| > 0.1)
    assume(abs(q0) + abs(qd0) > 0.1)
    run = integrate(_PENDULUM, q0, qd0, 3.0)
    assert run.drift <= 1e-8


def test_events_and_tolerances_are_checked():
    with pytest.raises(SpecError, match="not a quantity"):
        simulate(BAR.format(theta_0="10 deg"), until="height(bar) = 0 m")
    with pytest.raises(SpecError, match="not a unit of length"):
        simulate(BAR.format(theta_0="10 deg"), until="x(bar) = 2 kg")
    with pytest.raises(SpecError, match="no moving body"):
        simulate(BAR.format(theta_0="10 deg"), until="x(wheel) = 0 m")


def test_a_scene_with_two_degrees_of_freedom_is_refused():
    text = "given:\n  m = 1 kg\nscene:\n  body a: mass m, rod 1 m\n  gravity\n"
    with pytest.raises(SpecError, match="one coordinate"):
        simulate(text.replace("1 m", "L").replace("m = 1 kg", "m = 1 kg\n  L = 1 m"))


def run_cli(*args: object):
    return CliRunner().invoke(app, ["simulate", *(str(a) for a in args)])


def test_cli_writes_the_history_and_the_plot(tmp_path: Path):
    spec = tmp_path / "bar.dyn"
    spec.write_text(BAR.format(theta_0="30 deg"))
    history, plot = tmp_path / "h.csv", tmp_path / "p.png"
    result = run_cli(spec, "--t-end", "2 s", "--until", "max", "-o", history, "--plot", plot)
    assert result.exit_code == 0, result.output
    assert "period" in result.output and "energy drift" in result.output
    rows = list(csv.reader(history.open()))
    assert rows[0][:3] == ["t [s]", "q [rad]", "q_dot [rad/s]"]
    assert float(rows[-1][0]) < 2.0  # stopped at the first return to the top of the swing
    assert plot.read_bytes()[:4] == b"\x89PNG"


def test_cli_json_and_methods(tmp_path: Path):
    spec = tmp_path / "bar.dyn"
    spec.write_text(BAR.format(theta_0="30 deg"))
    out = tmp_path / "h.json"
    result = run_cli(spec, "--method", "Radau", "--rtol", "1e-8", "--t-end", "1 s", "-o", out)
    assert result.exit_code == 0, result.output
    data = json.loads(out.read_text())
    assert data["method"] == "Radau" and data["rtol"] == 1e-8
    assert len(data["rows"]) == 501


def test_cli_bad_input_exits_2(tmp_path: Path):
    spec = tmp_path / "bar.dyn"
    spec.write_text(BAR.format(theta_0="30 deg"))
    assert run_cli(spec, "--until", "when it stops").exit_code == 2
    assert run_cli(spec, "--t-end", "3 m").exit_code == 2
    assert run_cli(spec, "-o", tmp_path / "h.txt").exit_code == 2
    result = run_cli(spec, "--until", "x(bar) = 1 kg")
    assert result.exit_code == 2 and "not a unit of length" in result.output


SMOOTH_SLOPE = """\
given:
  m = 3 kg
  v_0 = 4 m/s
  phi = {phi}
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(phi), cos(phi))
  velocity block: v_0, (cos(phi), sin(phi))
  gravity
"""


@pytest.mark.parametrize("phi", ["30 deg", "12.5 deg"])
def test_constant_acceleration_is_compared_with_its_closed_form(phi):
    # a block sent up a smooth slope: along it m s'' = −m g sin(phi) (Hibbeler 13.4), so
    # s = v_0 t − ½ g sin(phi) t², highest at t = v_0/(g sin phi), s = v_0²/(2 g sin phi)
    p = math.radians(float(phi.split()[0]))
    history = simulate(SMOOTH_SLOPE.format(phi=phi), t_end=3.0)  # the top before 3 s
    accel, difference = history.constant_acceleration
    assert accel == pytest.approx(-G * math.sin(p), rel=1e-12)
    assert difference < 1e-9
    top = next(e for e in history.events if e[0] == "max")
    assert top[1] == pytest.approx(4.0 / (G * math.sin(p)), rel=1e-9)


def test_a_pendulum_has_no_constant_acceleration():
    history = simulate(BAR.format(theta_0="30 deg"), t_end=0.5)
    assert history.constant_acceleration is None


def test_cli_shows_the_constant_acceleration_closed_form(tmp_path: Path):
    spec = tmp_path / "slope.dyn"
    spec.write_text(SMOOTH_SLOPE.format(phi="30 deg"))
    result = CliRunner().invoke(app, ["simulate", str(spec), "--t-end", "1 s"])
    assert result.exit_code == 0, result.output
    assert "constant q'' = -4.905" in result.output and "closed form" in result.output
    out = tmp_path / "h.json"
    CliRunner().invoke(app, ["simulate", str(spec), "--t-end", "1 s", "-o", str(out)])
    data = json.loads(out.read_text())
    assert data["constant_acceleration"]["q_ddot"] == pytest.approx(-G / 2)


def test_a_cord_goes_slack_in_time_where_the_hand_formula_says(tmp_path: Path) -> None:
    # issue 11 part 3 (events: cord slack). Hand: a bob at the bottom of a 1-m cord at
    # 6 m/s goes slack where cos θ = (2gL − v²)/(3gL): θ = 123.8193°, v = √(−gL cos θ)
    spec = tmp_path / "slack.dyn"
    spec.write_text(
        "given:\n  m = 2 kg\n  L = 1 m\n  v_1 = 6 m/s\nscene:\n  point O: (0, 0)\n"
        "  body bob: particle, mass m, at (0, -L)\n  link cord: bob at G to O\n"
        "  velocity bob: v_1, right\n  gravity\nfind: v = speed(bob)\n"
    )
    from dynsolve.simulate.run import simulate_spec
    from dynsolve.spec.parser import parse_file

    history = simulate_spec(parse_file(str(spec)), "slack(cord)", 10.0)
    assert history.stopped_by == "slack(cord)"
    ((_, _, q, qd),) = [e for e in history.events if e[0] == "slack(cord)"]
    c = (2 * 9.81 - 36) / (3 * 9.81)
    assert q == pytest.approx(math.acos(c), rel=1e-8)
    assert abs(qd) == pytest.approx(math.sqrt(-9.81 * c), rel=1e-7)


def test_a_linkage_without_masses_is_refused_not_divided_by_zero():
    # fuzz seed 23 (input 806): the massless slider-crank of ic_slider_crank.dyn crashed the
    # integrator with a ZeroDivisionError (no inertia, no equation of motion)
    path = Path(__file__).parent.parent / "problems" / "linkages" / "ic_slider_crank.dyn"
    result = CliRunner().invoke(app, ["simulate", str(path)])
    assert result.exit_code == 2
    assert "no bar that moves has a mass" in result.stderr


def test_a_particle_on_a_curved_path_is_not_simulated_down_its_tangent():
    # regression: the dome's block (moves along a circular path) was integrated along the
    # straight tangent at its point (q'' = g sin 30° for ever), and the constant-speed car
    # over the hump as if coasting down its tangent (q'' = g sin β); both are refused now
    problems = Path(__file__).parent.parent / "problems" / "scenes"
    car = CliRunner().invoke(app, ["simulate", str(problems / "path_hump_nt.dyn")])
    assert car.exit_code == 2 and "at constant speed" in car.stderr
    block = CliRunner().invoke(app, ["simulate", str(problems / "path_dome_nt.dyn")])
    assert block.exit_code == 2 and "constant q''" not in block.stdout
