"""Kinetic friction never pushes: a slide from rest that the push cannot start (issue 25, 5).

A crate at rest, pushed with less than μk N, its contact written ``slides right`` with only
μk given and asked for its speed after 3 s, was answered moving backwards (v_2x < 0) by
impulse and momentum, and work and energy "confirmed" it with friction doing positive work,
every check green. Kinetic friction opposes the slip, so from rest it can only slow a
slide, never start one the other way: such a slide is a failed assumption, re-solved with
no slip (the crate stays at rest), in every mode. Every expected number is derived by hand
in the comment above it.
"""

import pytest

from dynsolve.errors import DynsolveError
from dynsolve.pipeline import solve_text
from dynsolve.principles.impulse_momentum import energy_check
from dynsolve.system import SolveOptions

MODES = ["exact", "numeric", "auto"]


def _crate(
    push: str, travel: str, mu_s: bool = False, find: str = "v_2 = speed(crate) [m/s]"
) -> str:
    """The crate as a student writes it: a particle on a rough floor, stated to slide right."""
    return f"""given:
  m = 50 kg
  P = {push}
  mu_k = 0.2{chr(10) + "  mu_s = 0.3" if mu_s else ""}
  dt = 3 s
  d = 3 m
scene:
  body crate: particle, mass m, at (0, 0)
  contact crate at G: normal up{", mu_s mu_s" if mu_s else ""}, mu_k mu_k, slides right
  force P on crate at G: right
  gravity
  travel crate: {travel}
find: {find}
"""


def _values(text: str, mode: str) -> tuple[dict[str, float], object]:
    solution = solve_text(text, options=SolveOptions(mode=mode))
    return {a.name: float(a.value) for a in solution.answers if a.value is not None}, solution


@pytest.mark.parametrize("mode", MODES)
def test_a_push_weaker_than_kinetic_friction_leaves_the_crate_at_rest(mode: str) -> None:
    # N = m g = 490.5 N, μk N = 98.1 N > P = 90 N. Sliding right would need
    # m v_2 = (P − μk N) Δt = (90 − 98.1)·3 = −24.3 N·s, v_2 = −0.486 m/s: backwards, with
    # friction doing +71.5 J. From rest that is impossible; with no slip F = P = 90 N
    # ≤ μk N ≤ μs N, so the crate stays at rest: v_2 = 0, F_G = 90 N to the left.
    values, solution = _values(
        _crate("90 N", "for dt", find="v_2 = speed(crate) [m/s], F_G [N]"), mode
    )
    assert values["v_2"] == pytest.approx(0.0, abs=1e-12)
    assert abs(values["F_G"]) == pytest.approx(90.0, rel=1e-9)
    slide = next(a for a in solution.assumptions if a.name == "sliding at G")
    assert not slide.holds and "re-solved with no slip" in slide.detail
    assert next(a for a in solution.assumptions if a.name == "no slip at G").holds
    energy = next(c for c in solution.checks if c.name.startswith("second method: work"))
    assert "U_F_G = 0" in energy.detail  # no work done by friction: nothing moves


