"""Keys per student: the base solve, and the adapter to ``dynsolve.grade.expected`` (variants);
the bundled example class graded end to end.

Hand values (Hibbeler 12e Example 17.11): alpha = 78.48/6.95 = 11.292 rad/s^2 cw,
T = 105.86 N, a = 4.517 m/s^2 down. A variant with m_b = 10 kg: alpha = 10(9.81)(0.4)/
(3.75 + 1.6) = 39.24/5.35 = 7.334 rad/s^2 cw.
"""

from __future__ import annotations

import sys
import types
from dataclasses import dataclass
from pathlib import Path

import pytest

from dynsolve.grade.command import GradeRequest, grade
from dynsolve.grade.key import base_keys, variant_keys
from dynsolve.spec.parser import parse_file
from dynsolve.system import SolveOptions
from dynsolve.units import Dim

ROOT = Path(__file__).parent.parent
SCENE_DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"


def test_base_keys_are_signed_si_values() -> None:
    keys = base_keys(parse_file(SCENE_DRUM)).shared
    assert keys["alpha"].value == pytest.approx(-11.292, rel=1e-4)  # cw: negative
    assert keys["T"].value == pytest.approx(105.86, rel=1e-4)
    assert keys["a"].value == pytest.approx(-4.5168, rel=1e-4)  # down: negative


@dataclass(frozen=True)
class _Expected:  # the shape of dynsolve.grade.expected.Expected (branch variants)
    name: str
    value: float
    si_unit: str
    unit: str
    dim: Dim
    direction: str = ""


@dataclass(frozen=True)
class _Student:
    student: str
    answers: dict
    path: str
    error: str = ""


@dataclass(frozen=True)
class _Result:
    students: dict
    path: str


def _fake_expected(monkeypatch: pytest.MonkeyPatch) -> None:
    def expected_answers(spec: object, variants: dict, options: object) -> _Result:
        alpha = _Expected("alpha", 7.334, "rad/s^2", "rad/s^2", Dim(0, 0, -2), "cw")
        return _Result(
            {
                "s1": _Student("s1", {"alpha": alpha}, "vectorized"),
                "s2": _Student("s2", {}, "per-variant", error="cannot read m_b"),
            },
            "vectorized",
        )

    module = types.ModuleType("dynsolve.grade.expected")
    module.expected_answers = expected_answers  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "dynsolve.grade.expected", module)


def test_variant_keys_through_the_expected_module(monkeypatch: pytest.MonkeyPatch) -> None:
    _fake_expected(monkeypatch)
    keys = variant_keys(parse_file(SCENE_DRUM), {"s1": {"m_b": "10 kg"}}, SolveOptions())
    assert keys.for_student("s1")["alpha"].value == pytest.approx(-7.334)
    assert keys.errors == {"s2": "cannot read m_b"}
    assert keys.path == "vectorized"
    assert keys.for_student("s9")["alpha"].value == pytest.approx(-11.292, rel=1e-4)


def test_the_example_class() -> None:
    # each student's numbers are their own variant's (examples/grading/make_answers.py
    # computes them by the hand formulas); s009 used 2r: alpha = m_b g (2r)/(I_O + 4 m_b r^2)
    example = ROOT / "examples" / "grading"
    request = GradeRequest(
        example / "drum.dyn", example / "answers.csv", variants=example / "variants.csv"
    )
    run = grade(request)
    rows = {r.student: r for r in run.results}
    assert len(rows) == 30
    assert rows["s001"].score == 100.0
    assert rows["s004"].score == 100.0  # signs for words, T in lb
    assert rows["s007"].parts["T"]["feedback"].startswith("g left out")
    assert rows["s008"].parts["a"]["feedback"].startswith("g from the US system")
    assert rows["s009"].parts["a"]["feedback"].startswith("the diameter used for the radius r")
    assert rows["s010"].parts["alpha"]["feedback"].startswith("a value in degrees labelled as")
    assert rows["s014"].parts["T"]["verdict"] == "dimension"
    assert rows["s016"].parts["alpha"]["verdict"] == "unreadable"
    assert rows["s028"].parts["T"]["verdict"] == "correct"  # 0.8 % off, rtol 1 %
    assert rows["s029"].parts["T"]["verdict"] == "wrong"  # 1.8 % off


def test_grading_against_variants(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    _fake_expected(monkeypatch)
    spec = tmp_path / "one.dyn"
    spec.write_text("given:\n  w = 2 rad/s^2\nequations:\n  alpha = w\nfind: alpha [rad/s^2]\n")
    answers = tmp_path / "answers.csv"
    # s1's own alpha is 7.334 rad/s^2 cw, so 73.3 is x10; s2 has no key; s3 has no variant,
    # so is not graded (never against the base problem, whose 2 rad/s^2 it wrote)
    answers.write_text("student,alpha\ns1,73.3 rad/s^2 cw\ns3,2 rad/s^2\ns2,1 rad/s^2\n")
    variants = tmp_path / "variants.csv"
    variants.write_text("student,w\ns1,3 rad/s^2\ns2,4 rad/s^2\n")
    run = grade(GradeRequest(spec, answers, variants=variants))
    rows = {r.student: r for r in run.results}
    assert rows["s1"].parts["alpha"]["verdict"] == "wrong"
    assert "power-of-ten slip (x10)" in rows["s1"].parts["alpha"]["feedback"]
    assert rows["s2"].parts["alpha"]["verdict"] == "no key"
    assert rows["s3"].parts["alpha"]["verdict"] == "no variant"
    assert run.ungraded == ["s3", "s2"]
    assert run.path == "vectorized"
