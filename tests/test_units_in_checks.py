"""Every value a check or an assumption states has its unit, in the problem's unit system
(issue 25 item 13, second pass): a declared slide's v_P, an until travel's start force,
an impact's closing speed and lost energy, a couple's sense, the work–energy sum of an
interval, the friction at the steepest slope, a simulated event's speed and stop, and a
numerically integrated kinematics step (`v(t_1) = 23.0225` had no unit)."""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems"
MODES = ["exact", "numeric", "auto"]


def _details(name: str, mode: str = "exact") -> list[str]:
    solution = solve_file(PROBLEMS / name, SolveOptions(mode=mode))
    return [c.detail for c in solution.checks] + [a.detail for a in solution.assumptions]


@pytest.mark.parametrize("mode", MODES)
def test_a_declared_slide_states_the_contact_speed_with_its_unit(mode: str) -> None:
    # disk_spinning_slides: v_P = v_G + ω r = 5 + 10 · 0.3 = 8 m/s, to the right as stated
    details = _details("scenes/disk_spinning_slides.dyn", mode)
    assert "its contact point slides that way (v_P = 8 m/s)" in details


@pytest.mark.parametrize("mode", MODES)
def test_an_until_travel_states_its_start_force_in_pounds(mode: str) -> None:
    # cylinder_block_leaves_fps at the top: N = W − (W/g) v₀²/R = 2 − (2/32.2)(16/3)
    # = 2 − 0.33126 = 1.669 lb; the event: v = √(g R cos θ) = 8.350648 ft/s
    details = _details("scenes/cylinder_block_leaves_fps.dyn", mode)
    assert "N_cylinder = 1.669 lb > 0 at the start" in details
    simulated = next(d for d in details if "the event at" in d)
    assert "speed 8.3506" in simulated and " ft/s (principle: 43.7903" in simulated


def test_an_impact_on_a_pinned_door_states_speeds_energy_and_reach_in_fps() -> None:
    # door_bullet_fps: closing speed v₀ = 1800 ft/s; ΔE = ½ m v² − H²/(2 I)
    # = 2515.528 − 5.577667 = 2509.950 ft·lb; the bullet 2 ft out on a 3 ft door: 1 ft within
    details = _details("angular_momentum/door_bullet_fps.dyn")
    assert "before the impact (v_bullet − v_P)·n = 1800 ft/s > 0" in details
    assert "T1 − T2 = 2510 ft·lb ≥ 0" in details
    assert any(d.endswith("|r_G| + half-size − |r_A| = 1 ft ≥ 0") for d in details)


def test_a_clutch_states_the_energy_it_loses_in_joules() -> None:
    # flywheels_clutch: I_A = 1.8, I_B = 0.4 kg·m²; ω = (180 − 16)/2.2 = 74.54545 rad/s;
    # ΔE = (½·1.8·100² + ½·0.4·40²) − ½·2.2·ω² = 9320 − 6112.727 = 3207.273 J
    details = _details("angular_momentum/flywheels_clutch.dyn")
    assert "T1 − T2 = 3207 J ≥ 0 (the clutch slips until they turn as one)" in details


def test_a_couple_of_unknown_size_states_its_sense_with_newton_metres() -> None:
    # gears_couple_needed: F = I_B α_B / r_B = 0.9 · 5 / 0.2 = 22.5 N;
    # M = I_A α_A + F r_A = 0.064 · 10 + 22.5 · 0.1 = 2.89 N·m, ccw as stated
    assert "M = 2.89 N·m ≥ 0: ccw, as stated" in _details("linkages/gears_couple_needed.dyn")


