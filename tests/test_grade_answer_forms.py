"""Answers as students write them: direction words per axis, bare magnitudes, the signed
rule, Unicode and typed unit forms, decimal commas, sig figs in the unit written.

Keys from the scene-mode drum, problems/seed/fa_hib_drum.dyn (Hibbeler 12e Example 17.11):
I_O = 60(0.25)^2 = 3.75 kg m^2, alpha = m_b g r/(I_O + m_b r^2) = 78.48/6.95 = 11.292 rad/s^2
clockwise, T = I_O alpha / r = 105.86 N, a = alpha r = 4.5168 m/s^2 down.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from dynsolve.grade.cells import CellError, read_cell
from dynsolve.grade.key import base_keys
from dynsolve.grade.semantics import Key, Rule, judge, rules_for
from dynsolve.spec.parser import parse_file, parse_spec
from dynsolve.units import Dim

ROOT = Path(__file__).parent.parent
KEYS = base_keys(parse_file(ROOT / "problems" / "seed" / "fa_hib_drum.dyn")).shared


def _verdict(cell: str, part: str, rule: Rule | None = None) -> str:
    return judge(cell, KEYS[part], rule or Rule()).verdict


def test_keys_carry_their_direction() -> None:
    assert KEYS["alpha"].direction == "cw" and KEYS["a"].direction == "down"


@pytest.mark.parametrize(
    ("cell", "part", "verdict"),
    [
        ("4.52 m/s^2 down", "a", "correct"),
        ("4.52 m/s^2 downward", "a", "correct"),
        ("4.52 m/s^2 Downwards", "a", "correct"),
        ("4.52 m/s^2 up", "a", "sign"),
        ("4.52 m/s^2 upwards", "a", "sign"),
        ("4.52 m/s^2 left", "a", "sign"),  # another axis: never a right answer
        ("4.52 m/s^2 to the left", "a", "sign"),
        ("4.52 m/s^2 right", "a", "sign"),
        ("11.3 rad/s^2 cw", "alpha", "correct"),
        ("11.3 rad/s^2 clockwise", "alpha", "correct"),
        ("11.3 rad/s^2 Clockwise.", "alpha", "correct"),
        ("11.3 rad/s^2 counterclockwise", "alpha", "sign"),
        ("11.3 rad/s^2 anticlockwise", "alpha", "sign"),
        ("11.3 rad/s^2 counter-clockwise", "alpha", "sign"),
        ("11.3 rad/s^2 down", "alpha", "sign"),  # not a sense of rotation
        ("11.3 rad/s^2 up", "alpha", "sign"),
        ("4.52 m/s^2 cw", "a", "sign"),  # a sense of rotation for a linear quantity
    ],
)
def test_direction_words_name_an_axis(cell: str, part: str, verdict: str) -> None:
    assert _verdict(cell, part) == verdict


def test_wrong_axis_says_why() -> None:
    assert "another axis" in judge("4.52 m/s^2 left", KEYS["a"], Rule()).detail
    assert "sense of rotation" in judge("11.3 rad/s^2 down", KEYS["alpha"], Rule()).detail
    # a wrong axis with a wrong magnitude is simply wrong
    assert _verdict("9.9 m/s^2 left", "a") == "wrong"


def test_bare_magnitude_is_right_by_default() -> None:
    # the textbook writes alpha = 11.3 rad/s^2 (cw) and a = 4.52 m/s^2 (down)
    assert _verdict("11.3 rad/s^2", "alpha") == "correct"
    assert _verdict("4.52 m/s^2", "a") == "correct"
    # an explicit sign is taken as written: down is negative, so +4.52 is up
    assert _verdict("+4.52 m/s^2", "a") == "sign"
    assert _verdict("-4.52 m/s^2", "a") == "correct"
    assert _verdict("-106 N", "T") == "sign"  # T = +105.86 N


def test_a_signed_scalar_is_not_a_magnitude() -> None:
    # work of -50 J is not 50 J: energy has no direction to leave out
    work = Key("U", -50.0, Dim.of("energy"), "J")
    assert judge("50 J", work, Rule()).verdict == "sign"
    assert judge("-50 J", work, Rule()).verdict == "correct"


def test_signed_rule_takes_a_bare_number_as_positive() -> None:
    spec = parse_spec(
        "given:\n  m = 2 kg\nequations:\n  W = m*g\nfind: W\ngrading:\n  signed\n  W magnitude\n",
        "s.dyn",
    )
    assert [(r.part, r.key, r.value) for r in spec.grading] == [
        ("", "signed", 1),
        ("W", "signed", 0),
    ]
    rules = rules_for(["alpha", "W"], spec.grading)
    assert rules["alpha"].signed and not rules["W"].signed
    assert _verdict("11.3 rad/s^2", "alpha", rules["alpha"]) == "sign"
    assert _verdict("11.3 rad/s^2 cw", "alpha", rules["alpha"]) == "correct"
    assert _verdict("-11.3 rad/s^2", "alpha", rules["alpha"]) == "correct"


@pytest.mark.parametrize(
    ("cell", "part"),
    [
        ("4.52 m/s2", "a"),
        ("4.52 m/s²", "a"),
        ("4.52 m s^-2", "a"),
        ("4.52 m·s⁻²", "a"),
        ("4.52 m⋅s^-2", "a"),
        ("−4.52 m/s^2", "a"),  # U+2212 minus: down
        ("4.52 m/s^2.", "a"),
        ("106 N.", "T"),
        ("1.06 x 10^2 N", "T"),
        ("1.06×10² N", "T"),
        ("106N", "T"),
        ("11.3 rad/s²", "alpha"),
        ("0.106 kN", "T"),
        ("647 deg/s^2", "alpha"),  # 11.292 rad/s^2 x 57.296 = 647.0 deg/s^2
        ("4.52m/s^2", "a"),
        ("\u20134.52 m/s^2", "a"),  # an en dash for the minus
        ("4.52 m/s^2 down.", "a"),
    ],
)
def test_typed_forms_are_read(cell: str, part: str) -> None:
    assert _verdict(cell, part) == "correct", judge(cell, KEYS[part], Rule()).detail


def test_degree_sign() -> None:
    assert read_cell("30°").value == pytest.approx(0.5235988)  # 30 pi/180 rad


def test_bare_zero_is_zero_in_any_unit() -> None:
    zero = Key("v", 0.0, KEYS["a"].dim, "m/s^2")
    assert judge("0", zero, Rule(atol=0.01)).verdict == "correct"
    assert judge("0", KEYS["T"], Rule()).verdict == "wrong"  # read, and 100 % off
    assert judge("3", KEYS["T"], Rule()).verdict == "unreadable"  # other bare numbers: no unit


def test_decimal_commas() -> None:
    assert judge("4,52 m/s^2", KEYS["a"], Rule(), decimal_comma=True).verdict == "correct"
    # a comma that cannot be a thousands separator is a decimal comma in any file
    assert judge("4,52 m/s^2", KEYS["a"], Rule()).verdict == "correct"
    # 105,86 N in a decimal-comma file; 1,060 is ambiguous in a decimal-point one
    assert judge("105,86 N", KEYS["T"], Rule(), decimal_comma=True).verdict == "correct"
    ambiguous = judge("1,060 kN", KEYS["T"], Rule())
    assert ambiguous.verdict == "unreadable" and "1060 or 1.060" in ambiguous.detail
    assert judge("0,106 kN", KEYS["T"], Rule(), decimal_comma=True).verdict == "correct"
    assert judge("1.060 N", KEYS["T"], Rule(), decimal_comma=True).verdict == "unreadable"
    assert judge("1,060.5 N", KEYS["T"], Rule()).verdict == "unreadable"  # thousands: refused


def test_spaces_inside_a_number_are_refused() -> None:
    with pytest.raises(CellError, match="number inside the unit"):
        read_cell("1 060 N")


def test_sigfig_in_the_unit_written() -> None:
    # 4.5168 m/s^2 / 0.3048 = 14.819 ft/s^2: to 3 figures 14.8, allowance 0.51 x 0.1 ft/s^2
    # (in SI 14.8 ft/s^2 = 4.5110 m/s^2 is 0.0058 off, beyond the SI allowance 0.0051)
    assert _verdict("14.8 ft/s^2 down", "a", Rule(sigfig=3)) == "correct"
    assert _verdict("14.8 ft/s^2", "a", Rule(sigfig=3)) == "correct"
    assert _verdict("14.9 ft/s^2", "a", Rule(sigfig=3)) == "wrong"  # 0.081 > 0.051
    # 105.86 N / 4.44822 = 23.799 lb: 23.8 passes to 3 figures
    assert _verdict("23.8 lb", "T", Rule(sigfig=3)) == "correct"


def test_sigfig_option_through_the_command_line(tmp_path: Path) -> None:
    import json

    from typer.testing import CliRunner

    from dynsolve.cli import app

    # a = 4.5168 m/s^2 = 14.819 ft/s^2 and T = 105.86 N = 23.799 lb: right to 3 figures
    answers = tmp_path / "answers.csv"
    answers.write_text("student,alpha,T,a\ns1,11.3 rad/s^2,23.8 lb,14.8 ft/s^2\n")
    out = tmp_path / "r.json"
    drum = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
    args = ["grade", str(drum), str(answers), "--sigfig", "3", "--json", str(out)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    parts = json.loads(out.read_text())["students"][0]["parts"]
    assert {p: c["verdict"] for p, c in parts.items()} == {
        "alpha": "correct",
        "T": "correct",
        "a": "correct",
    }
