"""Scene answers are never silently wrong (issue 8, item 7): every assumption is checked
whatever the find list asks, every assumed sense is checked against the answer, round bodies
keep their centre's height, and generated unknown names are unique and drawn as used.

Each expected number comes from the hand derivation in the comment beside it.
"""

from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

SCENES = Path(__file__).resolve().parent.parent / "problems" / "scenes"
G = 9.81


def write(tmp_path: Path, text: str, name: str = "scene.dyn") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def answer(solution, name: str) -> float:
    return next(a.value for a in solution.answers if a.name == name)


def assumption(solution, name: str):
    return next(a for a in solution.assumptions if a.name == name)


# ---- 1. every assumption is checked, whatever the find list asks
WHEEL = """\
problem: Wheel driven by a couple on a rough floor
units: SI
given:
  m = 10 kg
  r = 0.3 m
  M = {M} N*m
  mu_s = 0.1
  mu_k = 0.08
scene:
  point C: (0, 0)
  body wheel: mass m, disk r, at (0, r)
  contact wheel at C: normal up, mu_s mu_s, mu_k mu_k
  couple M on wheel: cw
  gravity
find: {find}
"""


@pytest.mark.parametrize("find", ["a = a_G(wheel), alpha = alpha(wheel)", "alpha = alpha(wheel)"])
def test_no_slip_is_checked_when_only_the_motion_is_asked(tmp_path, find):
    # Solid disk m = 10 kg, r = 0.3 m: I_G = m r²/2 = 0.45 kg·m²; N_C = m g = 98.1 N.
    # No-slip trial: F = m a, M − F r = I_G α, a = α r → α = M/(I_G + m r²) = 40/1.35
    #   = 29.63 rad/s², F = m α r = 88.9 N > μs N = 9.81 N: it slips.
    # Slipping: the rim point slides left, F = μk N = 7.848 N to the right;
    #   a = F/m = 0.7848 m/s²; α = (M − F r)/I_G = (40 − 2.3544)/0.45 = 83.66 rad/s² cw.
    # (Regression: asked for a_G and α only, N was not solved, so the check never ran and the
    # rolling answer 29.6 rad/s² was reported with every check green.)
    solution = solve_file(write(tmp_path, WHEEL.format(M=40, find=find)))
    trial = assumption(solution, "no slip at C")
    assert not trial.holds and "re-solved" in trial.detail
    assert answer(solution, "alpha") == pytest.approx(37.6456 / 0.45, rel=1e-6)
    if "a_G" in find:
        assert answer(solution, "a") == pytest.approx(0.08 * G, rel=1e-9)
    assert solution.passed


def test_a_small_couple_rolls_and_says_so(tmp_path):
    # M = 2 N·m: α = M/(I_G + m r²) = 2/1.35 = 1.4815 rad/s² cw, a = α r = 0.4444 m/s²,
    # F = m a = 4.444 N ≤ μs N = 9.81 N: it rolls, and the check ran although N was not asked.
    solution = solve_file(write(tmp_path, WHEEL.format(M=2, find="a = a_G(wheel)")))
    assert answer(solution, "a") == pytest.approx(0.3 * 2 / 1.35, rel=1e-9)
    assert assumption(solution, "no slip at C").holds
    assert solution.passed


def test_tipping_is_checked_when_only_a_G_is_asked(tmp_path):
    # Crate 1 m × 1 m, m = 50 kg, sliding right (v = 1 m/s, μk = 0.2), P = 600 N pushed right
    # at the top edge: N = m g = 490.5 N; ΣM_G = 0 with F = μk N = 98.1 N to the left at the
    # base: N x − P (h/2) − F (h/2) = 0 → x = (300 + 49.05)/490.5 = 0.712 m > b/2 = 0.5 m:
    # it tips, although only a_G is asked (x_C is needed by the check, so it is solved).
    text = """\
problem: Crate pushed at the top
units: SI
given:
  m = 50 kg
  b = 1 m
  h = 1 m
  P = 600 N
  mu_k = 0.2
  v_1 = 1 m/s
scene:
  body crate: mass m, block b by h, at (0, 0)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right
  point D on crate: (-b/2, h/2)
  force P on crate at D: right
  velocity crate: v_1, right
  gravity
find: a = a_G(crate)
"""
    solution = solve_file(write(tmp_path, text))
    tip = assumption(solution, "no tipping on base C")
    assert not tip.holds and "x = 0.7116" in tip.detail
    assert not solution.passed


