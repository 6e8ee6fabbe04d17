"""The run budget: CPU time and memory for the whole run, the step named when it runs out.

The CLI tests go through CliRunner (in-process; the worker is forked from the test
process). drag_fall takes about 4 s on this machine, far beyond half a second.
"""

from __future__ import annotations

import os
import shutil
import signal
import threading
import time
from pathlib import Path

import pytest
import sympy
from specs import DRUM
from typer.testing import CliRunner, Result

from dynsolve import budget
from dynsolve.budget import Budget, OverBudget, WorkerFailed, run, run_each, step
from dynsolve.cli import ExitCode, _Done, _Target, app, solve_and_render
from dynsolve.solver.blocks import BudgetExceeded, time_budget

ROOT = Path(__file__).resolve().parent.parent
SLOW = ROOT / "tests" / "data" / "slow_inversion.dyn"  # seconds in sympy's inversion
DRUM_FILE = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"


def cli(*args: str) -> Result:
    return CliRunner().invoke(app, list(args), env={"COLUMNS": "300"})  # tables unwrapped


def _sleep_in_a_step(seconds: float) -> str:
    with step("counting sheep"):
        time.sleep(seconds)
    return "awake"


def _burn_in_a_step(seconds: float) -> str:
    """Compute (use the CPU) for ``seconds`` of this process's CPU time."""
    with step("counting sheep"):
        deadline = time.process_time() + seconds
        while time.process_time() < deadline:
            sum(range(1000))
    return "tired"


def _allocate(megabytes: int) -> int:
    with step("allocating"):
        return len(bytearray(megabytes * 1024 * 1024))


def _raise() -> None:
    raise ZeroDivisionError("a bug")


def test_a_long_run_is_stopped_and_names_its_step():
    started = time.monotonic()
    with pytest.raises(OverBudget, match=r"time budget of 0\.5 s, while counting sheep") as info:
        run(_burn_in_a_step, (30.0,), Budget(seconds=0.5))
    assert time.monotonic() - started < 10
    assert info.value.step == "counting sheep"
    assert "--mode numeric" in info.value.hint and "--time-budget" in info.value.hint


@pytest.mark.skipif(budget.cpu_seconds(os.getpid()) is None, reason="no /proc: wall time")
def test_waiting_for_the_cpu_does_not_spend_the_budget():
    # a worker that waits (as on a busy machine, where it waits for a core) past its
    # budget of CPU seconds is not stopped: the budget counts the CPU it used
    assert run(_sleep_in_a_step, (1.5,), Budget(seconds=0.5)) == "awake"


def test_a_hang_is_stopped_by_the_wall_clock_backstop():
    started = time.monotonic()
    with pytest.raises(OverBudget, match=r"backstop against a hang .* while counting sheep"):
        run(_sleep_in_a_step, (60.0,), Budget(seconds=0.1))
    # the backstop: 10 × 0.1 s, at least 10 s more than the budget
    assert 10.0 <= time.monotonic() - started < 30


def test_a_run_within_the_budget_returns_its_result():
    assert run(_sleep_in_a_step, (0.01,), Budget(seconds=30)) == "awake"


def test_a_memory_hog_is_stopped():
    pytest.importorskip("resource")
    # 4 GB against a 512 MB address-space limit: MemoryError in the worker, not in the tests
    with pytest.raises(OverBudget, match="memory budget of 512 MB, while allocating"):
        run(_allocate, (4096,), Budget(seconds=60, megabytes=512))


def test_each_job_gets_the_budget_and_a_stopped_worker_is_replaced():
    outcomes = list(run_each(_burn_in_a_step, [(0.01,), (30.0,), (0.01,)], Budget(seconds=1)))
    assert outcomes[0] == "tired" and outcomes[2] == "tired"
    assert isinstance(outcomes[1], OverBudget)


def test_a_bug_in_the_worker_comes_back_with_its_traceback():
    with pytest.raises(WorkerFailed, match="ZeroDivisionError: a bug"):
        run(_raise, (), Budget(seconds=30))


def test_steps_nest_and_restore():
    with step("outer"):
        with step("inner"):
            pass
        with pytest.raises(OverBudget, match="while inner"):
            run(_nested_steps, (), Budget(seconds=0.5))


