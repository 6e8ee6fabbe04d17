"""Expected answers per student: the vectorized closed form, the per-variant fallback, and
their agreement on every bundled problem the closed form applies to.

Expected numbers are hand-derived in the comments, never taken from dynsolve's output.
"""

from __future__ import annotations

import functools
import math
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dynsolve.grade.expected import AGREE, expected_answers, per_variant
from dynsolve.grade.vary import decimal_text
from dynsolve.grade.vectorized import ClosedForm, NotClosedForm, build_closed_form, evaluate
from dynsolve.spec.ast import Spec
from dynsolve.spec.parser import parse_file, parse_spec
from dynsolve.system import SolveOptions

ROOT = Path(__file__).parent.parent
DRUM = ROOT / "examples" / "grading" / "drum.dyn"
WHEEL = Path(__file__).parent / "data" / "variants" / "wheel_couple.dyn"
OPTIONS = SolveOptions()


def drum_alpha(m_d: float, m_b: float, r: float) -> float:
    """Hibbeler 17.11 by hand: α = m_b g r/(I_O + m_b r²), I_O = m_d k_O², k_O = 0.25 m."""
    return m_b * 9.81 * r / (m_d * 0.25**2 + m_b * r**2)


def test_drum_students_get_their_own_hand_derived_answers() -> None:
    # s1: the textbook's numbers, α = 78.48/6.95 = 11.2921 rad/s², T = I_O α/r = 105.863 N,
    #     a = α r = 4.51683 m/s² (down)
    # s2: m_d = 50 kg, m_b = 18 kg, r = 0.36 m: I_O = 3.125 kg·m²,
    #     α = 18·9.81·0.36/(3.125 + 18·0.1296) = 63.5688/5.4578 = 11.6474 rad/s² (cw)
    spec = parse_file(DRUM)
    variants = {
        "s1": {"m_d": "60 kg", "m_b": "20 kg", "r": "0.4 m"},
        "s2": {"m_d": "50 kg", "m_b": "18 kg", "r": "0.36 m"},
    }
    result = expected_answers(spec, variants, OPTIONS)
    assert result.path == "vectorized"
    s1, s2 = result["s1"].answers, result["s2"].answers
    assert s1["alpha"].value == pytest.approx(7848 / 695, rel=1e-12)
    assert s1["T"].value == pytest.approx(14715 / 139, rel=1e-12)
    assert s1["a"].value == pytest.approx(15696 / 3475, rel=1e-12)
    assert (s1["a"].direction, s1["alpha"].direction) == ("down", "cw")
    assert s2["alpha"].value == pytest.approx(drum_alpha(50, 18, 0.36), rel=1e-12)
    assert s2["alpha"].value == pytest.approx(11.6474, rel=1e-5)
    assert (s1["T"].si_unit, s1["T"].unit) == ("m*kg*s^-2", "N")


def test_a_us_customary_variant_is_answered_in_si_base_units() -> None:
    # the drum in US units: 4.111 slug, 0.8202 ft, 1.312 ft, 1.370 slug, 32.19 ft/s² are
    # 59.996 kg, 0.25000 m, 0.39990 m, 19.994 kg, 9.8115 m/s² (1 slug = 14.5939 kg,
    # 1 ft = 0.3048 m); α from the hand formula with those SI values and g = 9.8115.
    spec = parse_file(DRUM)
    cells = {"m_d": "4.111 slug", "k_O": "0.8202 ft", "r": "1.312 ft", "m_b": "1.370 slug"}
    cells["g"] = "32.19 ft/s^2"
    result = expected_answers(spec, {"us": cells}, OPTIONS)
    m_d, k_O = 4.111 * 14.59390294, 0.8202 * 0.3048
    r, m_b, g = 1.312 * 0.3048, 1.370 * 14.59390294, 32.19 * 0.3048
    alpha = m_b * g * r / (m_d * k_O**2 + m_b * r**2)
    assert result["us"].answers["alpha"].value == pytest.approx(alpha, rel=1e-9)
    assert result["us"].answers["alpha"].value == pytest.approx(11.29, rel=1e-3)


