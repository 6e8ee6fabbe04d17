"""Method II (issue 12, part 4): a solved body's moments balanced about a second point."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.model.scene import Body
from dynsolve.pipeline import solve_file
from dynsolve.principles.moment_check import balance
from dynsolve.principles.newton_euler import ForceTerm, Kinematics

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


def _moment_checks(name: str) -> list:
    solution = solve_file(PROBLEMS / name)
    return [c for c in solution.checks if c.name.startswith("second moment point")]


def test_the_pendulum_balances_about_the_pin_with_the_seed_notes_moment():
    # seed notes: ΣM_O = m_rod g (L/2) cos θ + m_s g d_s cos θ + M = 143.65 N·m = I_O α
    (check,) = _moment_checks("seed/fa_seed_pendulum.dyn")
    assert check.passed
    assert "about O: 143.646 = 143.646" in check.detail


@pytest.mark.parametrize(
    "name", ["seed/gpm_seed_spool.dyn", "seed/tr_hib_car.dyn", "scenes/crate_push_tips.dyn"]
)
def test_rolling_and_translating_bodies_balance_about_every_point(name):
    (check,) = _moment_checks(name)
    assert check.passed and check.detail.count(",") >= 2  # G and at least two more points


def _rod(alpha_value):
    # a 10-kg, 2-m rod pinned at its end O, released horizontal: α = −3g/(2L) = −7.3575 rad/s²
    # (cw), O_y = m g / 4 (by hand); a wrong α must fail the check
    m, g, L, alpha = sympy.symbols("m g L alpha")
    rod = Body("rod", m, m * L**2 / 12, (L / 2, 0), (L / 2, 0), "rod", (L,), {}, False, "", 0, 0)
    weight = ForceTerm("W", "weight", "rod", (L / 2, 0), "G", (0, -1), m * g, True)
    pin = ForceTerm("O", "reaction", "rod", (0, 0), "O", (0, 1), m * g / 4, False)
    kin = Kinematics("rotation", alpha, (0, alpha * L / 2), 0)
    values = {m: 10, g: sympy.Rational(981, 100), L: 2, alpha: alpha_value}
    return balance("rod", rod, [weight, pin], [], kin, values)


def test_a_wrong_angular_acceleration_fails_the_second_point():
    assert _rod(sympy.Rational(-2943, 400)).passed
    wrong = _rod(sympy.Rational(-2943, 100))  # I_G used for I_O: 4 times too large
    assert not wrong.passed and "relative gap" in wrong.detail


def test_the_check_is_shown_in_the_terminal():
    result = CliRunner().invoke(app, ["solve", str(PROBLEMS / "seed/gpm_seed_spool.dyn")])
    assert "second moment point" in result.stdout
