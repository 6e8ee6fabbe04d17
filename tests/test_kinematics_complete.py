"""One-line kinematics: a time found before the start t₀ fails loudly (issue 8)."""

import subprocess
import sys
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.modes.kinematics_mode import build_kinematics_problem
from dynsolve.pipeline import solve_file
from dynsolve.spec.parser import parse_file, parse_spec

# a = -k x, x_0 = 0, v_0 = 2 m/s, k = 4 1/s²: x(t) = (v_0/ω) sin(ω t) = sin(2t) with ω = 2 rad/s,
# so x = -0.5 m is first reached on the way back, at 2t = 7π/6 (t = 7π/12 ≈ 1.83 s); the t(x)
# branch (v > 0 from x_0) gives t = asin(-0.5)/2 = -π/12 ≈ -0.2618 s, before t_0 = 0: an error.
BEFORE_START = """given:
  k = 4 1/s^2
  v_0 = 2 m/s
  x_1 = -0.5 m
kinematics:
  a = -k*x
find: t_1 = t(x_1)
"""

# Same law, x_1 = +0.5 m: t = asin(0.5·2/2)/2 = π/12 ≈ 0.2618 s, after t_0 = 0 (accepted).
AFTER_START = BEFORE_START.replace("x_1 = -0.5 m", "x_1 = 0.5 m")


def test_time_before_start_is_an_error_with_position() -> None:
    with pytest.raises(SpecError, match="comes before the start t_0") as caught:
        build_kinematics_problem(parse_spec(BEFORE_START, "k.dyn"))
    assert (caught.value.position.line, caught.value.position.column) == (7, 7)


def test_time_after_start_is_kept() -> None:
    problem = build_kinematics_problem(parse_spec(AFTER_START, "k.dyn"))
    values = {g.symbol: g.value for g in problem.givens if g.value is not None}
    t_1 = float(problem.targets[0].expr.xreplace(values))
    assert t_1 == pytest.approx(3.141592653589793 / 12, rel=1e-9)


def test_cli_exits_2_on_a_time_before_start(tmp_path: Path) -> None:
    spec = tmp_path / "before.dyn"
    spec.write_text(BEFORE_START)
    run = subprocess.run(
        [sys.executable, "-m", "dynsolve", "solve", str(spec)], capture_output=True, text=True
    )
    assert run.returncode == 2
    assert "before.dyn:7:7" in run.stderr + run.stdout
    assert "Traceback" not in run.stderr


BLOW_UP = """\
given:
  c = 1 1/m
  v_0 = 1 m/s
  t_1 = {t_1}
kinematics:
  a = c*v^2
find: v_1 = v(t_1)
"""


def test_a_value_after_the_motion_blows_up_is_an_error(tmp_path):
    # dv/dt = c v², v(0) = 1 m/s  ->  v = v_0/(1 − c v_0 t) = 1/(1 − t): infinite at t = 1 s.
    # Regression: v(2 s) was reported as −1.00 m/s (the formula's other branch) with exit 0.
    path = tmp_path / "blow_up.dyn"
    path.write_text(BLOW_UP.format(t_1="2 s"), encoding="utf-8")
    with pytest.raises(SpecError, match=r"v\(t\) is not finite at t = 1 s, before t_1 = 2 s"):
        build_kinematics_problem(parse_file(path))


def test_a_value_before_the_blow_up_is_kept(tmp_path):
    # v(0.5 s) = 1/(1 − 0.5) = 2 m/s
    path = tmp_path / "before.dyn"
    path.write_text(BLOW_UP.format(t_1="0.5 s"), encoding="utf-8")
    (answer,) = solve_file(path).answers
    assert answer.value == pytest.approx(2.0, rel=1e-12)