def test_a_slack_cord_is_caught_when_its_tension_is_not_asked(tmp_path):
    # Block A (10 kg) on a smooth floor, pushed LEFT by P = 50 N, tied by a cord to block B
    # (5 kg) on its left, the cord leaving A to the left: taut, both would move together with
    # a = P/15 = 3.33 m/s² to the left, and B needs T = −m_B a = −16.7 N along the cord
    # (a push): the cord goes slack. Asked only for B's acceleration.
    text = """\
problem: Pushed toward a cord
units: SI
given:
  m_A = 10 kg
  m_B = 5 kg
  d = 1 m
  P = 50 N
scene:
  body A: particle, mass m_A, at (0, 0)
  body B: particle, mass m_B, at (-d, 0)
  contact A at G: normal up, smooth
  contact B at G: normal up, smooth
  cord T: A at G to B, left
  force P on A at G: left
  gravity
find: a = a_G(B)
"""
    solution = solve_file(write(tmp_path, text))
    taut = assumption(solution, "cord T taut")
    assert not taut.holds and "slack" in taut.detail
    # issue 8 part 4: the cord is tension-only, so the scene is re-solved with it slack:
    # nothing pulls B horizontally (a_B = 0) and A alone takes P (a_A = 50/10 = 5 m/s²),
    # closing on B, which keeps the cord slack.
    slack = assumption(solution, "cord T slack")
    assert slack.holds
    assert solution.answers[0].value == pytest.approx(0.0, abs=1e-12)
    assert solution.passed


def test_the_bundled_wheel_reports_the_slipping_answer():
    solution = solve_file(SCENES / "wheel_couple_slips.dyn")
    assert solution.passed and all(k.passed for k in solution.key)


# ---- 2. a round body keeps its centre's height
def test_a_spinning_disk_sliding_keeps_its_centre_height():
    # Disk m = 10 kg, r = 0.3 m, v_G = 5 m/s right, ω = 10 rad/s ccw: the rim point C moves
    # at 5 + ω r = 8 m/s right, so F = μk N to the left. Contact kept: a_Gy = 0 → N = m g
    # = 98.1 N; a_G = μk g = 1.962 m/s² left; α = −μk N r/I_G = −5.886/0.45 = −13.08 rad/s².
    # (Regression: a_Gy + r ω² = 0 gave a_Gy = −30 m/s² and N = −202 N.)
    solution = solve_file(SCENES / "disk_spinning_slides.dyn")
    assert answer(solution, "N_C") == pytest.approx(98.1, rel=1e-9)
    assert answer(solution, "a") == pytest.approx(0.2 * G, rel=1e-9)
    assert answer(solution, "alpha") == pytest.approx(0.2 * 98.1 * 0.3 / 0.45, rel=1e-9)
    kept = next(e for e in solution.equations if e.note.startswith("contact at C kept"))
    assert kept.text == "a_Gy = 0" and "centre keeps its height" in kept.note
    assert solution.passed


# ---- 3. unknown names unique per body and contact, drawn as the equations use them
TWO_BLOCKS = """\
problem: Two blocks joined by a cord, pulled across a rough floor
units: SI
given:
  m_A = 10 kg
  m_B = 5 kg
  d = 1 m
  P = 100 N
  mu_k = 0.2
  v_1 = 2 m/s
scene:
  body A: particle, mass m_A, at (0, 0)
  body B: particle, mass m_B, at (-d, 0)
  contact A at G: normal up, mu_k mu_k, slides right
  contact B at G: normal up, mu_k mu_k, slides right
  cord T: A at G to B, left
  force P on A at G: right
  velocity A: v_1, right
  velocity B: v_1, right
  gravity
find: {find}
"""


def test_two_contacts_at_G_get_names_of_their_own(tmp_path):
    # Both slide right: a = (P − μk g (m_A + m_B))/(m_A + m_B) = (100 − 29.43)/15 = 4.705 m/s²;
    # T = m_B (a + μk g) = 5 × 6.667 = 33.33 N; N_G_A = m_A g = 98.1 N, N_G_B = m_B g = 49.05 N,
    # F_G_B = μk N_G_B = 9.81 N. (Regression: both contacts got the one unknown N_G.)
    find = "a = a_G(B), T, N_G_A, N_G_B, F_G_B"
    solution = solve_file(write(tmp_path, TWO_BLOCKS.format(find=find)))
    assert answer(solution, "a") == pytest.approx((100 - 0.2 * G * 15) / 15, rel=1e-9)
    assert answer(solution, "T") == pytest.approx(100 / 3, rel=1e-9)
    assert answer(solution, "N_G_A") == pytest.approx(98.1, rel=1e-9)
    assert answer(solution, "N_G_B") == pytest.approx(49.05, rel=1e-9)
    assert answer(solution, "F_G_B") == pytest.approx(9.81, rel=1e-9)
    assert solution.passed
    rows = {b.body: {r.name: r for r in b.forces} for b in solution.free_body}
    assert {"N_G_A", "F_G_A"} <= set(rows["A"]) and {"N_G_B", "F_G_B"} <= set(rows["B"])
    assert rows["A"]["N_G_A"].point == "G"  # the point keeps its own name on the diagram
    used = " ".join(e.text for e in solution.equations)
    assert "N_G_A" in used and "N_G_B" in used