def test_variants_that_slip_take_the_slow_path_with_the_slip_answer() -> None:
    # Rolling (M ≤ 22.07 N·m): α = M/1.35 cw, a_G = 0.3 α right (wheel_couple.dyn).
    # M = 25 N·m slips: F_C = μk m g = 39.24 N, a_G = 3.924 m/s² right,
    # α = (25 − 39.24·0.3)/0.45 = 29.3956 rad/s² cw.
    spec = parse_file(WHEEL)
    variants = {"roll": {"M": "20 N*m"}, "slip": {"M": "25 N*m"}, "base": {"M": "15 N*m"}}
    result = expected_answers(spec, variants, OPTIONS)
    assert result.path == "mixed: 2 vectorized, 1 per-variant"
    assert "no slip at C fails" in result.reason
    assert [result[s].path for s in variants] == ["vectorized", "per-variant", "vectorized"]
    roll, slip = result["roll"].answers, result["slip"].answers
    assert roll["alpha"].value == pytest.approx(20 / 1.35, rel=1e-12)
    assert roll["a"].value == pytest.approx(0.3 * 20 / 1.35, rel=1e-12)
    assert slip["alpha"].value == pytest.approx((25 - 39.24 * 0.3) / 0.45, rel=1e-12)
    assert slip["a"].value == pytest.approx(3.924, rel=1e-12)
    assert (slip["alpha"].direction, slip["a"].direction) == ("cw", "right")


def test_slip_check_is_vectorized_too() -> None:
    # the no-slip condition |F_C| ≤ μs N_C: M/0.45 ≤ 0.5·m·9.81; for m = 10 kg the edge is
    # M = 22.0725 N·m, so 22 rolls and 22.1 slips
    form = build_closed_form(parse_file(WHEEL), ("M",), OPTIONS)
    batch = evaluate(form, [{"M": "22 N*m"}, {"M": "22.1 N*m"}])
    assert batch.fast.tolist() == [True, False]
    assert batch.why_slow == {1: "no slip at C fails"}


def test_a_cell_that_cannot_be_read_fails_that_student_only() -> None:
    spec = parse_file(DRUM)
    variants = {"ok": {"m_b": "20 kg"}, "bad": {"m_b": "20 kgs"}, "dim": {"m_b": "2 m"}}
    result = expected_answers(spec, variants, OPTIONS)
    assert result["ok"].answers["alpha"].value == pytest.approx(7848 / 695, rel=1e-12)
    assert "unknown unit 'kgs'" in result["bad"].error and not result["bad"].answers
    assert result["dim"].error == "m_b = '2 m' is length, not mass"


def test_a_root_chosen_by_a_constraint_flips_to_the_slow_path() -> None:
    # x² = c with x ≥ 0: x = √c. With c < 0 no real root exists: the closed form gives NaN,
    # and the full solve says why.
    spec = parse_spec("given:\n  c = 4\nequations:\n  x^2 = c\n  x >= 0\nfind: x\n", "root.dyn")
    variants = {"a": {"c": "9"}, "b": {"c": "16"}, "n": {"c": "-1"}}
    result = expected_answers(spec, variants, OPTIONS)
    assert result.path == "mixed: 2 vectorized, 1 per-variant"
    assert [result[s].answers["x"].value for s in "ab"] == [3.0, 4.0]
    assert result["n"].path == "per-variant" and result["n"].error and not result["n"].answers


def test_problems_without_a_closed_form_say_why() -> None:
    spec = parse_file(ROOT / "problems" / "kinematics" / "projectile.dyn")
    with pytest.raises(NotClosedForm, match="solved per variant"):
        build_closed_form(spec, ("v_0",), OPTIONS)


# ---- the property: vectorized equals per-variant on every bundled problem it applies to

BUNDLED = sorted(
    p
    for p in (
        *(ROOT / "problems").rglob("*.dyn"),
        *(ROOT / "examples").rglob("*.dyn"),
        *WHEEL.parent.glob("*.dyn"),
    )
    if "kinematics" not in p.parts and "stages" not in p.parts and "symbolic" not in p.name
)


def _valued(spec: Spec) -> tuple[str, ...]:
    return tuple(g.name for g in spec.givens if g.quantity is not None and g.quantity.value != 0)


@functools.cache
def _closed_form(path: Path) -> ClosedForm | str:
    spec = parse_file(path)
    try:
        return build_closed_form(spec, _valued(spec), OPTIONS)
    except NotClosedForm as error:
        return str(error)


