"""Angles in a hand calculation are written as the textbook writes them (regression):
``sin(45°)``, not ``sin(0.7854)``; an angle outside a sine, as in the work M θ of a couple,
stays in radians; an angle a scene solves for is shown in degrees, not as a bare number."""

from __future__ import annotations

import math
from pathlib import Path

from dynsolve.pipeline import solve_file
from dynsolve.render.json import render_json
from dynsolve.render.latex import render_latex

PROBLEMS = Path(__file__).parent.parent / "problems"


def _substituted(path: Path) -> list[str]:
    solution = solve_file(path)
    return [r.substituted for s in solution.steps for r in s.results if r.substituted]


def test_a_given_angle_inside_a_sine_is_shown_in_degrees():
    # the seed pendulum: θ = 45 deg; O_n = g (m_rod + m_s) sin θ + …
    rows = _substituted(PROBLEMS / "seed" / "fa_seed_pendulum.dyn")
    assert any("sin(45°)" in r for r in rows) and any("cos(45°)" in r for r in rows)
    assert not any("0.7854" in r for r in rows)
    tex = render_latex(solve_file(PROBLEMS / "seed" / "fa_seed_pendulum.dyn"))
    assert "\\sin{\\left(45^\\circ \\right)}" in tex


def test_an_angle_in_the_work_of_a_couple_stays_in_radians():
    # the seed platform: U = M θ2 − W Δh with θ2 = 60° = π/3 = 1.047 rad, and sin θ2
    rows = _substituted(PROBLEMS / "seed" / "rwe_seed_platform.dyn")
    (row,) = [r for r in rows if "sin(60°)" in r]
    assert "900*1.047" in row  # M θ2 in radians, sin θ2 of 60° in the same row
    assert math.isclose(math.pi / 3, 1.047, rel_tol=1e-3)


def test_a_solved_angle_is_shown_with_its_unit():
    # the bob leaves its circle where sin θ3 = v2²/(3 L g): an angle, in degrees
    import json

    solution = solve_file(PROBLEMS / "stages" / "bob_horizontal_then_slack.dyn")
    data = json.loads(render_json(solution))
    (row,) = [r for s in data["steps"] for r in s["results"] if r["name"] == "theta_3_bob"]
    assert row["value"].endswith(" deg")
    shown = float(row["value"].split()[0])
    v2 = float(
        next(
            r["value"] for s in data["steps"] for r in s["results"] if r["name"] == "v_2_bob"
        ).split()[0]
    )
    assert math.isclose(shown, math.degrees(math.asin(v2**2 / (3 * 1 * 9.81))), rel_tol=2e-3)
