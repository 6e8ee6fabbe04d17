"""a(x) laws in one-line kinematics, once speed cliffs (issue 25, item 11): the spring written
as Newton's law, an inverse-square pull and a spring at micro scale, right in every mode;
max(v)/min(v) from v² = f(x) where x(t) has no closed form.

Correctness only (the time is bench/oneline_laws.py's). Every expected number is derived
by hand in the comment above it.
"""

from __future__ import annotations

import math

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text
from dynsolve.system import SolveOptions

MODES = ("exact", "numeric", "auto")

# m = 2 kg, k = 8 N/m: ω = √(k/m) = 2 rad/s; from rest at x₀ = 0.1 m, x = 0.1 cos 2t.
# x = 0 at 2t = π/2: t = π/4 s; there v = −ω x₀ = −0.2 m/s (moving towards −x), the
# smallest v; the particle swings to x = −0.1 m.
NEWTON_SPRING = """given:
  m = 2 kg
  k = 8 N/m
  x_0 = 0.1 m
  v_0 = 0 m/s
  x_c = 0 m
kinematics:
  m*a = -k*x
find: t_c = t_at(x, 0), v_c = v(x_c), v_lo = min(v), x_lo = min(x)
"""

# C = 4 m³/s², from rest at x₀ = 2 m: v² = 2C (1/x − 1/x₀); at x₁ = 1 m, v² = 8 (1 − 1/2)
# = 4, v = −2 m/s (falling in). t = ∫ dx/|v| from x₁ to x₀; with x = x₀ cos² θ this is
# √(x₀³/2C) (θ + sin θ cos θ) at cos² θ = x₁/x₀ = 1/2: θ = π/4, so t = 1 · (π/4 + 1/2)
# = 1.285398 s.
INVERSE_SQUARE = """given:
  C = 4 m^3/s^2
  x_0 = 2 m
  v_0 = 0 m/s
  x_1 = 1 m
kinematics:
  a = -C/x^2
find: v_1 = v(x_1), t_1 = t_at(x, x_1)
"""

# m = 1e-9 kg, k = 4e-9 N/m: ω = 2 rad/s again; from rest at x₀ = 1 µm: x = 0 at t = π/4 s,
# the swing to −1 µm, the largest v = ω x₀ = 2e-6 m/s (on the way back, at x = 0).
MICRO_SPRING = """given:
  m = 1e-9 kg
  k = 4e-9 N/m
  x_0 = 1 um
  v_0 = 0 m/s
kinematics:
  m*a = -k*x
find: t_c = t_at(x, 0), x_lo = min(x), v_hi = max(v)
"""

# m a = −k x − c x³ (m = 2 kg, k = 8 N/m, c = 0.5 N/m³) from rest at x₀ = 0.1 m: no closed
# x(t). v² = (k/m)(x₀² − x²) + (c/2m)(x₀⁴ − x⁴); a = 0 only at x = 0, where v² = 0.04 +
# 0.125e-4 = 0.0400125: max(v) = +0.2000312 m/s (passed going back, a' v < 0 there) and
# min(v) = −0.2000312 m/s (the first pass, towards −x).
DUFFING = """given:
  m = 2 kg
  k = 8 N/m
  c = 0.5 N/m^3
  x_0 = 0.1 m
  v_0 = 0 m/s
kinematics:
  m*a = -k*x - c*x^3
find: v_hi = max(v), v_lo = min(v)
"""


def values(text: str, mode: str) -> dict[str, float]:
    solution = solve_text(text, "law.dyn", SolveOptions(mode=mode))  # type: ignore[arg-type]
    assert not any(check.failed for check in solution.checks), solution.checks
    return {a.name: a.value for a in solution.answers}  # type: ignore[misc]


@pytest.mark.parametrize("mode", MODES)
def test_spring_written_as_newtons_law(mode: str) -> None:
    found = values(NEWTON_SPRING, mode)
    assert found["t_c"] == pytest.approx(math.pi / 4, rel=1e-9)
    assert found["v_c"] == pytest.approx(-0.2, rel=1e-9)
    assert found["v_lo"] == pytest.approx(-0.2, rel=1e-9)
    assert found["x_lo"] == pytest.approx(-0.1, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_inverse_square_pull(mode: str) -> None:
    found = values(INVERSE_SQUARE, mode)
    assert found["v_1"] == pytest.approx(-2.0, rel=1e-9)
    assert found["t_1"] == pytest.approx(math.pi / 4 + 0.5, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_spring_at_micro_scale(mode: str) -> None:
    found = values(MICRO_SPRING, mode)
    assert found["t_c"] == pytest.approx(math.pi / 4, rel=1e-9)
    assert found["x_lo"] == pytest.approx(-1e-6, rel=1e-9)
    assert found["v_hi"] == pytest.approx(2e-6, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_largest_and_smallest_speed_without_a_closed_x_of_t(mode: str) -> None:
    found = values(DUFFING, mode)
    speed = math.sqrt(0.04 + 0.125e-4)
    assert found["v_hi"] == pytest.approx(speed, rel=1e-9)
    assert found["v_lo"] == pytest.approx(-speed, rel=1e-9)


def test_no_largest_speed_under_an_inverse_square_pull() -> None:
    # a = −C/x² is never 0: v only grows in size as the particle falls in, so max(v) has
    # no stationary point to be at; refused with the reason, never a number
    text = INVERSE_SQUARE.replace("find: v_1 = v(x_1), t_1 = t_at(x, x_1)", "find: v_hi = max(v)")
    with pytest.raises(SpecError, match="no largest value"):
        solve_text(text, "law.dyn")


def test_the_spring_as_newtons_law_through_the_cli(tmp_path) -> None:  # type: ignore[no-untyped-def]
    (tmp_path / "spring.dyn").write_text(NEWTON_SPRING, encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(tmp_path / "spring.dyn"), "-f", "json"])
    assert result.exit_code == 0, result.output
    assert '"t_c"' in result.stdout and "0.785398" in result.stdout
