"""The command line, end to end through typer's CliRunner: exit codes, output, files.

Expected numbers come from the textbook or from the hand derivations in the comments,
never from dynsolve's own output.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from fractions import Fraction
from importlib import metadata
from pathlib import Path

import pytest
import sympy
from specs import DRUM
from typer.testing import CliRunner, Result

import dynsolve
from dynsolve.cli import ExitCode, app
from dynsolve.units import registry

# Hibbeler 12e Example 17.11: a 60-kg drum (k_O = 0.25 m, r = 0.4 m) lets a 20-kg
# block down on a cord. Textbook: alpha = 11.3 rad/s², T = 106 N, a = 4.52 m/s².
#
# By hand, with g = 9.81 m/s² (the SI default):
#   I_O = m_d k_O² = 60 (0.25)² = 15/4 kg·m²
#   T r = I_O alpha            ->  T = I_O alpha / r
#   m_b g - T = m_b a, a = alpha r
#   ->  m_b g = alpha (I_O / r + m_b r)
#   ->  alpha = m_b g r / (I_O + m_b r²) = 20·9.81·0.4 / (3.75 + 20·0.16)
#             = 78.48 / 6.95 = 7848/695 rad/s²            (11.2921…)
#   T = I_O alpha / r = (15/4)(5/2)(7848/695) = 14715/139 N  (105.863…)
#   a = alpha r = (2/5)(7848/695) = 15696/3475 m/s²        (4.51683…)
ALPHA = Fraction(7848, 695)
TENSION = Fraction(14715, 139)
ACCEL = Fraction(15696, 3475)

# 120 N is 13 % above the true 105.9 N: far outside the 0.5 % tolerance.
DRUM_WRONG_KEY = DRUM.replace("T     = 106 N", "T     = 120 N")
assert DRUM_WRONG_KEY != DRUM

# Line 6, column 12 is "kgs" ("  m_d = 60 kgs": 11 characters before it).
DRUM_BAD_UNIT = DRUM.replace("m_d = 60 kg ", "m_d = 60 kgs")
# Line 13, column 5 is "r" in "  T r = I_O*alpha" (no implicit multiplication).
DRUM_IMPLICIT = DRUM.replace("  T*r = I_O*alpha", "  T r = I_O*alpha")

# A 40-lb block hanging at rest from a cord: ΣF_y = 0 gives T = W = 40 lb.
# In newtons: 1 lb = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N (exact by
# definition), so T = 177.92886461042 N, 178 N to three figures.
FPS_BLOCK = """\
problem: 40-lb block hanging from a cord
units: FPS
given:
  W = 40 lb    # weight of the block
equations:
  T = W        # ΣF_y = 0 for the block
find: {find}
"""
LBF_IN_N = Fraction("4.4482216152605")

# Energy conservation from rest: m v²/2 = m g h  ->  v = sqrt(2 g h), taking v >= 0.
SYMBOLIC = """\
problem: Speed after falling a height h
given:
  m: mass
  h: length
  g: acceleration
equations:
  m*v^2/2 = m*g*h     # T1 + V1 = T2 + V2, from rest
  v >= 0
find: v
answers:
  v = {key}
