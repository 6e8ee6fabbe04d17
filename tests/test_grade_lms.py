"""LMS exports graded as they come: Canvas, Gradescope and Moodle CSV files (tests/data/lms/),
their delimiters, decimal commas, id headers, answer columns and rows that are no student.

Keys from the scene-mode drum, problems/seed/fa_hib_drum.dyn (Hibbeler 12e Example 17.11):
alpha = 78.48/6.95 = 11.292 rad/s^2 cw (= 647.0 deg/s^2), T = 3.75(11.292)/0.4 = 105.86 N,
a = 0.4(11.292) = 4.5168 m/s^2 down (= 14.819 ft/s^2).
"""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.grade.answers import read_answers

ROOT = Path(__file__).parent.parent
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
LMS = ROOT / "tests" / "data" / "lms"
FINDS = ["alpha", "T", "a"]
runner = CliRunner()


def _grade(tmp_path: Path, answers: Path) -> dict:
    out = tmp_path / "r.json"
    result = runner.invoke(app, ["grade", str(DRUM), str(answers), "--json", str(out)])
    assert result.exit_code == 0, result.output
    return json.loads(out.read_text())


def _verdicts(report: dict) -> dict[str, dict[str, str]]:
    return {
        s["student"]: {part: cell["verdict"] for part, cell in s["parts"].items()}
        for s in report["students"]
    }


ALL_RIGHT = {"alpha": "correct", "T": "correct", "a": "correct"}


def test_canvas_quiz_student_analysis(tmp_path: Path) -> None:
    report = _grade(tmp_path, LMS / "canvas_quiz_student_analysis.csv")
    assert _verdicts(report) == {
        "S001": ALL_RIGHT,  # clockwise, 106 N, downward
        "S002": ALL_RIGHT,  # bare magnitudes in the header's units
        # ccw for a cw alpha; 196 N is m_b g = 20(9.81) = 196.2 N; left for a downward a
        "S003": {"alpha": "sign", "T": "wrong", "a": "sign"},
    }
    assert any("'sis_id'" in w for w in report["warnings"])
    poe = next(s for s in report["students"] if s["student"] == "S003")
    assert poe["parts"]["T"]["feedback"].startswith("the static answer T = m_b g")


def test_canvas_gradebook_skips_points_possible_and_test_student(tmp_path: Path) -> None:
    report = _grade(tmp_path, LMS / "canvas_gradebook.csv")
    # ids from SIS User ID, not the 'Student' names; "11,3" in a point file is 11.3
    assert _verdicts(report) == {"S001": ALL_RIGHT, "S002": ALL_RIGHT}


def test_gradescope_export(tmp_path: Path) -> None:
    report = _grade(tmp_path, LMS / "gradescope_online_assignment.csv")
    missing = {"alpha": "missing", "T": "missing", "a": "missing"}
    # S002: 647 deg/s^2, 1.06 x 10^2 N, 14.8 ft/s^2 (4.511 m/s^2, 0.13 % off)
    assert _verdicts(report) == {"S001": ALL_RIGHT, "S002": ALL_RIGHT, "S003": missing}


def test_moodle_semicolons_and_decimal_commas(tmp_path: Path) -> None:
    report = _grade(tmp_path, LMS / "moodle_responses_semicolon.csv")
    # S002: 11,3 deg/s^2 is 0.197 rad/s^2 (wrong); -106 N for +105.86 N; '-' is no answer
    assert _verdicts(report) == {
        "S001": ALL_RIGHT,
        "S002": {"alpha": "wrong", "T": "sign", "a": "missing"},
    }
    roe = next(s for s in report["students"] if s["student"] == "S002")
    assert roe["parts"]["alpha"]["feedback"].startswith("a value in radians labelled as degrees")
    warnings = "\n".join(report["warnings"])
    assert "decimal comma" in warnings
    assert "'Response 1' -> alpha, 'Response 2' -> T, 'Response 3' -> a" in warnings


def test_moodle_tabs_and_empty_id_numbers(tmp_path: Path) -> None:
    report = _grade(tmp_path, LMS / "moodle_responses_tab.csv")
    # ID number is empty: ids from Email address; 'down' is no sense of rotation; 0 N read
    assert _verdicts(report) == {
        "jdoe@univ.edu": ALL_RIGHT,
        "rroe@univ.edu": {"alpha": "sign", "T": "wrong", "a": "sign"},
    }


@pytest.mark.parametrize(
    ("header", "id_column"),
    [
        ("Student ID,a", "Student ID"),
        ("SIS User ID,a", "SIS User ID"),
        ("SIS Login ID,a", "SIS Login ID"),
        ("Student,ID,SIS User ID,a", "SIS User ID"),  # Canvas: Student holds names
        ("ID number,a", "ID number"),
        ("Email address,a", "Email address"),
        ("Username,a", "Username"),
        ("Name,SID,Email,a", "SID"),
        ("student,email,a", "student"),
    ],
)
def test_id_headers(header: str, id_column: str) -> None:
    cells = ",".join(["u1"] * (header.count(",")) + ["4.52 m/s^2"])
    sheet = read_answers(io.StringIO(f"{header}\n{cells}\n"), ["a"], "a.csv")
    assert sheet.id_header == id_column and sheet.rows[0][0] == "u1"


def test_excel_sep_line_and_delimiters() -> None:
    text = 'sep=;\nstudent;a [m/s^2]\ns1;"4,52"\n'
    sheet = read_answers(io.StringIO(text), ["a"], "a.csv")
    assert sheet.rows == (("s1", {"a": "4,52"}),) and sheet.decimal_comma
    tabbed = read_answers(io.StringIO("student\ta\ns1\t4.52 m/s^2\n"), ["a"], "a.csv")
    assert tabbed.rows == (("s1", {"a": "4.52 m/s^2"}),) and not tabbed.decimal_comma


def test_a_score_column_is_not_an_answer() -> None:
    sheet = read_answers(io.StringIO("SID,1: T (1.0 pts),2: T (N)\ns1,1.0,106\n"), ["T"], "g.csv")
    assert sheet.columns == {"T": "2: T (N)"} and sheet.units == {"T": "N"}


def test_header_unit_of_another_dimension_stops_the_run(tmp_path: Path) -> None:
    answers = tmp_path / "a.csv"
    answers.write_text("student,alpha [rad/s^2],T [N],a [N]\ns1,11.3,106,4.52\n")
    result = runner.invoke(app, ["grade", str(DRUM), str(answers)])
    assert result.exit_code == 2
    assert "a.csv:1:" in result.output and "column 'a [N]'" in result.output
    assert "acceleration" in result.output


def test_many_ignored_columns_make_one_warning() -> None:
    header = "student," + ",".join(f"x{i}" for i in range(500)) + ",a"
    sheet = read_answers(io.StringIO(header + "\ns1" + "," * 500 + ",4.52 m/s^2\n"), ["a"], "a")
    assert len(sheet.warnings) == 1 and "500 columns" in sheet.warnings[0]


def test_unknown_header_unit_still_stops() -> None:
    with pytest.raises(SpecError, match="unknown unit"):
        read_answers(io.StringIO("student,a [blargs]\ns1,1\n"), ["a"], "a.csv")
