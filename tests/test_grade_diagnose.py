"""Each classic mistake reproduced from a hand-made wrong answer, on the problem's own model.

The drum is Hibbeler 12e Example 17.11 in equation mode (problems/equations/fa_hib_drum.dyn):
alpha = m_b g r / (I_O + m_b r^2), I_O = m_d k_O^2 = 60(0.25)^2 = 3.75 kg m^2,
m_b = 20 kg, r = 0.4 m, g = 9.81 m/s^2: alpha = 78.48/6.95 = 11.292 rad/s^2, a = alpha r.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from dynsolve.grade.diagnose import Diagnoser
from dynsolve.grade.key import base_keys
from dynsolve.grade.semantics import Rule, judge
from dynsolve.spec.parser import parse_file, parse_spec

DRUM = Path(__file__).parent.parent / "problems" / "equations" / "fa_hib_drum.dyn"


@pytest.fixture(scope="module")
def drum() -> tuple[Diagnoser, dict]:
    spec = parse_file(DRUM)
    return Diagnoser(spec), dict(base_keys(spec).shared)


def _named(doctor: Diagnoser, keys: dict, part: str, cell: str) -> str:
    result = judge(cell, keys[part], Rule())
    assert result.verdict == "wrong" and result.value is not None
    return doctor.diagnose(part, result.value, keys, Rule())


def test_g_left_out(drum: tuple[Diagnoser, dict]) -> None:
    # g = 1: alpha = 20(1)(0.4)/6.95 = 1.151 rad/s^2
    assert _named(*drum, "alpha", "1.15 rad/s^2") == "g left out (g = 1)"


def test_g_from_the_other_system(drum: tuple[Diagnoser, dict]) -> None:
    # g = 32.2: alpha = 20(32.2)(0.4)/6.95 = 257.6/6.95 = 37.06 rad/s^2
    assert "g from the US system" in _named(*drum, "alpha", "37.1 rad/s^2")


def test_diameter_for_radius(drum: tuple[Diagnoser, dict]) -> None:
    # r = 0.8: alpha = 20(9.81)(0.8)/(3.75 + 20(0.64)) = 156.96/16.55 = 9.484 rad/s^2
    assert _named(*drum, "alpha", "9.48 rad/s^2") == "the diameter used for the radius r"


def test_power_of_ten(drum: tuple[Diagnoser, dict]) -> None:
    # a = 4.5168 m/s^2 written as 45.2: x10
    assert "power-of-ten slip (x10)" in _named(*drum, "a", "45.2 m/s^2")
    # T = 105.86 N written as 0.106 N: x1/1000 (a kN value in N)
    assert "power-of-ten slip (x1/1000)" in _named(*drum, "T", "0.106 N")


def test_degrees_for_radians(drum: tuple[Diagnoser, dict]) -> None:
    # 11.292 rad/s^2 = 647.0 deg/s^2, written with rad
    assert _named(*drum, "alpha", "647 rad/s^2") == "a value in degrees labelled as radians (x57.3)"


def test_another_part(drum: tuple[Diagnoser, dict]) -> None:
    # a's number given for T: 4.5168 in T's unit
    assert _named(*drum, "T", "4.52 N") == "the answer of a given for T"


def test_no_diagnosis_for_an_unrelated_number(drum: tuple[Diagnoser, dict]) -> None:
    assert _named(*drum, "alpha", "7.77 rad/s^2") == ""


def _diagnose(text: str, part: str, cell: str) -> str:
    spec = parse_spec(text, "p.dyn")
    keys = dict(base_keys(spec).shared)
    return _named(Diagnoser(spec), keys, part, cell)


def test_degrees_taken_as_radians() -> None:
    # F_x = F cos(theta) = 10 cos 30 deg = 8.660 N; with 30 rad: 10 cos(30) = 1.543 N
    text = "given:\n  F = 10 N\n  theta = 30 deg\nequations:\n  F_x = F*cos(theta)\nfind: F_x\n"
    assert _diagnose(text, "F_x", "1.54 N") == "theta in degrees taken as radians"


def test_mu_s_and_mu_k_swapped() -> None:
    # F = mu_k m g = 0.4(10)(9.81) = 39.24 N; with mu_s: 0.5(10)(9.81) = 49.05 N
    text = "given:\n  m = 10 kg\n  mu_s = 0.5\n  mu_k = 0.4\nequations:\n  F = mu_k*m*g\nfind: F\n"
    assert _diagnose(text, "F", "49.1 N") == "mu_s and mu_k swapped"


def test_parallel_axis_forgotten() -> None:
    # I_O = I_G + m d^2 = 0.5 + 2(0.5)^2 = 1.0 kg m^2; M = I_O alpha: alpha = 10/1 = 10 rad/s^2
    # with I_G for I_O: alpha = 10/0.5 = 20 rad/s^2
    text = (
        "given:\n  m = 2 kg\n  I_G = 0.5 kg*m^2\n  d = 0.5 m\n  M = 10 N*m\n"
        "equations:\n  I_O = I_G + m*d^2\n  M = I_O*alpha\nfind: alpha\n"
    )
    assert _diagnose(text, "alpha", "20 rad/s^2") == (
        "I_G used for I_O (the parallel-axis term m d^2 forgotten)"
    )


def test_weight_used_as_mass() -> None:
    # FPS: m = W/g = 64.4/32.2 = 2 slug, a = F/m = 10/2 = 5 ft/s^2;
    # W in lb used as the mass: m = 64.4 slug, a = 10/64.4 = 0.1553 ft/s^2
    text = (
        "units: FPS\ngiven:\n  W = 64.4 lb\n  F = 10 lb\n  g = 32.2 ft/s^2\n"
        "equations:\n  m = W/g\n  F = m*a\nfind: a [ft/s^2]\n"
    )
    assert _diagnose(text, "a", "0.155 ft/s^2") == "the weight W in lb used as a mass (x32.2)"


def test_re_solves_are_cached(drum: tuple[Diagnoser, dict]) -> None:
    doctor, _ = drum
    assert doctor.mistakes() is doctor.mistakes()


def test_radians_labelled_degrees(drum: tuple[Diagnoser, dict]) -> None:
    # 11.3 written with deg/s^2: 11.3 pi/180 = 0.1972 rad/s^2, the key times pi/180
    named = _named(*drum, "alpha", "11.3 deg/s^2")
    assert named == "a value in radians labelled as degrees (/57.3)"


def test_a_static_answer_for_a_dynamic_problem(drum: tuple[Diagnoser, dict]) -> None:
    # T = m_b g = 20(9.81) = 196.2 N, as if the block hung at rest (the key is 105.86 N)
    assert _named(*drum, "T", "196 N") == "the static answer T = m_b g, as if nothing accelerated"


def test_the_static_answer_in_us_units() -> None:
    # a 10-lb weight W pulled up by T with a = 8 ft/s^2: T = W + (W/g) a = 10 + 2.484 lb;
    # the static answer is T = W = 10 lb
    text = (
        "units: FPS\ngiven:\n  W = 10 lb\n  a = 8 ft/s^2\n  g = 32.2 ft/s^2\n"
        "equations:\n  T - W = (W/g)*a\nfind: T [lb]\n"
    )
    assert _diagnose(text, "T", "10 lb") == "the static answer T = W, as if nothing accelerated"


def test_the_printed_numbers_for_a_variant() -> None:
    # s1's variant has m_b = 25 kg: alpha = 25(9.81)(0.4)/(3.75 + 25(0.16)) = 98.1/7.75
    # = 12.658 rad/s^2; 11.3 rad/s^2 is the printed problem's (m_b = 20 kg) answer
    from dynsolve.grade.semantics import Key
    from dynsolve.units import Dim

    doctor = Diagnoser(parse_file(DRUM), variants={"s1": {"m_b": "25 kg"}})
    keys = {"alpha": Key("alpha", 12.658, Dim(0, 0, -2), "rad/s^2")}
    result = judge("11.3 rad/s^2", keys["alpha"], Rule())
    assert result.verdict == "wrong" and result.value is not None
    named = doctor.diagnose("alpha", result.value, keys, Rule(), "s1")
    assert named == "the numbers of the problem as printed used, not those of your own variant"


def test_rounded_to_two_figures(drum: tuple[Diagnoser, dict]) -> None:
    # 105.86 N to 2 figures is 110 N (3.9 % off); 11.292 rad/s^2 to 2 figures is 11 (2.6 %)
    _, keys = drum
    assert judge("110 N", keys["T"], Rule()).detail.startswith("rounded to 2 significant")
    assert judge("11 rad/s^2", keys["alpha"], Rule()).detail.startswith("rounded to 2")
    assert judge("107 N", keys["T"], Rule()).detail.startswith("off by")  # not a rounding


def test_top_three_mistakes_skip_undiagnosed_answers() -> None:
    from dynsolve.grade.report import class_summary
    from dynsolve.grade.run import StudentResult

    feedbacks = ["off by 12 %"] * 5 + ["g left out (g = 1) (off by 90 %)"] * 3
    feedbacks += ["a power-of-ten slip (x10): check the unit prefix (off by 900 %)"] * 2
    feedbacks += ["the diameter used for the radius r (off by 16 %)"]
    rows = [
        StudentResult(
            f"s{i}", 0.0, {"a": {"answer": "", "verdict": "wrong", "credit": 0.0, "feedback": text}}
        )
        for i, text in enumerate(feedbacks)
    ]
    mistakes = class_summary(rows)["parts"]["a"]["mistakes"]
    assert [m for m, _ in mistakes] == [
        "g left out (g = 1)",
        "a power-of-ten slip (x10): check the unit prefix",
        "the diameter used for the radius r",
    ]