def test_a_shared_contact_name_is_refused_with_the_new_names(tmp_path):
    with pytest.raises(SpecError, match="N_G"):
        solve_file(write(tmp_path, TWO_BLOCKS.format(find="N_G")))


def resultant(body) -> tuple[float, float]:
    """ΣF of a free-body table: each row's value along its drawn arrow."""
    total = [0.0, 0.0]
    for row in body.forces:
        if row.kind == "couple":
            continue
        magnitude = float(row.value.split()[0])
        total[0] += magnitude * row.dx
        total[1] += magnitude * row.dy
    return total[0], total[1]


@pytest.mark.parametrize("P", [90, 200])
def test_the_free_body_table_sums_to_m_a(tmp_path, P):
    # The table's arrows and values, summed, must give m a_G as the equations do: friction
    # drawn the way the equations apply it (it was once listed along the slide).
    # P = 90 N: at rest, F = 90 N to the left (ΣF = 0). P = 200 N > μs N = 147.15 N: it slides
    # right, F = μk N = 98.1 N to the left, m a = 200 − 98.1 = 101.9 N to the right.
    text = (SCENES / "crate_push_too_weak.dyn").read_text().replace("P    = 90 N", f"P = {P} N")
    text = text[: text.index("answers:")]
    solution = solve_file(write(tmp_path, text))
    (crate,) = solution.free_body
    friction = next(r for r in crate.forces if r.kind.startswith("friction"))
    assert friction.direction == "left"
    x, y = resultant(crate)
    expected = 0.0 if P == 90 else 200 - 0.2 * 490.5
    assert x == pytest.approx(expected, abs=0.2) and y == pytest.approx(0.0, abs=0.2)
    assert answer(solution, "a") * 50 == pytest.approx(expected, abs=1e-9)


# ---- 4. every assumed sense is checked against the answer
def test_a_push_too_weak_to_slide_leaves_the_crate_at_rest():
    # N = 490.5 N, μk N = 98.1 N, μs N = 147.15 N; P = 90 N. Sliding right would need
    # a = (90 − 98.1)/50 = −0.162 m/s² (against the slide): re-solved without slip,
    # a = 0, F = P = 90 N ≤ μs N. (Regression: a = 0.162 m/s² left was reported, sliding.)
    solution = solve_file(SCENES / "crate_push_too_weak.dyn")
    slide = assumption(solution, "sliding at C")
    assert not slide.holds and "re-solved with no slip" in slide.detail
    assert assumption(solution, "no slip at C").holds
    assert answer(solution, "a") == 0
    assert answer(solution, "F_C") == pytest.approx(90.0, rel=1e-9)
    assert solution.passed


CRATE = """\
problem: Crate pushed from rest
units: SI
given:
  m = 50 kg
  b = 1 m
  h = 1 m
  P = {P} N
  mu_k = 0.2
  {extra}
scene:
  body crate: mass m, block b by h, at (0, 0)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, {props}
  force P on crate at G: right
  {velocity}
  gravity
find: a = a_G(crate), F_C
"""


def test_a_push_between_kinetic_and_static_friction_does_not_start_a_slide(tmp_path):
    # P = 120 N: μk N = 98.1 < P < μs N = 147.15 N. From rest the crate does not slide
    # (a = 0, F = 120 N) although 'slides right' was written and (P − μk N)/m > 0.
    text = CRATE.format(P=120, extra="mu_s = 0.3", props="mu_s mu_s, slides right", velocity="")
    solution = solve_file(write(tmp_path, text))
    assert answer(solution, "a") == 0
    assert answer(solution, "F_C") == pytest.approx(120.0, rel=1e-9)
    assert solution.passed