@pytest.mark.parametrize("path", BUNDLED, ids=lambda p: f"{p.parent.name}/{p.stem}")
@settings(max_examples=3, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_vectorized_equals_per_variant(path: Path, data: st.DataObject) -> None:
    form = _closed_form(path)
    if isinstance(form, str):
        pytest.skip(f"no closed form: {form}")
    spec = form.spec
    cells = {}
    for name in form.names:
        quantity = next(g.quantity for g in spec.givens if g.name == name)
        assert quantity is not None
        percent = data.draw(st.integers(90, 110), label=name)
        unit = quantity.unit.text if quantity.unit else ""
        cells[name] = f"{decimal_text(quantity.value * Fraction(percent, 100))} {unit}".strip()
    batch = evaluate(form, [cells])
    slow = per_variant(spec, "s", cells, OPTIONS)
    if not batch.fast[0]:
        return  # a flipped condition: the full solve answers, nothing to compare
    assert not slow.error, slow.error
    for name, expected in slow.answers.items():
        value = float(batch.values[name][0])
        assert math.isclose(value, expected.value, rel_tol=AGREE, abs_tol=1e-12), name
        assert batch.directions[name][0] == expected.direction, name


def test_tipping_and_a_stated_slide_are_vectorized() -> None:
    # Hibbeler's crate (tr_hib_crate.dyn): N_C = m g = 490.5 N, F_C = μk N_C = 98.1 N left;
    # ΣM_G = 0: N_C x − 0.3 P − 0.5 F_C = 0 → x = (0.3 P + 49.05)/490.5, within the 1-m base
    # (|x| ≤ 0.5 m) while P ≤ 654 N. a_G = (P − 98.1)/50.
    #   P = 600 N: x = 0.46697 m, a_G = 10.038 m/s²;  P = 650 N: x = 0.49755 m;
    #   P = 660 N: x = 0.50367 m > 0.5 m, the crate tips: solved per variant, and that solve
    #   fails its tipping check, so the student's expected answer is refused with the reason.
    spec = parse_file(ROOT / "problems" / "seed" / "tr_hib_crate.dyn")
    variants = {"a": {"P": "600 N"}, "b": {"P": "650 N"}, "c": {"P": "660 N"}}
    result = expected_answers(spec, variants, OPTIONS)
    assert result.path == "mixed: 2 vectorized, 1 per-variant"
    assert result["c"].why == "no tipping on base C fails"
    assert "no tipping on base C" in result["c"].error
    assert result["a"].answers["x"].value == pytest.approx((180 + 49.05) / 490.5, rel=1e-12)
    assert result["a"].answers["a_G"].value == pytest.approx((600 - 98.1) / 50, rel=1e-12)
    assert result["b"].answers["x"].value == pytest.approx((195 + 49.05) / 490.5, rel=1e-12)


def test_a_base_problem_that_slips_is_vectorized_through_its_re_solve() -> None:
    # wheel_couple_slips.dyn (m = 10 kg, r = 0.3 m, I_G = 0.45 kg·m², μs = 0.1, μk = 0.08):
    # the no-slip trial needs F_C = M/0.45 ≤ μs m g = 9.81 N, i.e. M ≤ 4.41 N·m.
    #   M = 40 N·m (base) and 50 N·m slip: F_C = μk m g = 7.848 N right, a_G = 0.7848 m/s²
    #     right, α = (M − 7.848·0.3)/0.45 cw: 83.655 and 105.88 rad/s².
    #   M = 1 N·m rolls (the trial holds): α = 1/1.35 = 0.74074 rad/s² cw, a_G = 0.22222
    #     m/s² right; that student is solved per variant.
    spec = parse_file(ROOT / "problems" / "scenes" / "wheel_couple_slips.dyn")
    variants = {"base": {"M": "40 N*m"}, "more": {"M": "50 N*m"}, "rolls": {"M": "1 N*m"}}
    result = expected_answers(spec, variants, OPTIONS)
    assert result.path == "mixed: 2 vectorized, 1 per-variant"
    assert result["rolls"].why == "no slip at C holds"
    for student, M in (("base", 40), ("more", 50)):
        answers = result[student].answers
        assert answers["alpha"].value == pytest.approx((M - 7.848 * 0.3) / 0.45, rel=1e-12)
        assert answers["a"].value == pytest.approx(0.7848, rel=1e-12)
        assert (answers["alpha"].direction, answers["a"].direction) == ("cw", "right")
    rolls = result["rolls"].answers
    assert rolls["alpha"].value == pytest.approx(1 / 1.35, rel=1e-12)
    assert rolls["a"].value == pytest.approx(0.3 / 1.35, rel=1e-12)