"""

ANSI = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]")


def run(*args: str | Path) -> Result:
    """Invoke the CLI; fail on any exception other than the normal exit."""
    result = CliRunner().invoke(app, [str(a) for a in args])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"uncaught {result.exception!r}") from result.exception
    assert "Traceback" not in result.output
    return result


def text_of(stream: str) -> str:
    return ANSI.sub("", stream)


def section(output: str, title: str, following: str) -> str:
    """The lines of ``output`` between the heading ``title`` and the next heading."""
    match = re.search(rf"^{title}\s*$(.*?)^{following}\s*$", output, re.S | re.M)
    assert match, f"no '{title}' section in:\n{output}"
    return match.group(1)


def last_line(output: str) -> str:
    return [line for line in output.splitlines() if line.strip()][-1].strip()


@pytest.fixture
def workdir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Run in tmp_path so paths in output stay short (rich tables wrap long ones)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# ---- solve: text ------------------------------------------------------------------------


def test_solve_drum_exits_0_with_answers_to_three_figures_and_checks(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn")
    assert result.exit_code == ExitCode.OK == 0
    out = text_of(result.stdout)
    answers = section(out, "Answers", "Checks")
    # Textbook: alpha = 11.3 rad/s², T = 106 N, a = 4.52 m/s² (3 s.f. of the values above).
    assert re.search(r"^\s*α\s+11\.3 rad/s(²|\^2)\s*$", answers, re.M), answers
    assert re.search(r"^\s*T\s+106 N\s*$", answers, re.M), answers
    assert re.search(r"^\s*a\s+4\.52 m/s(²|\^2)\s*$", answers, re.M), answers
    checks = out.split("Checks", 1)[1]
    for name in ("dimensions", "structure", "substitution", "answer alpha", "answer T", "answer a"):
        assert name in checks
    assert "✗" not in checks
    assert result.stderr == ""


def test_solve_with_a_wrong_key_exits_1_and_marks_the_failed_answer(workdir: Path):
    write(workdir, "drum.dyn", DRUM_WRONG_KEY)
    result = run("solve", "drum.dyn")
    assert result.exit_code == ExitCode.FAILED == 1
    checks = text_of(result.stdout).split("Checks", 1)[1]
    failed = [line for line in checks.splitlines() if "✗" in line]
    assert len(failed) == 1 and "answer T" in failed[0] and "120 N" in failed[0]


def test_check_with_a_wrong_key_prints_a_failures_table_and_summary(workdir: Path):
    write(workdir, "drum.dyn", DRUM_WRONG_KEY)
    result = run("check", "drum.dyn")
    assert result.exit_code == 1
    out = text_of(result.stdout)
    table = out.rsplit("0 passed", 1)[0]
    assert "drum.dyn" in table and "answer T" in table and "120 N" in table
    assert "answer alpha" not in table  # only the failure is listed
    assert last_line(out) == "0 passed, 1 failed"


def test_check_of_a_passing_spec_exits_0(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    result = run("check", "drum.dyn")
    assert result.exit_code == 0
    assert last_line(text_of(result.stdout)) == "1 passed, 0 failed"


@pytest.mark.parametrize(
    ("text", "position", "message"),
    [
        pytest.param(DRUM_BAD_UNIT, "6:12", "unknown unit 'kgs'", id="unknown-unit"),
        pytest.param(DRUM_IMPLICIT, "13:5", "unexpected 'r'", id="implicit-multiplication"),
    ],
)
def test_malformed_spec_exits_2_with_file_line_column_on_stderr(
    workdir: Path, text: str, position: str, message: str
):
    write(workdir, "drum.dyn", text)
    result = run("solve", "drum.dyn")
    assert result.exit_code == ExitCode.BAD_INPUT == 2
    assert f"drum.dyn:{position}: {message}" in result.stderr
    assert "hint:" in result.stderr
    assert result.stdout == ""


# ---- solve: other formats -----------------------------------------------------------------


def test_json_output_has_full_precision_values_and_parsable_units(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", "--format", "json")
    assert result.exit_code == 0
    data = json.loads(result.stdout)
    assert data["title"] == "Drum and hanging block"
    assert data["mode"] == "equations"

    ureg = registry()  # lb = pound_force, as in the spec language
    answers = {a["name"]: a for a in data["answers"]}
    assert list(answers) == ["alpha", "T", "a"]
    for name, exact, si_unit in (
        ("alpha", ALPHA, "rad/s**2"),
        ("T", TENSION, "N"),
        ("a", ACCEL, "m/s**2"),
    ):
        answer = answers[name]
        assert answer["value"] == pytest.approx(float(exact), rel=1e-12)
        in_si = ureg.Quantity(answer["value"], ureg.Unit(answer["unit"])).to(si_unit)
        assert in_si.magnitude == pytest.approx(float(exact), rel=1e-12)

    assert len(data["equations"]) == 4
    for equation in data["equations"]:
        assert isinstance(equation["text"], str) and equation["text"]
        assert isinstance(equation["latex"], str) and equation["latex"]
        assert equation["dimension_ok"] is True
    assert "T r = I_{O} \\alpha" in [e["latex"] for e in data["equations"]]

    names = [c["name"] for c in data["checks"]]
    assert {"dimensions", "substitution", "answer alpha", "answer T", "answer a"} <= set(names)
    for check in data["checks"]:
        assert isinstance(check["name"], str)
        assert check["passed"] is True
        assert isinstance(check["detail"], str) and check["detail"]


def test_json_of_a_wrong_key_reports_the_failed_check(workdir: Path):
    write(workdir, "drum.dyn", DRUM_WRONG_KEY)
    result = run("solve", "drum.dyn", "-f", "json")
    assert result.exit_code == 1
    checks = {c["name"]: c for c in json.loads(result.stdout)["checks"]}
    assert checks["answer T"]["passed"] is False
    assert checks["answer alpha"]["passed"] is True


def test_markdown_output(workdir: Path):
    pytest.importorskip("dynsolve.render.markdown")
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", "--format", "markdown")
    assert result.exit_code == 0
    assert result.stdout.lstrip().startswith("# Drum and hanging block")
    assert "11.3" in result.stdout and "106" in result.stdout and "4.52" in result.stdout


def test_latex_output_is_a_document(workdir: Path):
    pytest.importorskip("dynsolve.render.latex")
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", "--format", "latex")
    assert result.exit_code == 0
    tex = result.stdout
    assert tex.lstrip().startswith("\\documentclass")
    assert "\\begin{document}" in tex and tex.rstrip().endswith("\\end{document}")
    assert "11.3" in tex and "106" in tex


# ---- solve -o -------------------------------------------------------------------------------


def test_output_file_is_written_and_stdout_stays_empty(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", "--format", "json", "-o", "out.json")
    assert result.exit_code == 0
    assert result.stdout == ""
    data = json.loads((workdir / "out.json").read_text(encoding="utf-8"))
    assert data["title"] == "Drum and hanging block"
    assert {a["name"]: a["value"] for a in data["answers"]}["alpha"] == pytest.approx(
        float(ALPHA), rel=1e-12
    )
    assert sorted(p.name for p in workdir.iterdir()) == ["drum.dyn", "out.json"]  # no temp left


# regression (fixed): _write_atomically writes through tempfile.mkstemp, whose 0600 mode survives
# os.replace: -o files are private, unlike any other file the user creates
def test_output_file_gets_ordinary_permissions(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    reference = write(workdir, "reference.txt", "x")
    assert run("solve", "drum.dyn", "-f", "json", "-o", "out.json").exit_code == 0
    assert (workdir / "out.json").stat().st_mode & 0o777 == reference.stat().st_mode & 0o777


@pytest.mark.parametrize(
    ("spec_name", "output"),
    [
        pytest.param("drum.dyn", "drum.dyn", id="the-spec-itself"),
        pytest.param("drum.dyn", "./sub/../drum.dyn", id="the-spec-by-another-path"),
        pytest.param("drum.dyn", "other.dyn", id="another-dyn-path"),
        pytest.param("problem.txt", "problem.txt", id="a-spec-without-dyn-suffix"),
    ],
)
def test_output_never_overwrites_a_spec(workdir: Path, spec_name: str, output: str):
    spec = write(workdir, spec_name, DRUM)
    (workdir / "sub").mkdir()
    before = spec.read_bytes()
    for fmt in ("json", "text"):
        result = run("solve", spec_name, "-f", fmt, "-o", output)
        assert result.exit_code == 2
        assert "refusing" in result.stderr or "spec" in result.stderr
        assert spec.read_bytes() == before
    assert not (workdir / "other.dyn").exists()
    assert sorted(p.name for p in workdir.iterdir()) == sorted([spec_name, "sub"])


def test_output_into_a_missing_folder_exits_2(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", "-f", "json", "-o", "missing/out.json")
    assert result.exit_code == 2
    assert "missing" in result.stderr
    assert not (workdir / "missing").exists()


# regression (fixed): -o naming an existing folder: os.replace raises IsADirectoryError, a
# traceback instead of exit 2 with a message
def test_output_onto_an_existing_folder_exits_2(workdir: Path):
    write(workdir, "drum.dyn", DRUM)
    (workdir / "results").mkdir()
    result = run("solve", "drum.dyn", "-f", "json", "-o", "results")
    assert result.exit_code == 2
    assert "results" in result.stderr


# ---- bad command lines ----------------------------------------------------------------------


@pytest.mark.parametrize("command", ["solve", "check"])
def test_a_missing_file_exits_2_with_a_clear_message(workdir: Path, command: str):
    result = run(command, "nowhere.dyn")
    assert result.exit_code == 2
    assert "nowhere.dyn" in result.stderr
    assert re.search(r"no such file|cannot read", result.stderr, re.I)


@pytest.mark.parametrize(
    "options",
    [
        pytest.param(["--format", "docx"], id="format-docx"),
        pytest.param(["--mode", "fast"], id="mode-fast"),
        pytest.param(["--time-budget", "0"], id="time-budget-0"),
        pytest.param(["--no-such-option"], id="unknown-option"),
    ],
)
def test_a_bad_option_exits_2(workdir: Path, options: list[str]):
    write(workdir, "drum.dyn", DRUM)
    result = run("solve", "drum.dyn", *options)
    assert result.exit_code == 2
    assert result.stdout == ""


def test_solve_without_a_file_exits_2(workdir: Path):
    assert run("solve").exit_code == 2


# ---- check on folders ---------------------------------------------------------------------


def test_check_folder_counts_passes_failures_and_malformed_specs(workdir: Path):
    write(workdir, "specs/a_drum.dyn", DRUM)
    write(workdir, "specs/b_block.dyn", FPS_BLOCK.format(find="T"))
    write(workdir, "specs/nested/c_wrong.dyn", DRUM_WRONG_KEY)
    write(workdir, "specs/d_bad.dyn", DRUM_BAD_UNIT)
    write(workdir, "specs/notes.txt", "not a spec: ignored")
    result = run("check", "specs")
    # a malformed spec is bad input: exit 2 even though a spec merely failed too
    assert result.exit_code == 2
    out = text_of(result.stdout)
    assert last_line(out) == "2 passed, 1 failed, 1 malformed"
    assert "c_wrong.dyn" in out and "d_bad.dyn" in out and "kgs" in out
    assert "a_drum.dyn" not in out and "b_block.dyn" not in out


def test_check_folder_where_everything_passes_exits_0(workdir: Path):
    write(workdir, "specs/a_drum.dyn", DRUM)
    write(workdir, "specs/b_block.dyn", FPS_BLOCK.format(find="T [N]"))
    result = run("check", "specs")
    assert result.exit_code == 0
    assert last_line(text_of(result.stdout)) == "2 passed, 0 failed"


def test_check_of_an_empty_folder_exits_2(workdir: Path):
    (workdir / "empty").mkdir()
    result = run("check", "empty")
    assert result.exit_code == 2
    assert "no .dyn files" in result.stderr


# ---- units and symbolic problems ------------------------------------------------------------


def test_fps_answer_is_shown_in_pounds(workdir: Path):
    write(workdir, "block.dyn", FPS_BLOCK.format(find="T"))
    result = run("solve", "block.dyn")
    assert result.exit_code == 0
    answers = section(text_of(result.stdout), "Answers", "Checks")
    assert re.search(r"^\s*T\s+40(\.0)? lb\s*$", answers, re.M), answers


def test_fps_answer_in_requested_newtons(workdir: Path):
    write(workdir, "block.dyn", FPS_BLOCK.format(find="T [N]"))
    result = run("solve", "block.dyn")
    assert result.exit_code == 0
    answers = section(text_of(result.stdout), "Answers", "Checks")
    assert re.search(r"^\s*T\s+178 N\s*$", answers, re.M), answers
    data = json.loads(run("solve", "block.dyn", "-f", "json").stdout)
    (answer,) = data["answers"]
    assert answer["unit"] == "N"
    assert answer["value"] == pytest.approx(float(40 * LBF_IN_N), rel=1e-12)


def test_symbolic_problem_gives_a_formula_equivalent_to_sqrt_2gh(workdir: Path):
    write(workdir, "fall.dyn", SYMBOLIC.format(key="sqrt(2*g*h)"))
    result = run("solve", "fall.dyn")
    assert result.exit_code == 0  # the formula key passes
    data = json.loads(run("solve", "fall.dyn", "-f", "json").stdout)
    (answer,) = data["answers"]
    assert answer["name"] == "v" and answer["value"] is None
    g, h = sympy.symbols("g h", positive=True)
    formula = sympy.sympify(answer["exact"], locals={"g": g, "h": h})
    assert sympy.simplify(formula - sympy.sqrt(2 * g * h)) == 0
    assert registry().Unit(answer["unit"]).dimensionality == registry().Unit("m/s").dimensionality


def test_symbolic_problem_with_a_wrong_formula_key_exits_1(workdir: Path):
    # sqrt(g*h) is off by a factor sqrt(2) from sqrt(2*g*h).
    write(workdir, "fall.dyn", SYMBOLIC.format(key="sqrt(g*h)"))
    assert run("solve", "fall.dyn").exit_code == 1


# regression (fixed): a block whose only root is not real: pipeline._View.step indexes
# block.values[y] and raises KeyError (a traceback) instead of reporting the discarded root
def test_a_spec_whose_only_root_is_complex_fails_without_a_traceback(workdir: Path):
    # x = -1, y = sqrt(x): the only root y = i is not real, so y is not determined.
    write(workdir, "complex.dyn", "equations:\n  y = sqrt(x)\n  x = -1\nfind: y\n")
    result = run("solve", "complex.dyn")
    assert result.exit_code == 1


# ---- help and version -----------------------------------------------------------------------


def test_help_lists_the_commands():
    result = run("--help")
    assert result.exit_code == 0
    assert "solve" in result.stdout and "check" in result.stdout


def test_help_does_not_import_sympy():
    code = (
        "import sys; from typer.testing import CliRunner; from dynsolve.cli import app; "
        "r = CliRunner().invoke(app, ['--help']); assert r.exit_code == 0, r.output; "
        "print('sympy' in sys.modules)"
    )
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "False"


def test_version_prints_the_package_version():
    result = run("--version")
    assert result.exit_code == 0
    assert result.stdout.strip() == f"dynsolve {dynsolve.__version__}"
    assert dynsolve.__version__ == metadata.version("dynsolve")


def test_a_partly_symbolic_answer_names_the_units_of_its_numbers(tmp_path: Path):
    # regression: w = sqrt(k/m) with k = 100 N/m and m symbolic printed '10/sqrt(m)'
    # without saying that 10 is in SI base units (sqrt(100 N/m) = 10 kg^(1/2)/s).
    path = tmp_path / "mixed.dyn"
    path.write_text("given:\n  m: mass\n  k = 100 N/m\nequations:\n  w = sqrt(k/m)\nfind: w\n")
    result = CliRunner().invoke(app, ["solve", str(path), "--format", "json"])
    assert result.exit_code == 0, result.output
    answer = json.loads(result.stdout)["answers"][0]
    assert answer["value"] is None
    assert "10/sqrt(m)" in answer["shown"] and "(numbers in m, kg, s)" in answer["shown"]