def test_a_push_beyond_static_friction_slides(tmp_path):
    # P = 200 N > μs N = 147.15 N: it slides right, a = (200 − 98.1)/50 = 2.038 m/s².
    text = CRATE.format(P=200, extra="mu_s = 0.3", props="mu_s mu_s, slides right", velocity="")
    solution = solve_file(write(tmp_path, text))
    assert answer(solution, "a") == pytest.approx((200 - 98.1) / 50, rel=1e-9)
    assert assumption(solution, "slip at C").holds
    assert solution.passed


def test_a_stated_slide_against_the_velocity_fails_loudly(tmp_path):
    # Moving LEFT at 2 m/s but written 'slides right': friction would be applied the wrong way.
    text = CRATE.format(
        P=120, extra="v_1 = 2 m/s", props="slides right", velocity="velocity crate: v_1, left"
    )
    solution = solve_file(write(tmp_path, text))
    assert not assumption(solution, "sliding at C").holds
    assert not solution.passed


def test_a_stated_slide_the_wrong_way_fails_loudly(tmp_path):
    # At rest, P = 200 N to the right > μs N: it slips right, not left as written.
    text = CRATE.format(P=200, extra="mu_s = 0.3", props="mu_s mu_s, slides left", velocity="")
    solution = solve_file(write(tmp_path, text))
    assert not solution.passed
    failed = [a for a in solution.assumptions if not a.holds and "re-solved" not in a.detail]
    assert failed, solution.assumptions


def test_a_sliding_body_may_slow_down(tmp_path):
    # Moving right at 2 m/s, P = 50 N < μk N = 98.1 N: it still slides right, decelerating:
    # a = (50 − 98.1)/50 = −0.962 m/s² (to the left) at the instant.
    text = CRATE.format(
        P=50, extra="v_1 = 2 m/s", props="slides right", velocity="velocity crate: v_1, right"
    )
    solution = solve_file(write(tmp_path, text))
    assert answer(solution, "a") == pytest.approx(48.1 / 50, rel=1e-9)
    assert assumption(solution, "sliding at C").holds
    assert solution.passed


# ---- 5. work and energy: the travel's sense and friction's sense
TRAVEL = """\
problem: Block pushed along a rough floor
units: SI
given:
  m = 50 kg
  P = {P} N
  mu_k = 0.2
  d = 2 m
  v_1 = 3 m/s
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, mu_k mu_k
  force P on block at G: right
  {velocity}
  gravity
  travel block: by d, right
find: v = speed(block)
"""


def test_friction_work_needs_the_body_moving_toward_state_2(tmp_path):
    # Moving LEFT at state 1 but travelling right: it would first slide left (friction to the
    # right), stop and come back, so U_F = −μk N s with one sense is wrong: refused.
    text = TRAVEL.format(P=150, velocity="velocity block: v_1, left")
    with pytest.raises(SpecError, match="change sense"):
        solve_file(write(tmp_path, text))


def test_a_travel_that_cannot_be_reached_fails(tmp_path):
    # From rest, P = 50 N < μk N = 98.1 N: T1 + ΣU = (50 − 98.1) × 2 = −96.2 J < 0: it never
    # gets to state 2 (and at state 1 it does not even start: |F| = 50 ≤ μk N ≤ μs N).
    solution = solve_file(write(tmp_path, TRAVEL.format(P=50, velocity="")))
    assert not solution.passed
    assert assumption(solution, "no slip at G").holds


def test_a_travel_with_enough_push_gets_there(tmp_path):
    # From rest, P = 150 N: T2 = (150 − 98.1) × 2 = 103.8 J = ½ 50 v² → v = 2.038 m/s.
    solution = solve_file(write(tmp_path, TRAVEL.format(P=150, velocity="")))
    assert answer(solution, "v") == pytest.approx((2 * 103.8 / 50) ** 0.5, rel=1e-9)
    assert solution.passed


def test_a_block_held_by_static_friction_does_not_travel(tmp_path):
    # From rest, P = 120 N: μk N = 98.1 N < P ≤ μs N = 147.15 N. Energy alone would give
    # T2 = (120 − 98.1) × 2 = 43.8 J (v = 1.32 m/s), but static friction holds the block at
    # state 1 (F = 120 N ≤ μs N): it never starts. (Regression: v = 1.32 m/s, all green.)
    text = TRAVEL.format(P=120, velocity="").replace(
        "contact block at G: normal up, mu_k mu_k",
        "contact block at G: normal up, mu_s 0.3, mu_k mu_k",
    )
    solution = solve_file(write(tmp_path, text))
    starts = assumption(solution, "block starts toward state 2")
    assert not starts.holds and "never reaches state 2" in starts.detail
    assert not solution.passed
