"""A given never used whose name is a near miss of a defaulted initial condition (issue 8)."""

import pytest

from dynsolve.errors import SpecError
from dynsolve.modes.kinematics_mode import build_kinematics_problem
from dynsolve.pipeline import solve_file
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


def test_a_given_no_equation_reads_is_named_as_unused(tmp_path):
    # F = m g needs only m: the height h is a distractor; it must be named, not passed over.
    path = tmp_path / "unused.dyn"
    path.write_text(
        "given:\n  m = 3 kg\n  h = 2 m\nequations:\n  F = m*g\nfind: F\n", encoding="utf-8"
    )
    solution = solve_file(path)
    notes = [c for c in solution.checks if c.name == "unused givens"]
    assert [c.detail for c in notes] == ["h (line 3) is given but not used"]
    assert solution.answers[0].value == pytest.approx(3 * 9.81)


def test_every_given_used_gives_no_unused_note(tmp_path):
    path = tmp_path / "used.dyn"
    path.write_text("given:\n  m = 3 kg\nequations:\n  F = m*g\nfind: F\n", encoding="utf-8")
    assert not [c for c in solve_file(path).checks if c.name == "unused givens"]
