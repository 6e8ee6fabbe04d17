"""``dynsolve grade`` and ``dynsolve check --format/-v`` through the command line.

Keys by hand: Hibbeler 12e Example 17.11 (drum and block), alpha = 78.48/6.95 = 11.292 rad/s^2,
T = 3.75(11.292)/0.4 = 105.86 N (= 23.80 lb), a = 0.4(11.292) = 4.5168 m/s^2.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from xml.etree import ElementTree

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app

ROOT = Path(__file__).parent.parent
DRUM = ROOT / "problems" / "equations" / "fa_hib_drum.dyn"
runner = CliRunner()

ANSWERS = """student,alpha [rad/s^2],T,a
s1,11.3,106 N,4.52 m/s^2
s2,11.29,23.8 lb,45.2 m/s^2
s3,abc,106 kg,-4.52 m/s^2
s4,1.15,,4.52
"""


def _write(tmp_path: Path, text: str = ANSWERS) -> Path:
    path = tmp_path / "answers.csv"
    path.write_text(text)
    return path


def test_grade_reports(tmp_path: Path) -> None:
    answers = _write(tmp_path)
    before = answers.read_bytes()
    out, js, gb, hist = (tmp_path / n for n in ("r.csv", "r.json", "gb.csv", "h.svg"))
    result = runner.invoke(
        app,
        [
            "grade", str(DRUM), str(answers), "-o", str(out), "--json", str(js),
            "--gradebook", str(gb), "--histogram", str(hist),
        ],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert answers.read_bytes() == before  # the input is never modified
    document = json.loads(js.read_text())
    rows = {r["student"]: r for r in document["students"]}
    assert rows["s1"]["score"] == 100.0
    assert rows["s2"]["parts"]["a"]["verdict"] == "wrong"
    assert "power-of-ten" in rows["s2"]["parts"]["a"]["feedback"]
    assert rows["s3"]["parts"]["alpha"]["verdict"] == "unreadable"
    assert rows["s3"]["parts"]["T"]["verdict"] == "dimension"
    assert rows["s3"]["parts"]["a"]["verdict"] == "sign"  # equation mode: a is positive
    assert rows["s4"]["parts"]["alpha"]["feedback"].startswith("g left out")
    assert rows["s4"]["parts"]["T"]["verdict"] == "missing"
    assert rows["s4"]["parts"]["a"]["verdict"] == "unreadable"  # a bare number, no unit
    assert gb.read_text().splitlines()[1] == "s1,100.00,3,3"
    assert hist.read_text().startswith("<?xml")
    assert "s2" in out.read_text()
    assert not (tmp_path / "r.csv.journal").exists()


def test_grade_overrides_and_weights(tmp_path: Path) -> None:
    spec = tmp_path / "drum.dyn"
    spec.write_text(DRUM.read_text() + "\ngrading:\n  alpha weight 2\n")
    answers = _write(tmp_path, "student,alpha,T,a\ns1,11.3 rad/s^2,0 N,0 m/s^2\n")
    js = tmp_path / "r.json"
    result = runner.invoke(app, ["grade", str(spec), str(answers), "--json", str(js)])
    assert result.exit_code == 0, result.output
    assert json.loads(js.read_text())["students"][0]["score"] == 50.0  # 2 of 4 points
    result = runner.invoke(
        app, ["grade", str(spec), str(answers), "--json", str(js), "--sigfig", "4"]
    )
    part = json.loads(js.read_text())["students"][0]["parts"]["alpha"]
    assert part["verdict"] == "sigfig"  # 11.3 has 3 figures of the 4 asked


def test_grade_warns_about_columns_and_fails_cleanly(tmp_path: Path) -> None:
    answers = _write(tmp_path, "student,alpha,extra\ns1,11.3 rad/s^2,1\n")
    result = runner.invoke(app, ["grade", str(DRUM), str(answers)])
    assert result.exit_code == 0
    assert "column 'extra' is not a find" in result.output
    assert "no column for T" in result.output
    bad = _write(tmp_path, "name,alpha\ns1,1\n")
    result = runner.invoke(app, ["grade", str(DRUM), str(bad)])
    assert result.exit_code == 2 and "no student id column" in result.output
    twice = _write(tmp_path, "student,alpha\ns1,1\ns1,2\n")
    result = runner.invoke(app, ["grade", str(DRUM), str(twice)])
    assert result.exit_code == 2 and "appears twice" in result.output
    unit = _write(tmp_path, "student,alpha [blarg]\ns1,1\n")
    result = runner.invoke(app, ["grade", str(DRUM), str(unit)])
    assert result.exit_code == 2 and "blarg" in result.output
    result = runner.invoke(app, ["grade", str(DRUM), str(unit), "-o", str(DRUM)])
    assert result.exit_code == 2 and "input" in result.output


def test_resume_after_sigterm(tmp_path: Path) -> None:
    rows = ["student,alpha,T,a"]
    for i in range(8000):  # distinct cells: each is read, none is cached
        rows.append(
            f"s{i:05d},{11.29 + i * 1e-7:.7f} rad/s^2,106 N,{4.5 + i % 97 * 1e-3:.3f} m/s^2"
        )
    answers = _write(tmp_path, "\n".join(rows) + "\n")
    clean, killed = tmp_path / "clean.csv", tmp_path / "killed.csv"
    command = [sys.executable, "-m", "dynsolve", "grade", str(DRUM), str(answers)]
    subprocess.run([*command, "-o", str(clean), "--no-diagnose"], check=True, capture_output=True)
    process = subprocess.Popen([*command, "-o", str(killed), "--no-diagnose"])
    journal = tmp_path / "killed.csv.journal"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if journal.exists() and journal.stat().st_size > 20_000:
            break
        time.sleep(0.05)
    process.send_signal(signal.SIGTERM)
    process.wait(timeout=30)
    assert process.returncode != 0, "the run finished before it was killed"
    assert not killed.exists()
    finished = journal.read_text().count("\n") - 1
    assert 0 < finished < 8000
    resumed = subprocess.run(
        [*command, "-o", str(killed), "--no-diagnose", "--resume"],
        capture_output=True,
        text=True,
        env={**os.environ, "COLUMNS": "100"},
    )
    assert resumed.returncode == 0, resumed.stderr
    assert killed.read_bytes() == clean.read_bytes()


def test_resume_refuses_another_runs_journal(tmp_path: Path) -> None:
    answers = _write(tmp_path)
    out = tmp_path / "r.csv"
    (tmp_path / "r.csv.journal").write_text('{"fingerprint": "other"}\n')
    result = runner.invoke(app, ["grade", str(DRUM), str(answers), "-o", str(out), "--resume"])
    assert result.exit_code == 2 and "journal of another run" in result.output


@pytest.fixture
def two_specs(tmp_path: Path) -> Path:
    good = "given:\n  m = 2 kg\nequations:\n  W = m*g\nfind: W\nanswers:\n  W = 19.6 N\n"
    (tmp_path / "good.dyn").write_text(good)
    (tmp_path / "bad.dyn").write_text(good.replace("19.6 N", "25 N"))
    return tmp_path


def test_check_verbose_lists_passing_files(two_specs: Path) -> None:
    result = runner.invoke(app, ["check", str(two_specs), "-v"])
    assert result.exit_code == 1
    assert "passed  " in result.output and "good.dyn" in result.output
    quiet = runner.invoke(app, ["check", str(two_specs)])
    assert "passed  " not in quiet.output


def test_check_json(two_specs: Path) -> None:
    result = runner.invoke(app, ["check", str(two_specs), "--format", "json"])
    assert result.exit_code == 1
    document = json.loads(result.stdout)
    assert document["summary"] == {"passed": 1, "failed": 1, "malformed": 0}
    statuses = {Path(f["file"]).name: f["status"] for f in document["files"]}
    assert statuses == {"good.dyn": "passed", "bad.dyn": "failed"}


def test_check_junit(two_specs: Path) -> None:
    good = (two_specs / "good.dyn").read_text()
    (two_specs / "broken.dyn").write_text(good.replace("2 kg", "2 blarg"))
    result = runner.invoke(app, ["check", str(two_specs), "--format", "junit"])
    assert result.exit_code == 2
    suite = ElementTree.fromstring(result.stdout.split("\n", 1)[1])
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    cases = {Path(c.get("name")).name: c for c in suite.iter("testcase")}
    assert cases["bad.dyn"].find("failure") is not None
    assert "blarg" in cases["broken.dyn"].find("error").text
    assert list(cases["good.dyn"]) == []
