"""The simulation cross-check of travels: it passes on the bundled problems, fails on a
wrong principle answer, and says where a travel cannot be simulated."""

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import dynsolve.principles.work_energy as work_energy
from dynsolve.pipeline import solve_file

ROOT = Path(__file__).resolve().parents[1]
SIMULATED = [
    "problems/stages/bounce_ball.dyn",  # a fall, then a rebound that stops (h_2)
    "problems/stages/pendulum_block.dyn",  # a swing on a cord (a link)
    "problems/stages/pile_driver.dyn",  # a fall, then ram and pile stopping together
    "problems/seed/rwe_seed_disk40lb.dyn",  # rolling, wound spring, couple (FPS)
    "problems/seed/rwe_seed_platform.dyn",  # parallel links, couple on a link
    "problems/seed/rwe_seed_wheel10rev.dyn",  # rolling under a constant force
    "problems/seed/we_seed_collar.dyn",  # a collar on a smooth rod, spring
    "problems/seed/ci_seed_cube_lip.dyn",  # tipping about a lip, stops at the top
]


def simulation(solution):
    return [c for c in solution.checks if c.name.startswith("simulation")]


@pytest.mark.parametrize("name", SIMULATED)
def test_the_simulation_agrees_with_the_principle(name):
    solution = solve_file(ROOT / name)
    checks = simulation(solution)
    assert checks, "no simulation check"
    for check in checks:
        assert check.passed, check.detail
        assert "not simulated" not in check.detail
        assert "solve_ivp DOP853 (rtol 1e-10" in check.detail
    assert solution.passed


def test_a_wrong_kinetic_energy_fails_the_simulation(monkeypatch):
    # the principle's T = ½ m v² + ½ I ω² made 2 % too large: ω₂ comes out 1 % too small,
    # which the simulation (with its own M(q) = m |dr_G/dq|² + I (dθ/dq)²) must catch
    kinetic = work_energy._kinetic
    monkeypatch.setattr(work_energy, "_kinetic", lambda *a: kinetic(*a) * 1.02)
    solution = solve_file(ROOT / "problems/seed/rwe_seed_wheel10rev.dyn")
    (check,) = simulation(solution)
    assert not check.passed
    assert "> 1e-06" in check.detail
    assert not solution.passed


def test_a_wrong_work_of_the_weight_fails_a_stop(monkeypatch):
    # the weights' work made 1 % too large: the rebound height h_2 comes out wrong, and the
    # simulated rebound stops short of it (the work still needed is not 0)
    weights = work_energy._Work.weights

    def wrong(self):
        weights(self)
        self.terms = [t * 1.01 for t in self.terms]

    monkeypatch.setattr(work_energy._Work, "weights", wrong)
    solution = solve_file(ROOT / "problems/stages/bounce_ball.dyn")
    failed = [c for c in simulation(solution) if c.failed]
    assert failed, [c.detail for c in simulation(solution)]


def test_a_symbolic_travel_is_noted_not_simulated():
    solution = solve_file(ROOT / "problems/seed/we_seed_collar-symbolic.dyn")
    (check,) = simulation(solution)
    assert check.detail.startswith("not simulated: symbolic givens")
    assert check.status == "not_run" and not check.passed  # never shown as a pass


def test_an_interval_is_noted_not_simulated(tmp_path):
    # a block sliding to rest on a rough floor, by impulse and momentum: t = v_1/(mu_k g)
    spec = tmp_path / "interval.dyn"
    spec.write_text(
        "given:\n  m = 2 kg\n  b = 0.2 m\n  h = 0.1 m\n  mu_k = 0.2\n  v_1 = 3 m/s\n"
        "scene:\n  body block: mass m, block b by h, at (0, h/2)\n"
        "  base B on block: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right\n"
        "  velocity block: v_1, right\n  gravity\n  travel block: for t_s, stops\n"
        "find: t_s [s]\n"
    )
    solution = solve_file(spec)
    (check,) = simulation(solution)
    assert "not simulated" in check.detail and "interval" in check.detail
    assert check.status == "not_run"


def test_a_sliding_block_that_stops_is_checked(tmp_path):
    # a 3-kg block sliding at 4 m/s on a rough floor (mu_k = 0.25) stops after
    # d = v²/(2 mu_k g) = 16/(2 (0.25)(9.81)) = 3.261977574 m
    spec = tmp_path / "slide.dyn"
    spec.write_text(
        "given:\n  m = 3 kg\n  mu_k = 0.25\n  v_1 = 4 m/s\n"
        "scene:\n  body block: particle, mass m, at (0, 0)\n"
        "  contact block at G: normal up, mu_k mu_k\n  velocity block: v_1, right\n"
        "  gravity\n  travel block: by d, right, stops\n"
        "find: d [m]\nanswers:\n  d = 3.261977574 m +- 0.0001%\n"
    )
    solution = solve_file(spec)
    (check,) = simulation(solution)
    assert check.passed, check.detail
    assert "q = 3.261978" in check.detail  # where it stops or reaches the end at rest
    assert solution.passed


PENDULUM = """\
given:
  m = 4 kg
  L = 1.2 m
  w_1 = {w_1} rad/s
  turn = {turn} deg
scene:
  point O: (0, 0)
  body rod: mass m, rod L, at (L/2, 0)
  pin rod at O
  omega rod: w_1 cw
  gravity
  travel rod: turns turn cw
find: omega = omega2(rod)
"""


@settings(max_examples=5)
@given(w_1=st.integers(min_value=0, max_value=6), turn=st.integers(min_value=10, max_value=170))
def test_simulated_and_principle_answers_agree_for_any_swing(tmp_path_factory, w_1, turn):
    # a rod pinned at its end, horizontal, turning cw at w_1 and swinging down by `turn`:
    # work and energy and the integrated motion must give the same omega_2
    spec = tmp_path_factory.mktemp("swing") / "swing.dyn"
    spec.write_text(PENDULUM.format(w_1=w_1, turn=turn))
    solution = solve_file(spec)
    (check,) = simulation(solution)
    assert check.passed, check.detail
    assert "not simulated" not in check.detail
