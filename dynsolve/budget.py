"""The run budget: one unit of work in a worker process, stopped past its CPU time or memory.

The worker is a child process (``fork`` on Linux, so it starts with the parent's
modules already imported; ``spawn`` elsewhere), so parsing, solving, symbolic
simplification, the numeric fallbacks and rendering are all covered, on every
platform, without signals. The time budget counts the worker's CPU seconds (read from
``/proc`` where it exists), so a busy machine, which slows the wall clock, never turns
a solve that would finish into a failure; a generous wall-clock backstop
(:data:`WALL_FACTOR` times the budget, at least :data:`WALL_SLACK` s more) still stops
a worker that hangs without using the CPU. Where ``/proc`` is missing (macOS,
Windows) the budget is wall time. Where ``resource.RLIMIT_AS`` exists the child's
address space is capped, so an allocation past the budget raises MemoryError
there instead of swapping the machine. The child names the step it is in with
:func:`step`; the parent keeps the latest name, kills the child at the deadline
and raises :class:`OverBudget` naming that step.

>>> run(sum, ([1, 2, 3],), Budget(seconds=30))
6
"""

from __future__ import annotations

import multiprocessing
import os
import sys
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from multiprocessing.connection import Connection
from typing import Any, TypeVar

from dynsolve.errors import DynsolveError

DEFAULT_SECONDS = 60.0  # every bundled problem takes under 1.5 s cold (docs/benchmarks.md)
DEFAULT_MEGABYTES = 2048  # address space of the worker, libraries included
# fork starts the worker with the parent's modules in ~5 ms; macOS and Windows have
# only spawn (a fresh interpreter) as a safe choice
START_METHOD = "fork" if sys.platform.startswith("linux") else "spawn"
_KILL_GRACE = 2.0  # seconds the child gets to exit after being terminated
WALL_FACTOR = 10.0  # the wall-clock backstop: this many times the CPU budget …
WALL_SLACK = 10.0  # … and at least this many seconds more than it (a load of 9 on 2
# cores gives a worker about a fifth of a core: 1 s of CPU takes some 5 s)
_POLL = 0.05  # wall seconds between two reads of the worker's CPU time

_Result = TypeVar("_Result")
_channel: Connection | None = None  # set in the worker: where step names go
_current = ["starting"]
_out_of_memory_in = [""]  # the step a MemoryError came from, in the worker


@dataclass(frozen=True)
class Budget:
    """CPU seconds and megabytes of address space for one run (None: no memory cap)."""

    seconds: float = DEFAULT_SECONDS
    megabytes: int | None = DEFAULT_MEGABYTES


class WorkerFailed(RuntimeError):
    """The work raised an unexpected exception in the worker (a bug); its traceback as text."""


class OverBudget(DynsolveError):
    """The work ran past its time or memory budget; ``step`` names what it was doing."""

    def __init__(self, message: str, step: str, hint: str) -> None:
        super().__init__(message, hint=hint)
        self.step = step


@contextmanager
def step(name: str) -> Iterator[None]:
    """Name what the work is doing (reported if the budget runs out); the previous name after.

    >>> with step("parsing"):
    ...     current_step()
    'parsing'
    """
    previous = _current[0]
    _announce(name)
    try:
        yield
    except MemoryError:
        _out_of_memory_in[0] = _out_of_memory_in[0] or name  # the innermost step
        raise
    finally:
        _announce(previous)


def current_step() -> str:
    """The step most recently announced in this process."""
    return _current[0]


def run(work: Callable[..., _Result], args: tuple[Any, ...], budget: Budget) -> _Result:
    """``work(*args)`` in a worker process under ``budget``; its (picklable) result.

    Raises OverBudget past the time or memory budget, WorkerFailed when ``work``
    raised. ``work`` must be a module-level function (``spawn`` pickles it).
    """
    (outcome,) = run_each(work, [args], budget)
    if isinstance(outcome, BaseException):
        raise outcome
    return outcome


def run_each(
    work: Callable[..., _Result], jobs: Sequence[tuple[Any, ...]], budget: Budget
) -> Iterator[_Result | OverBudget | WorkerFailed]:
    """``work(*args)`` for each ``args`` of ``jobs``, in order, each under the whole ``budget``.

    One worker runs job after job (so caches stay warm); a worker stopped by the
    budget is replaced by a new one for the next job. Yields each result, or the
    OverBudget or WorkerFailed that ended that job.

    >>> list(run_each(abs, [(-1,), (2,)], Budget(seconds=30)))
    [1, 2]
    """
    context = multiprocessing.get_context(START_METHOD)
    first = 0
    while first < len(jobs):
        receiver, sender = context.Pipe(duplex=False)
        worker = context.Process(
            target=_work_in_child, args=(sender, work, jobs[first:], budget), daemon=True
        )
        worker.start()
        sender.close()
        try:
            for outcome in _outcomes(receiver, worker, budget, len(jobs) - first):
                first += 1
                yield outcome
        finally:
            receiver.close()
            _stop(worker)