@pytest.mark.parametrize("mode", MODES)
def test_the_work_energy_second_method_states_each_term_in_joules(mode: str) -> None:
    # crate_pulled_impulse: v₂ = 8.604381 m/s, so over 3 s from rest d = ½ v₂ Δt = 12.90657 m;
    # U_P = P cos 30° d = 86.60254 · 12.90657 = 1117.74 J; U_F = −μk N d = −29.24 · 12.90657
    # = −377.388 J; T2 = ½ m v₂² = 10 · 8.604381² = 740.3537 J = 0 + 1117.74 − 377.388
    check = next(
        d for d in _details("scenes/crate_pulled_impulse.dyn", mode) if d.startswith("T1 + ΣU")
    )
    assert check.startswith("T1 + ΣU = 0 J + (U_W = 0 J, U_P = 1117.74 J, U_N_G = 0 J, ")
    assert "U_F_G = -377.388 J) = 740.3537 J; T2 = 740.3537 J; relative difference" in check


def test_the_steepest_slope_states_the_friction_in_newtons() -> None:
    # block_steepest_tips_first (m = 10 kg) at tan β = 0.5: |F| = m g sin β = 98.1 · 0.44721
    # = 43.87 N ≤ μs N = 0.6 · 98.1 · 0.89443 = 52.65 N
    details = _details("scenes/block_steepest_tips_first.dyn")
    assert any(d.startswith("|F| = 43.87 N ≤ μs N = 52.65 N") for d in details)


def test_a_simulated_stop_states_where_in_metres() -> None:
    # bumper_spring_compression: x = v √(m/k) = 3 √(5/2000) = 0.15 m; d = 0.2 + 0.15 = 0.35 m
    simulated = next(
        d for d in _details("scenes/bumper_spring_compression.dyn") if "comes to rest" in d
    )
    assert "it comes to rest at q = 0.35 m (t = " in simulated
    assert "principle: q = 0.35 m, relative" in simulated


@pytest.mark.parametrize("mode", MODES)
def test_a_numerically_integrated_kinematics_step_shows_its_unit(mode: str) -> None:
    # drag_fall: v(3 s) = v_T tanh(k t) = 31.321 tanh(0.93963) = 23.022 m/s;
    # x(3 s) = (m/c) ln cosh(k t) = 100 ln cosh(0.93963) = 38.859 m
    solution = solve_file(PROBLEMS / "kinematics" / "drag_fall.dyn", SolveOptions(mode=mode))
    rows = {r.name: r for s in solution.steps for r in s.results}
    assert rows["v(t_1)"].value == "23.0225 m/s" and rows["v(t_1)"].formula == ""
    assert rows["x(t_1)"].value == "38.8591 m"
    assert rows["x(t_1)"].value_latex == "38.8591\\,\\mathrm{m}"


def test_every_format_shows_the_integrated_value_with_its_unit() -> None:
    path = str(PROBLEMS / "kinematics" / "drag_fall.dyn")
    runner = CliRunner()
    terminal = runner.invoke(app, ["solve", path], env={"COLUMNS": "200"}).output
    assert "v(t_1) = 23.0225 m/s" in terminal
    data = json.loads(runner.invoke(app, ["solve", path, "--format", "json"]).output)
    values = {r["name"]: r["value"] for s in data["steps"] for r in s["results"]}
    assert values["v(t_1)"] == "23.0225 m/s"
    markdown = runner.invoke(app, ["solve", path, "--format", "markdown"]).output
    assert "= 23.0225\\,\\mathrm{m/s}$$" in markdown


def test_a_3d_travel_from_rest_states_its_zero_energy_in_joules() -> None:
    # gear_rolling starts at rest: T1 = 0 J (SI)
    assert "at rest: T1 = 0 J" in _details("rigid3d/gear_rolling.dyn")


def test_a_speed_found_a_second_way_states_both_values_in_metres_per_second() -> None:
    # drum_block_cord_energy: U_W = 20 · 9.81 · 2 = 392.4 J = 21.71875 v² → v = 4.250569 m/s;
    # Example 17.11's a = 4.517 m/s² gives v = √(2 a h) = 4.2506 m/s the second way
    check = next(d for d in _details("scenes/drum_block_cord_energy.dyn") if "(work–energy: " in d)
    assert ": 4.250569 m/s (work–energy: 4.250569 m/s; relative difference " in check
