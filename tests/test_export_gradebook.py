"""``dynsolve export canvas|scores``: the gradebook in Canvas's import format and as a
Gradescope/Moodle scores CSV, every cell safe from formula injection (OWASP).

Canvas's import columns (Canvas guides, "How do I import grades in the Gradebook?", and
its own gradebook export): Student, ID, SIS User ID, SIS Login ID, Section, then one
column per assignment headed "Name (assignment id)", with a "Points Possible" row.
Points are scaled by hand in the comments: earned / max_points × --points.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import ExitCode, app
from dynsolve.safe_csv import csv_text, unescape_cell
from dynsolve.safe_csv import escape_cell as safe_cell

runner = CliRunner()
HOSTILE = (
    '=HYPERLINK("http://evil.example","x")',
    "+cmd|' /C calc'!A0",
    "@SUM(1+1)*cmd|' /C calc'!A0",
    "=1+1",
    "-2+3",
    "\tleading tab",
    "\rcarriage return",
)
GRADEBOOK = (
    "student,score,points,max_points\n"
    "s001,100.00,3,3\n"
    "s002,50.00,1.5,3\n"
    "'=1+1,0.00,0,3\n"  # dynsolve's own escaped id, read back as =1+1
)


def _rows(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text, newline="")))


@pytest.mark.parametrize("cell", HOSTILE)
def test_every_formula_trigger_is_quoted(cell: str) -> None:
    assert safe_cell(cell) == "'" + cell
    assert unescape_cell(safe_cell(cell)) == cell
    (row,) = _rows(csv_text([[cell]]))
    assert row[0].startswith("'")  # a spreadsheet shows it as text


@pytest.mark.parametrize("number", ["-4.52", "-1e3", "-.5", "-0", "4.52", "-1.06E+2"])
def test_plain_numbers_stay_numbers(number: str) -> None:
    assert safe_cell(number) == number


def test_an_apostrophe_that_escapes_nothing_is_kept() -> None:
    assert unescape_cell("'O'Brien") == "'O'Brien"


def _text(path: Path) -> str:
    return path.read_bytes().decode("utf-8")  # no newline translation: CRLF stays


def _gradebook(tmp_path: Path, text: str = GRADEBOOK) -> Path:
    path = tmp_path / "gradebook.csv"
    path.write_text(text)
    return path


def test_canvas_import_columns_and_points(tmp_path: Path) -> None:
    out = tmp_path / "canvas.csv"
    result = runner.invoke(
        app,
        ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out),
         "--assignment", "Drum and block (4711)", "--points", "10"],
    )  # fmt: skip
    assert result.exit_code == ExitCode.OK, result.output
    rows = _rows(_text(out))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section",
                       "Drum and block (4711)"]  # fmt: skip
    assert rows[1][0].strip() == "Points Possible" and rows[1][5] == "10"
    by_id = {row[2]: row[5] for row in rows[2:]}
    assert by_id["s001"] == "10"  # 3/3 x 10
    assert by_id["s002"] == "5"  # 1.5/3 x 10
    assert by_id["'=1+1"] == "0"  # the id escaped again on the way out


def test_canvas_without_points_keeps_the_weights(tmp_path: Path) -> None:
    out = tmp_path / "canvas.csv"
    args = ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out), "--assignment", "HW"]
    assert runner.invoke(app, [*args, "--id-column", "sis-login-id"]).exit_code == 0
    rows = _rows(_text(out))
    assert rows[1][5] == "3" and rows[3][3] == "s002" and rows[3][5] == "1.5"


def test_canvas_roster_fills_names_and_sections(tmp_path: Path) -> None:
    roster = tmp_path / "canvas_export.csv"
    roster.write_text(
        "Student,ID,SIS User ID,SIS Login ID,Section,Quiz 1 (12)\n"
        "    Points Possible,,,,,5\n"
        '"Lovelace, Ada",101,s001,ada,Sec A,4\n'
        '"Babbage, Charles",102,9002,s002,Sec B,3\n'
        '"=cmd, Eve",103,=1+1,eve,@Sec,1\n'
    )
    out = tmp_path / "canvas.csv"
    result = runner.invoke(
        app,
        ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out), "--assignment", "HW",
         "--roster", str(roster)],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    rows = _rows(_text(out))
    assert rows[2] == ["Lovelace, Ada", "101", "s001", "ada", "Sec A", "3"]
    assert rows[3] == ["Babbage, Charles", "102", "9002", "s002", "Sec B", "1.5"]
    assert rows[4] == ["'=cmd, Eve", "103", "'=1+1", "eve", "'@Sec", "0"]


def test_canvas_roster_missing_a_graded_student_stops(tmp_path: Path) -> None:
    roster = tmp_path / "canvas_export.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\nAda,101,s001,ada,A\n")
    out = tmp_path / "canvas.csv"
    result = runner.invoke(
        app,
        ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out), "--assignment", "HW",
         "--roster", str(roster)],
    )  # fmt: skip
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "2 graded student(s) not in the Canvas roster: s002, =1+1" in result.output
    assert not out.exists()


def test_scores_csv_for_gradescope_and_moodle(tmp_path: Path) -> None:
    out = tmp_path / "scores.csv"
    args = ["export", "scores", str(_gradebook(tmp_path)), "-o", str(out), "--points", "20"]
    assert runner.invoke(app, args).exit_code == 0
    rows = _rows(_text(out))
    assert rows[0] == ["SID", "Total Score", "Max Points"]
    assert rows[1:] == [["s001", "20", "20"], ["s002", "10", "20"], ["'=1+1", "0", "20"]]


def test_a_non_empty_output_needs_force(tmp_path: Path) -> None:
    out = tmp_path / "scores.csv"
    out.write_text("keep me\n")
    args = ["export", "scores", str(_gradebook(tmp_path)), "-o", str(out)]
    result = runner.invoke(app, args)
    assert result.exit_code == ExitCode.BAD_INPUT and "--force" in result.output
    assert _text(out) == "keep me\n"
    assert runner.invoke(app, [*args, "--force"]).exit_code == 0
    assert _text(out).startswith("SID,")


def test_the_input_is_never_the_output(tmp_path: Path) -> None:
    gradebook = _gradebook(tmp_path)
    result = runner.invoke(
        app, ["export", "scores", str(gradebook), "-o", str(gradebook), "--force"]
    )
    assert result.exit_code == ExitCode.BAD_INPUT and "it is an input" in result.output
    assert gradebook.read_text() == GRADEBOOK


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("student,alpha\ns1,3 N\n", "not a dynsolve gradebook"),
        ("student,score,points,max_points\ns1,x,1,3\n", "must be numbers"),
        ("student,score,points,max_points\ns1,50,1,3\ns1,50,1,3\n", "appears twice"),
        ("student,score,points,max_points\n", "lists no students"),
    ],
)
def test_bad_gradebooks_are_refused_with_their_line(
    tmp_path: Path, text: str, message: str
) -> None:
    out = tmp_path / "scores.csv"
    result = runner.invoke(
        app, ["export", "scores", str(_gradebook(tmp_path, text)), "-o", str(out)]
    )
    assert result.exit_code == ExitCode.BAD_INPUT
    assert message in result.output and "gradebook.csv:" in result.output
    assert not out.exists()


def test_an_unreadable_assignment_name_is_refused(tmp_path: Path) -> None:
    out = tmp_path / "c.csv"
    args = ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out), "--assignment", "a\nb"]
    result = runner.invoke(app, args)
    assert result.exit_code == ExitCode.BAD_INPUT and "printable" in result.output


def test_a_broken_csv_is_an_error_with_its_line_not_a_traceback(tmp_path: Path) -> None:
    huge = "student,score,points,max_points\n" + "x" * 200_000 + ",1,1,3\n"  # over csv's limit
    out = tmp_path / "s.csv"
    result = runner.invoke(
        app, ["export", "scores", str(_gradebook(tmp_path, huge)), "-o", str(out)]
    )
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "cannot read" in result.output and "field larger than field limit" in result.output
    roster = tmp_path / "roster.csv"
    roster.write_text("Student,ID\n" + "y" * 200_000 + ",1\n")
    args = ["export", "canvas", str(_gradebook(tmp_path)), "-o", str(out), "--assignment", "HW"]
    result = runner.invoke(app, [*args, "--roster", str(roster)])
    assert result.exit_code == ExitCode.BAD_INPUT and "roster.csv:" in result.output


def test_two_graded_ids_of_one_canvas_student_stop(tmp_path: Path) -> None:
    roster = tmp_path / "canvas_export.csv"
    roster.write_text("Student,ID,SIS User ID,SIS Login ID,Section\nAda,101,s001,s002,A\n")
    gradebook = _gradebook(tmp_path, "student,score,points,max_points\ns001,100,3,3\ns002,0,0,3\n")
    out = tmp_path / "canvas.csv"
    args = ["export", "canvas", str(gradebook), "-o", str(out), "--assignment", "HW"]
    result = runner.invoke(app, [*args, "--roster", str(roster)])
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "graded ids 's001' and 's002' are one Canvas student (Ada)" in result.output
    assert not out.exists()