def _outcomes(receiver: Connection, worker: Any, budget: Budget, count: int) -> Iterator[Any]:
    """The outcome of each job the worker runs, ending at the first that stops the worker."""
    for _ in range(count):
        started = time.monotonic()
        cpu_before = cpu_seconds(worker.pid)  # None: no CPU clock of the worker, wall time
        backstop = started + (
            budget.seconds
            if cpu_before is None
            else max(budget.seconds * WALL_FACTOR, budget.seconds + WALL_SLACK)
        )
        last_step = "starting"
        while True:
            now = time.monotonic()
            if _used(worker.pid, cpu_before, now - started) >= budget.seconds:
                yield _over_time(budget, last_step)
                return
            if now >= backstop:
                yield _over_wall_time(budget, now - started, last_step)
                return
            if not receiver.poll(min(_POLL, backstop - now)):
                continue
            try:
                kind, payload = receiver.recv()
            except EOFError:
                worker.join(_KILL_GRACE)
                yield _died(budget, last_step, worker.exitcode)
                return
            if kind == "step":
                last_step = payload
                continue
            if kind == "memory":
                yield _over_memory(budget, payload)
                return
            yield payload if kind == "done" else WorkerFailed(payload)
            break


def _used(pid: int | None, cpu_before: float | None, wall: float) -> float:
    """The seconds of the budget a job has used: the worker's CPU seconds since
    ``cpu_before``, or ``wall`` seconds where there is no CPU clock of it (0 once the
    worker is gone: its end is read from the pipe)."""
    if cpu_before is None:
        return wall
    now = cpu_seconds(pid)
    return 0.0 if now is None else now - cpu_before


_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def cpu_seconds(pid: int | None) -> float | None:
    """The CPU seconds (user + system) process ``pid`` has used, from ``/proc`` (Linux);
    None where that cannot be read (another platform, or the process is gone).

    >>> cpu_seconds(os.getpid()) is None or cpu_seconds(os.getpid()) >= 0
    True
    """
    if pid is None:
        return None
    try:
        with open(f"/proc/{pid}/stat", "rb") as stat:
            fields = stat.read().rsplit(b")", 1)[1].split()
    except (OSError, IndexError):
        return None
    # after the command's ")": state is field 3, utime 14 and stime 15 (man 5 proc)
    return (int(fields[11]) + int(fields[12])) / _TICKS


def _work_in_child(
    sender: Connection,
    work: Callable[..., object],
    jobs: Sequence[tuple[Any, ...]],
    budget: Budget,
) -> None:
    global _channel
    _channel = sender
    _limit_memory(budget.megabytes)
    for args in jobs:
        _current[0], _out_of_memory_in[0] = "starting", ""
        try:
            result = work(*args)
        except MemoryError:
            sender.send(("memory", _out_of_memory_in[0] or _current[0]))
            return  # the heap may be in pieces: a new worker takes the next job
        except BaseException:
            sender.send(("error", traceback.format_exc()))
            continue
        sender.send(("done", result))


def _limit_memory(megabytes: int | None) -> None:
    """Cap the address space where the platform allows it (Linux; not Windows)."""
    if megabytes is None:
        return
    try:
        import resource
    except ImportError:  # Windows: only the time budget applies
        return
    limit = megabytes * 1024 * 1024
    try:
        _soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        if hard != resource.RLIM_INFINITY:
            limit = min(limit, hard)
        resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    except (ValueError, OSError, AttributeError):  # macOS may refuse RLIMIT_AS
        return


def _announce(name: str) -> None:
    _current[0] = name
    if _channel is not None:
        _channel.send(("step", name))


def _stop(worker: Any) -> None:
    if worker.is_alive():
        worker.terminate()
        worker.join(_KILL_GRACE)
    if worker.is_alive():
        worker.kill()
    worker.join()


SIMULATING = "integrating the motion in time (solve_ivp)"


def _over_time(budget: Budget, step: str) -> OverBudget:
    hint = (
        "try a looser --rtol, a shorter --t-end, or a larger --time-budget"
        if step == SIMULATING
        else "try --mode numeric, or a larger --time-budget"
    )
    return OverBudget(
        f"stopped after the time budget of {budget.seconds:g} s, while {step}",
        step,
        hint=hint,
    )


def _over_wall_time(budget: Budget, seconds: float, step: str) -> OverBudget:
    return OverBudget(
        f"stopped after {seconds:.3g} s of wall time, the backstop against a hang (the time "
        f"budget is {budget.seconds:g} s of CPU), while {step}",
        step,
        hint="the worker was waiting, not computing: try again, or a larger --time-budget",
    )


def _over_memory(budget: Budget, step: str) -> OverBudget:
    return OverBudget(
        f"stopped at the memory budget of {budget.megabytes} MB, while {step}",
        step,
        hint="try --mode numeric, or a larger --memory-budget",
    )


def _died(budget: Budget, step: str, exit_code: int | None) -> OverBudget | WorkerFailed:
    if budget.megabytes is not None:  # an allocation the C library could not satisfy
        return OverBudget(
            f"the worker stopped (exit code {exit_code}) while {step}, "
            f"probably at the memory budget of {budget.megabytes} MB",
            step,
            hint="try --mode numeric, or a larger --memory-budget",
        )
    return WorkerFailed(f"the worker stopped (exit code {exit_code}) while {step}")
