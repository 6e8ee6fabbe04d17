"""A given never used whose name is a near miss of a defaulted initial condition (issue 8)."""

import pytest

from dynsolve.errors import SpecError
from dynsolve.kinematics_mode import build_kinematics_problem
from dynsolve.spec.parser import parse_spec

TYPO = """given:
  v_0 = 2 m/s
  x0 = 3 m
  c = 2 m/s^2
kinematics:
  a = c
find: x_t = x(t)
"""


def test_typo_of_x_0_is_an_error_at_the_given() -> None:
    # `x0` is read by nothing; x_0 would silently default to 0 (x = t² + 2t instead of + 3).
    with pytest.raises(SpecError, match="'x0' is never used") as caught:
        build_kinematics_problem(parse_spec(TYPO, "k.dyn"))
    assert (caught.value.position.line, caught.value.position.column) == (3, 3)
    assert "did you mean 'x_0'" in str(caught.value)


def test_correct_name_is_used() -> None:
    # x = x_0 + v_0 t + c t²/2 = 3 + 2t + t² (hand integration of a = c from t_0 = 0)
    problem = build_kinematics_problem(parse_spec(TYPO.replace("x0 =", "x_0 ="), "k.dyn"))
    values = {g.symbol: g.value for g in problem.givens if g.value is not None}
    x_at_1 = float(problem.targets[0].expr.xreplace(values).subs(problem.symbols["t"], 1))
    assert x_at_1 == pytest.approx(6.0)