@pytest.mark.parametrize("mode", MODES)
def test_with_mu_s_a_slide_from_rest_starts_only_past_static_friction(mode: str) -> None:
    # P = 90 N ≤ μs N = 0.3·490.5 = 147.15 N: static friction holds it, v_2 = 0.
    values, solution = _values(_crate("90 N", "for dt", mu_s=True), mode)
    assert values["v_2"] == pytest.approx(0.0, abs=1e-12)
    assert next(a for a in solution.assumptions if a.name == "no slip at G").holds
    # P = 200 N > μs N: it slides, m v_2 = (P − μk N) Δt = (200 − 98.1)·3 = 305.7 N·s,
    # v_2 = 6.114 m/s.
    values, _ = _values(_crate("200 N", "for dt", mu_s=True), mode)
    assert values["v_2"] == pytest.approx((200 - 98.1) * 3 / 50, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_a_push_stronger_than_kinetic_friction_slides_the_stated_way(mode: str) -> None:
    # P = 200 N > μk N = 98.1 N: v_2 = (200 − 98.1)·3/50 = 6.114 m/s, friction's work
    # −μk N s with s = v_2 Δt/2 = 9.171 m: −899.7 J (negative).
    values, solution = _values(_crate("200 N", "for dt"), mode)
    assert values["v_2"] == pytest.approx(6.114, rel=1e-9)
    slide = next(a for a in solution.assumptions if a.name == "sliding at G")
    assert slide.holds
    assert solution.passed


@pytest.mark.parametrize("mode", MODES)
def test_work_and_energy_refuses_a_weak_push_from_rest(mode: str) -> None:
    # by work and energy over d = 3 m: the crate never starts (F = 90 N ≤ μk N), so it
    # never reaches state 2: refused, never a speed with friction doing positive work.
    _, solution = _values(_crate("90 N", "by d, right"), mode)
    assert not solution.passed
    held = next(a for a in solution.assumptions if a.name == "crate starts toward state 2")
    assert not held.holds


def test_kinetic_friction_doing_positive_work_fails_the_energy_check() -> None:
    # the backwards answer's own energy balance: T1 + U_P + U_F = 0 − 65.61 + 71.51 = 5.90 = T2
    # agrees, but U_F > 0 is friction pushing: the check fails and says so.
    check = energy_check(
        "", (0, {"P": -65.61, "F_G": 71.51}, 5.90), {}, 1e-2, "SI", kinetic={"F_G"}
    )
    assert check is not None and not check.passed
    assert "kinetic friction does positive work" in check.detail


@pytest.mark.parametrize("mode", MODES)
def test_newton_at_the_instant_keeps_a_weakly_pushed_crate_at_rest(mode: str) -> None:
    # at the instant: sliding right would need a_G = (P − μk N)/m = (90 − 98.1)/50
    # = −0.162 m/s² (against the slide); re-solved with no slip: a_G = 0, F = 90 N left.
    text = _crate("90 N", "for dt", find="a = a_G(crate) [m/s^2], F_G [N]")
    text = text.replace("  travel crate: for dt\n", "")
    values, solution = _values(text, mode)
    assert values["a"] == pytest.approx(0.0, abs=1e-12)
    assert abs(values["F_G"]) == pytest.approx(90.0, rel=1e-9)
    slide = next(a for a in solution.assumptions if a.name == "sliding at G")
    assert not slide.holds and "re-solved with no slip" in slide.detail


def test_a_chain_refuses_a_slide_from_rest() -> None:
    # two intervals from rest: a chain follows only contacts sliding at an interval's start,
    # so the weak push is refused (never answered backwards).
    text = _crate("90 N", "for dt", find="v_3 = speed(crate, 3) [m/s]")
    text = text.replace(
        "  travel crate: for dt\n", "  travel crate: for dt\n  travel crate: for dt\n"
    )
    with pytest.raises(DynsolveError, match="does not slide at G at the start"):
        solve_text(text)


@pytest.mark.parametrize("mode", MODES)
def test_a_stated_slide_that_reverses_inside_the_interval_fails(mode: str) -> None:
    # given 1 m/s right, ``slides right``, no push, for 3 s: friction decelerates it at
    # μk g = 1.962 m/s², so it stops after 1/1.962 = 0.51 s and stays; one interval would
    # give v_2 = 1 − 1.962·3 = −4.886 m/s (backwards, friction doing +572 J). Was exit 0.
    text = """given:
  m = 50 kg
  mu_k = 0.2
  v_1 = 1 m/s
  dt = 3 s
scene:
  body crate: particle, mass m, at (0, 0)
  contact crate at G: normal up, mu_k mu_k, slides right
  velocity crate: v_1, right
  gravity
  travel crate: for dt
find: v_2 = speed(crate) [m/s]
"""
    solution = solve_text(text, options=SolveOptions(mode=mode))
    assert not solution.passed
    kept = next(a for a in solution.assumptions if a.name == "sliding at G through the interval")
    assert not kept.holds and "stops sliding before the interval ends" in kept.detail
    energy = next(c for c in solution.checks if c.name.startswith("second method: work"))
    assert not energy.passed and "kinetic friction does positive work" in energy.detail
