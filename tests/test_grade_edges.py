"""Grading edges closed for issue 9: decimal places in e-notation, keys of exactly 0."""

from __future__ import annotations

from pathlib import Path

from dynsolve.grade.command import GradeRequest, grade
from dynsolve.grade.semantics import Key, Rule, judge
from dynsolve.units import Dim

LENGTH = Dim.of("length")


def test_decdig_counts_the_place_an_e_notation_number_is_written_to():
    key = Key("x", 0.4517, LENGTH, "m")
    # 4.52e-1 m = 0.452 m, written to 3 decimals: decdig 2 asks for 2, |0.452 - 0.4517| ok
    assert judge("4.52e-1 m", key, Rule(decdig=2)).verdict == "correct"
    # 4.5e-1 m = 0.45 m, written to 2 decimals, 0.0017 off: within 0.51e-2
    assert judge("4.5e-1 m", key, Rule(decdig=2)).verdict == "correct"
    # 0.5 m is written to 1 decimal: too few, but right to that place (|0.5 - 0.4517| <= 0.051)
    short = judge("0.5 m", key, Rule(decdig=2, partial=0.5))
    assert (short.verdict, short.credit) == ("sigfig", 0.5)


def test_decdig_of_a_number_written_to_the_tens():
    key = Key("x", 45.17, LENGTH, "m")
    # 4.5e1 m = 45 m, written to the units (1 - 1 = 0 decimals) where 1 is asked; right to
    # the units (|45 - 45.17| <= 0.51): the short verdict
    assert judge("4.5e1 m", key, Rule(decdig=1)).verdict == "sigfig"
    # 4.517e1 = 45.17, written to 2 decimals
    assert judge("4.517e1 m", key, Rule(decdig=1)).verdict == "correct"
    # 5e1 m = 50 m is written to the tens: right to that place (|50 - 45.17| <= 5.1), short;
    # 6e1 m = 60 m is off by 14.8 > 5.1: wrong
    assert judge("5e1 m", key, Rule(decdig=1)).verdict == "sigfig"
    assert judge("6e1 m", key, Rule(decdig=1)).verdict == "wrong"


ZERO = """given:
  F = 0 N
  m = 2 kg
equations:
  F = m*a
find: a [m/s^2]
"""


def _class(tmp_path: Path) -> tuple[Path, Path]:
    problem, answers = tmp_path / "p.dyn", tmp_path / "a.csv"
    problem.write_text(ZERO, encoding="utf-8")
    answers.write_text("student,a\ns1,0 m/s^2\ns2,0.001 m/s^2\n", encoding="utf-8")
    return problem, answers


def test_a_key_of_zero_without_an_absolute_tolerance_is_warned(tmp_path):
    # F = m a with F = 0: a = 0 exactly; 1 % of 0 is 0, so 0.001 m/s² fails, and the run
    # says why and how to set a tolerance
    run = grade(GradeRequest(*_class(tmp_path)))
    verdicts = {r.student: r.parts["a"]["verdict"] for r in run.results}
    assert verdicts == {"s1": "correct", "s2": "wrong"}
    assert any(w.startswith("the key of a is 0") and "atol" in w for w in run.warnings)


def test_an_absolute_tolerance_grades_around_a_zero_key(tmp_path):
    run = grade(GradeRequest(*_class(tmp_path), atol_text="0.01 m/s^2"))
    assert {r.student: r.parts["a"]["verdict"] for r in run.results} == {
        "s1": "correct",
        "s2": "correct",
    }
    assert not any("key of a is 0" in w for w in run.warnings)


ROD = """given:
  m = 10 kg
  L = 2 m
  g = 9.81 m/s^2
scene:
  point O: (0, 0)
  body rod: mass m, rod L, at (L/2, 0)
  pin rod at O
  gravity
find: alpha = alpha(rod) [rad/s^2]
"""


def test_i_g_for_i_o_is_diagnosed_in_a_scene(tmp_path):
    # a rod pinned at one end, released horizontal: alpha = (m g L/2)/(m L²/3) = 3g/(2L)
    # = 7.36 rad/s² cw; with I_G = m L²/12 for I_O: alpha = 6g/L = 29.4 rad/s² (by hand)
    problem, answers = tmp_path / "rod.dyn", tmp_path / "a.csv"
    problem.write_text(ROD, encoding="utf-8")
    answers.write_text("student,alpha\ns1,7.36 rad/s^2 cw\ns2,29.4 rad/s^2 cw\n", encoding="utf-8")
    run = grade(GradeRequest(problem, answers))
    parts = {r.student: r.parts["alpha"] for r in run.results}
    assert parts["s1"]["verdict"] == "correct"
    assert parts["s2"]["verdict"] == "wrong"
    assert "parallel-axis" in parts["s2"]["feedback"]


def test_i_g_for_i_o_is_diagnosed_on_each_students_variant(tmp_path):
    # s1 has L = 3 m: 3g/(2L) = 4.905, with I_G: 6g/L = 19.62 rad/s²;
    # s2 has L = 1 m: 14.715, with I_G: 58.86 rad/s² (by hand)
    problem, answers, variants = tmp_path / "rod.dyn", tmp_path / "a.csv", tmp_path / "v.csv"
    problem.write_text(ROD + "vary:\n  L = 1..3 m step 1\n", encoding="utf-8")
    variants.write_text("student,L\ns1,3 m\ns2,1 m\n", encoding="utf-8")
    answers.write_text("student,alpha\ns1,19.6 rad/s^2 cw\ns2,14.7 rad/s^2 cw\n", encoding="utf-8")
    run = grade(GradeRequest(problem, answers, variants=variants))
    parts = {r.student: r.parts["alpha"] for r in run.results}
    assert parts["s2"]["verdict"] == "correct"
    assert parts["s1"]["verdict"] == "wrong" and "parallel-axis" in parts["s1"]["feedback"]