def _nested_steps() -> None:
    with step("outer"), step("inner"):
        deadline = time.process_time() + 30
        while time.process_time() < deadline:
            sum(range(1000))


def test_solve_past_the_time_budget_exits_2_naming_the_step():
    result = cli("solve", str(SLOW), "--time-budget", "0.5")
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "error: stopped after the time budget of 0.5 s, while " in result.stderr
    assert "try --mode numeric, or a larger --time-budget" in result.stderr
    assert result.stdout == ""


def test_check_goes_on_past_a_spec_over_the_budget(tmp_path: Path):
    shutil.copy(SLOW, tmp_path / "a_slow.dyn")
    (tmp_path / "b_drum.dyn").write_text(DRUM, encoding="utf-8")
    result = cli("check", str(tmp_path), "--time-budget", "1")
    out = " ".join(result.stdout.split())
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "a_slow.dyn" in out and "time budget of 1 s" in out, out
    assert result.stdout.strip().splitlines()[-1] == "1 passed, 0 failed, 1 malformed"


@pytest.mark.parametrize("value", ["0", "-1", "1e9"])
def test_budgets_out_of_range_are_bad_input(value: str):
    assert cli("solve", str(SLOW), "--time-budget", value).exit_code == 2
    assert cli("solve", str(SLOW), "--memory-budget", value).exit_code == 2


def test_the_block_budget_works_without_signals_in_another_thread():
    # the cooperative path (as on Windows, where there is no SIGPROF)
    x = sympy.Symbol("x")
    outcome: list[str] = []

    def solve_hard() -> None:
        started = time.monotonic()
        try:
            with time_budget(0.3):
                sympy.solve(x**7 + x**3 * sympy.sin(x) - sympy.exp(x) + 3, x)
            outcome.append("finished")
        except BudgetExceeded:
            outcome.append(f"stopped after {time.monotonic() - started:.1f} s")

    worker = threading.Thread(target=solve_hard)
    worker.start()
    worker.join(60)
    # 0.3 s of CPU time: well under 10 s of wall time even on a busy machine
    assert outcome and outcome[0].startswith("stopped after ")
    assert float(outcome[0].split()[2]) < 10


def test_the_spawn_start_method_of_macos_and_windows_works(monkeypatch: pytest.MonkeyPatch):
    # a fresh interpreter imports the job by name: what runs on macOS and Windows
    monkeypatch.setattr(budget, "START_METHOD", "spawn")
    target = _Target("json", True, 80, False, None)
    outcome = run(solve_and_render, (("file", str(DRUM_FILE)), "exact", Budget(), target), Budget())
    assert isinstance(outcome, _Done) and outcome.exit_code == ExitCode.OK
    # Hibbeler 17.11: T = 106 N (14715/139 N by hand, see tests/test_cli.py)
    assert '"T"' in outcome.text and "105.86" in outcome.text
    with pytest.raises(OverBudget, match="while counting sheep"):
        run(_burn_in_a_step, (60.0,), Budget(seconds=8))  # spawn imports sympy first


def _spin(seconds: float) -> None:
    end = time.process_time() + seconds
    while time.process_time() < end:
        pass


@pytest.mark.skipif(not hasattr(signal, "setitimer"), reason="no setitimer here")
def test_the_budget_never_raises_inside_a_gc_callback() -> None:
    """CI failed once with 'Failed to process unraisable exception': the block's budget
    expired while Python ran hypothesis's garbage-collection callback, so BudgetExceeded
    was raised where nothing could catch it. It now waits for the next expiry (0.1 s of
    CPU later), outside the callback, and the block still stops."""
    import gc
    import sys

    unraisable: list[object] = []

    def slow(phase: str, info: object) -> None:
        if phase == "start":
            _spin(0.3)  # the 0.05 s budget expires in here

    previous = sys.unraisablehook
    sys.unraisablehook = lambda args: unraisable.append(args.exc_type)
    gc.callbacks.append(slow)
    try:
        with pytest.raises(BudgetExceeded), time_budget(0.05):
            gc.collect()
            _spin(2.0)  # the work after the collection is stopped
    finally:
        gc.callbacks.remove(slow)
        sys.unraisablehook = previous
    assert unraisable == []
