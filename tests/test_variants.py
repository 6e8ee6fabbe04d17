"""Per-student variants: the vary: section, drawing from the seed, redraws, the variants file
and the CLI (``dynsolve variants``, ``dynsolve solve --variant``).

Expected numbers are hand-derived in the comments, never taken from dynsolve's output.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import ExitCode, app
from dynsolve.errors import SpecError, UnitError
from dynsolve.grade.generate import make_variants, signature, us_twin
from dynsolve.grade.substitute import VariantError, with_variant
from dynsolve.grade.variants import CsvError, read_roster, read_variants
from dynsolve.grade.vary import cells_in_range, draw, round_within, vary_plan
from dynsolve.pipeline import solve_spec
from dynsolve.spec.parser import parse_file, parse_spec

DATA = Path(__file__).parent / "data" / "variants"
WHEEL = DATA / "wheel_couple.dyn"
DRUM = Path(__file__).parent.parent / "examples" / "grading" / "drum.dyn"

BASE = """\
given:
  m = 50 kg
  k = 200 N/m
  L: length
equations:
  F = m*g + k*L
find: F
vary:
"""


def spec_with(*lines: str) -> object:
    return parse_spec(BASE + "".join(f"  {line}\n" for line in lines), "v.dyn")


# ---- the vary: section


def test_range_values_include_both_ends() -> None:
    (variation,) = vary_plan(spec_with("m = 40..60 kg step 5"))
    assert variation.values() == ("40", "45", "50", "55", "60")


def test_range_that_is_not_a_multiple_of_the_step_stops_below_the_top() -> None:
    # 0, 0.3, 0.6, 0.9: 1.2 would pass the top of 1
    (variation,) = vary_plan(spec_with("m = 0..1 kg step 0.3"))
    assert variation.values() == ("0", "0.3", "0.6", "0.9")


def test_percent_spread_is_relative_to_the_given() -> None:
    # 200 N/m ± 10 % → 180 … 220 N/m, in the given's own unit
    (variation,) = vary_plan(spec_with("k = ±10% sigfig 3"))
    assert (variation.low, variation.high, variation.unit) == (180, 220, "N/m")
    (plain,) = vary_plan(spec_with("k = +-10%"))  # ASCII form, sigfig 3 by default
    assert plain.sigfig == 3


@pytest.mark.parametrize(
    ("line", "column", "words"),
    [
        ("q = 1..2 kg step 1", 3, "'q' cannot vary: it is not a given"),
        ("L = 1..2 m step 1", 3, "'L' cannot vary: it is a symbolic given"),
        ("m = 60..40 kg step 5", 7, "runs backwards"),
        ("m = 40..60 kg step 0", 22, "step of a range must be positive"),
        ("m = 0..1e9 kg step 1", 22, "the limit is 100000"),
        ("k = ±0% sigfig 3", 8, "out of range"),
        ("k = ±100%", 8, "out of range"),
        ("k = ±10% sigfig 0", 19, "sigfig 0 is out of range"),
        ("m = 40-60 kg", 7, "cannot read the variation of 'm'"),
        ("m = 40..60 kg", 7, "cannot read the variation"),
    ],
)
def test_bad_vary_lines_are_positioned_errors(line: str, column: int, words: str) -> None:
    with pytest.raises(SpecError) as caught:
        spec_with(line)
    assert caught.value.position is not None
    assert (caught.value.position.line, caught.value.position.column) == (9, column)
    assert words in caught.value.message


def test_a_given_varies_once() -> None:
    with pytest.raises(SpecError, match="'m' varies twice"):
        spec_with("m = 40..60 kg step 5", "m = ±10%")


def test_range_in_a_unit_of_another_dimension_is_a_positioned_error() -> None:
    spec = spec_with("m = 40..60 m step 5")
    with pytest.raises(UnitError) as caught:
        vary_plan(spec)
    assert caught.value.position is not None
    assert (caught.value.position.line, caught.value.position.column) == (9, 14)
    assert "'m' is mass" in caught.value.message


def test_a_range_in_another_unit_of_the_same_dimension_is_accepted() -> None:
    (variation,) = vary_plan(spec_with("m = 40000..60000 g step 5000"))
    assert variation.unit == "g"


# ---- drawing


def test_rounding_stays_inside_the_spread() -> None:
    # 109.99 rounds to 110 (3 figures), the top itself; 0.3333… to 2 figures is 0.33, below
    # the bottom 1/3, so it is rounded inward to 0.34
    assert round_within(Fraction(10999, 100), 3, Fraction(90), Fraction(110)) == "110"
    assert round_within(Fraction(1, 3), 2, Fraction(1, 3), Fraction(1, 2)) == "0.34"
    assert round_within(Fraction(-1051, 10), 3, Fraction(-110), Fraction(-90)) == "-105"


def test_every_percent_draw_is_in_range_with_at_most_n_figures() -> None:
    plan = vary_plan(spec_with("k = ±10% sigfig 2"))
    seen = set()
    for i in range(500):
        cells = draw(plan, seed=5, student=f"s{i}")
        number = cells["k"].removesuffix(" N/m")
        assert cells_in_range(plan, cells)
        assert len(number.replace(".", "").strip("0")) <= 2  # 180 … 220 to 2 figures
        seen.add(number)
    assert seen == {"180", "190", "200", "210", "220"}  # every 2-figure value, ends included


def test_every_range_value_is_drawn_and_none_outside() -> None:
    plan = vary_plan(spec_with("m = 40..60 kg step 5"))
    drawn = {draw(plan, seed=9, student=f"s{i}")["m"] for i in range(300)}
    assert drawn == {"40 kg", "45 kg", "50 kg", "55 kg", "60 kg"}


def test_draws_are_reproducible_and_depend_on_the_seed_and_the_id() -> None:
    plan = vary_plan(spec_with("m = 40..60 kg step 0.5", "k = ±10% sigfig 4"))
    first = [draw(plan, 11, f"s{i}") for i in range(20)]
    assert first == [draw(plan, 11, f"s{i}") for i in range(20)]
    assert first != [draw(plan, 12, f"s{i}") for i in range(20)]
    assert len({tuple(c.values()) for c in first}) > 15  # students differ


# ---- generation: solved, checked, redrawn


def test_variants_are_reproducible_whatever_the_roster_order() -> None:
    spec = parse_file(DRUM)
    forward = make_variants(spec, ["a", "b", "c"], seed=4)
    backward = make_variants(spec, ["c", "b", "a"], seed=4)
    assert {r.student: r.cells for r in forward} == {r.student: r.cells for r in backward}
    assert make_variants(spec, ["a", "b", "c"], seed=4) == forward


def test_every_variant_solves_with_the_base_problems_checks() -> None:
    spec = parse_file(DRUM)
    plan = vary_plan(spec)
    for row in make_variants(spec, [f"s{i}" for i in range(8)], seed=1):
        assert cells_in_range(plan, row.cells)
        solution = solve_spec(with_variant(spec, row.cells, row.student))
        assert not any(c.failed for c in solution.checks), row


def test_a_variant_that_slips_is_redrawn() -> None:
    # Rolling needs F_C = M/(1.5 r) ≤ μs m g, i.e. M ≤ 1.5·0.3·0.5·m·9.81 = 2.207 m
    # (N·m for m in kg): M = 10, 15, 20 roll for every m in 9 … 11 kg; 25 and 30 slip.
    spec = parse_file(WHEEL)
    plan = vary_plan(spec)
    students = [f"s{i}" for i in range(40)]
    slips_first = [s for s in students if draw(plan, 3, s)["M"] in ("25 N*m", "30 N*m")]
    assert slips_first  # some first draws slip, so redraws happened
    rows = make_variants(spec, students, seed=3)
    assert {r.cells["M"] for r in rows} <= {"10 N*m", "15 N*m", "20 N*m"}
    redrawn = {r.student: r.cells for r in rows if r.student in slips_first}
    assert all(redrawn[s] != draw(plan, 3, s) for s in slips_first)


def test_no_valid_variant_is_an_error_naming_the_student() -> None:
    text = WHEEL.read_text().replace("M = 10..30 N*m step 5", "M = 25..30 N*m step 5")
    spec = parse_spec(text, "wheel.dyn")
    with pytest.raises(SpecError) as caught:
        make_variants(spec, ["alice"], seed=1)
    assert "student alice: no valid variant in 20 draws" in caught.value.message
    assert "no slip at C" in caught.value.message


def test_signature_sees_a_flipped_assumption() -> None:
    spec = parse_file(WHEEL)
    rolls = signature(solve_spec(with_variant(spec, {"M": "20 N*m"}, "a")))
    slips = signature(solve_spec(with_variant(spec, {"M": "25 N*m"}, "b")))
    assert rolls.differs(rolls) == ""
    assert "assumption 'no slip at C' fails (base: holds)" in rolls.differs(slips)


def test_us_twin_converts_every_dimensional_given() -> None:
    # 45 kg = 45/14.5939029 slug = 3.0835 slug; 0.4 m = 1.3123 ft; 0.25 m = 0.82021 ft;
    # 9.81 m/s² = 32.185 ft/s²
    spec = parse_file(DRUM)
    twin = us_twin(spec, {"m_b": "45 kg", "r": "0.4 m"})
    assert twin == {
        "m_d": "4.111 slug",
        "k_O": "0.8202 ft",
        "r": "1.312 ft",
        "m_b": "3.083 slug",
        "g": "32.19 ft/s^2",
    }


# ---- cells are untrusted


@pytest.mark.parametrize(
    ("cell", "words"),
    [
        ("__import__('os')", "unexpected character"),
        ("45 kgs", "unknown unit 'kgs'"),
        ("1e999 kg", "out of range"),
        ("45", "is dimensionless, but m_b is mass"),
        ("4.5 m", "is length, but m_b is mass"),
    ],
)
def test_bad_cells_are_errors_naming_the_student(cell: str, words: str) -> None:
    spec = parse_file(DRUM)
    with pytest.raises((VariantError, UnitError)) as caught:
        with_variant(spec, {"m_b": cell}, "s042")
    assert "student s042" in caught.value.message
    assert words in caught.value.message


def test_a_cell_for_a_name_that_is_not_a_given_is_refused() -> None:
    with pytest.raises(VariantError, match="'x' is not a given"):
        with_variant(parse_file(DRUM), {"x": "1 m"}, "s1")


# ---- files


def test_roster_reads_the_id_column_and_refuses_duplicates(tmp_path: Path) -> None:
    roster = tmp_path / "r.csv"
    roster.write_text("name,id\nAda,s1\nBen,s2\n")
    assert read_roster(roster) == ["s1", "s2"]
    roster.write_text("student\ns1\ns1\n")
    with pytest.raises(CsvError) as caught:
        read_roster(roster)
    assert str(caught.value).startswith(f"{roster}:3:1: student 's1' appears twice")


def test_variants_file_with_a_short_row_is_a_positioned_error(tmp_path: Path) -> None:
    path = tmp_path / "v.csv"
    path.write_text("student,units,m\ns1,SI,45 kg\ns2,SI\n")
    with pytest.raises(CsvError, match="row has 2 cells, the header 3") as caught:
        read_variants(path)
    assert caught.value.position is not None and caught.value.position.line == 3


# ---- command line

runner = CliRunner()


def test_variants_command_writes_the_same_file_for_the_same_seed(tmp_path: Path) -> None:
    roster = tmp_path / "roster.csv"
    roster.write_text("student\ns1\ns2\ns3\n")
    outputs = []
    for name in ("a.csv", "b.csv"):
        out = tmp_path / name
        result = runner.invoke(
            app, ["variants", str(DRUM), "--roster", str(roster), "--seed", "8", "-o", str(out)]
        )
        assert result.exit_code == ExitCode.OK, result.output
        outputs.append(out.read_text())
    assert outputs[0] == outputs[1]
    assert outputs[0].splitlines()[0] == "student,units,m_d,m_b,r"
    assert len(outputs[0].splitlines()) == 4


def test_variants_both_writes_a_us_twin_per_student(tmp_path: Path) -> None:
    roster = tmp_path / "roster.csv"
    roster.write_text("student\ns1\n")
    out = tmp_path / "v.csv"
    args = ["variants", str(DRUM), "--roster", str(roster), "--seed", "8", "-o", str(out)]
    result = runner.invoke(app, [*args, "--units", "both"])
    assert result.exit_code == ExitCode.OK, result.output
    table = read_variants(out)
    assert list(table) == ["s1", "s1@US"]
    assert table["s1@US"]["k_O"] == "0.8202 ft"  # 0.25 m / 0.3048 m/ft = 0.82021 ft


def test_solve_variant_shows_the_students_givens(tmp_path: Path) -> None:
    # m_b = 25 kg, m_d = 60 kg, r = 0.4 m: α = m_b g r/(I_O + m_b r²) = 98.1/(3.75 + 4)
    # = 12.658 rad/s², shown 12.7
    variants = tmp_path / "v.csv"
    variants.write_text("student,units,m_b\ns7,SI,25 kg\n")
    result = runner.invoke(
        app, ["solve", str(DRUM), "--variant", "s7", "--variants", str(variants), "-f", "json"]
    )
    assert result.exit_code == ExitCode.OK, result.output
    assert "12.7 rad/s" in result.output
    assert "Drum and hanging block (student s7)" in result.output


def test_solve_variant_of_an_unknown_student_suggests_one(tmp_path: Path) -> None:
    variants = tmp_path / "v.csv"
    variants.write_text("student,units,m_b\ns007,SI,25 kg\n")
    result = runner.invoke(
        app, ["solve", str(DRUM), "--variant", "s07", "--variants", str(variants)]
    )
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "no student 's07'" in result.output and "did you mean 's007'" in result.output


def test_solve_variant_needs_the_variants_file() -> None:
    result = runner.invoke(app, ["solve", str(DRUM), "--variant", "s1"])
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "--variant and --variants go together" in result.output


def test_variants_of_a_spec_without_vary_is_an_error(tmp_path: Path) -> None:
    roster = tmp_path / "roster.csv"
    roster.write_text("student\ns1\n")
    spec = Path(__file__).parent.parent / "problems" / "seed" / "fa_hib_drum.dyn"
    out = tmp_path / "v.csv"
    result = runner.invoke(
        app, ["variants", str(spec), "--roster", str(roster), "--seed", "1", "-o", str(out)]
    )
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "has no 'vary:' section" in result.output
    assert not out.exists()


def test_allow_changes_keeps_variants_whose_assumptions_differ() -> None:
    # M = 25 and 30 N·m slip (M > 22.07 N·m, see wheel_couple.dyn); with 'allow changes'
    # they are kept, each solved with kinetic friction and its checks passing.
    text = WHEEL.read_text().replace("vary:\n", "vary:\n  allow changes\n")
    spec = parse_spec(text, "wheel.dyn")
    rows = make_variants(spec, [f"s{i}" for i in range(30)], seed=3)
    values = {r.cells["M"] for r in rows}
    assert values & {"25 N*m", "30 N*m"}
    plan = vary_plan(spec)
    assert all(r.cells == draw(plan, 3, r.student) for r in rows)  # first draws, none redrawn


def test_an_angle_varies_in_degrees_or_radians() -> None:
    # 20..40 deg step 5: 20, 25, 30, 35, 40 deg; a range in rad for a given in deg is the
    # same dimension (an angle), so it is accepted as written
    spec = parse_spec(
        "given:\n  theta = 30 deg\n  m = 2 kg\nvary:\n  theta = 20..40 deg step 5\n"
        "equations:\n  N = m*g*cos(theta)\nfind: N\n",
        "angle.dyn",
    )
    (variation,) = vary_plan(spec)
    assert variation.values() == ("20", "25", "30", "35", "40")
    # N = m g cos θ = 2·9.81·cos 40° = 15.0296 N for θ = 40 deg
    solution = solve_spec(with_variant(spec, {"theta": "40 deg"}, "s1"))
    assert solution.answers[0].value == pytest.approx(2 * 9.81 * 0.766044443, rel=1e-8)
    in_radians = parse_spec(
        "given:\n  theta = 30 deg\nvary:\n  theta = 0.3..0.7 rad step 0.1\n"
        "equations:\n  x = sin(theta)\nfind: x\n",
        "rad.dyn",
    )
    assert vary_plan(in_radians)[0].unit == "rad"


def test_variants_in_us_units_keep_the_student_ids(tmp_path: Path) -> None:
    roster = tmp_path / "roster.csv"
    roster.write_text("student\ns1\ns2\n")
    out = tmp_path / "v.csv"
    args = ["variants", str(DRUM), "--roster", str(roster), "--seed", "8", "-o", str(out)]
    result = runner.invoke(app, [*args, "--units", "us"])
    assert result.exit_code == ExitCode.OK, result.output
    lines = out.read_text().splitlines()
    assert [line.split(",")[:2] for line in lines[1:]] == [["s1", "US"], ["s2", "US"]]
    assert all(cell.endswith((" slug", " ft", " ft/s^2")) for cell in lines[1].split(",")[2:])


# ---- untrusted text never escapes as a traceback

_VARY_PIECES = st.sampled_from(
    ["m", "k", "x", " = ", "=", "..", ".", "-", "40", "1e99", "0", "kg", "N/m", "m^99", "step",
     " step ", "±", "+-", "%", "sigfig", " 3", "(", ")", "*", "/", " ", "allow changes"]
)  # fmt: skip


@settings(max_examples=300, derandomize=True)
@given(st.one_of(st.text(max_size=60), st.lists(_VARY_PIECES, max_size=12).map("".join)))
def test_any_vary_line_parses_or_is_a_positioned_error(text: str) -> None:
    source = f"given:\n  m = 50 kg\n  k = 200 N/m\nvary:\n  {text}\n"
    source += "equations:\n  F = m*g\nfind: F\n"
    try:
        spec = parse_spec(source, "fuzz.dyn")
        vary_plan(spec)
    except (SpecError, UnitError) as error:
        assert error.position is not None and error.position.file == "fuzz.dyn"


@settings(max_examples=300, derandomize=True)
@given(st.one_of(st.text(max_size=40), st.lists(_VARY_PIECES, max_size=8).map("".join)))
def test_any_cell_is_read_or_refused_with_the_student_named(text: str) -> None:
    spec = parse_file(DRUM)
    try:
        with_variant(spec, {"m_b": text}, "s9")
    except (VariantError, UnitError) as error:
        assert "student s9" in error.message


def test_the_example_class_variants_file_is_what_its_command_writes(tmp_path: Path) -> None:
    # examples/grading/README.md gives the command; the same seed must write the same file
    folder = DRUM.parent
    out = tmp_path / "variants.csv"
    args = ["variants", str(DRUM), "--roster", str(folder / "roster.csv"), "--seed", "2026"]
    result = runner.invoke(app, [*args, "-o", str(out)])
    assert result.exit_code == ExitCode.OK, result.output
    assert out.read_text() == (folder / "variants.csv").read_text()
    assert len(read_variants(out)) == 30


@pytest.mark.parametrize("path", [DRUM, WHEEL], ids=["drum", "wheel_couple"])
def test_the_closed_form_keeps_exactly_the_draws_full_solves_keep(path: Path) -> None:
    # issue 9: make_variants keeps first draws the closed form answers on the base branch
    # without a full solve each; the variants must be those of a full solve per student
    from dynsolve.grade.generate import _checked_draw, signature
    from dynsolve.system import SolveOptions

    spec = parse_file(path)
    plan, students = vary_plan(spec), [f"s{i}" for i in range(40)]
    options = SolveOptions()
    base = signature(solve_spec(with_variant(spec, {}, "base"), options))
    slow = {s: _checked_draw(spec, plan, 3, s, base, options) for s in students}
    fast = {row.student: row.cells for row in make_variants(spec, students, seed=3)}
    assert fast == slow


def test_a_variant_whose_solve_runs_past_its_budget_is_redrawn_then_refused(monkeypatch) -> None:
    # issue 9: the per-variant full solve runs under a budget in a worker, like `dynsolve
    # solve`; a wheel variant that rolls/slips needs a full solve, and with a budget no solve
    # can meet, every draw is refused and the error says why, naming the student
    import dynsolve.grade.generate as generate
    from dynsolve.budget import Budget

    monkeypatch.setattr(generate, "VARIANT_BUDGET", Budget(seconds=0.001))
    monkeypatch.setattr(generate, "_closed_form_accepts", lambda *args: {})
    with pytest.raises(SpecError) as caught:
        make_variants(parse_file(WHEEL), ["alice"], seed=1)
    assert "student alice: no valid variant in 20 draws" in caught.value.message
    assert "time budget" in caught.value.message
