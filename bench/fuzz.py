"""Fuzz the parser and the solve path with many inputs under a time and a memory limit.

Inputs come from tests/fuzz_grammar.py (grammar-built specs and mutated bundled
problems), each reproducible from its index and the seed; a fraction go through
``dynsolve solve``, half as many through ``dynsolve simulate`` (0.2 s of motion).
They run in a worker subprocess whose address space is capped with RLIMIT_AS; the parent kills and
restarts the worker when an input passes the wall-clock limit or the worker dies.
Crashes (any exception other than DynsolveError, or a CLI exit code other than
0/1/2), hangs and memory-limit hits are counted and their inputs written to
bench/fuzz-crashes/ (git-ignored) with the traceback.

    nice -n 15 python bench/fuzz.py --count 100000 --solve-fraction 0.02
"""

from __future__ import annotations

import argparse
import json
import os
import random
import select
import subprocess
import sys
import time
import traceback
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from fuzz_grammar import bundled_problems, grammar_spec, mutated_problem  # noqa: E402

CRASHES = HERE / "fuzz-crashes"


def make_input(seed: int, index: int, solve_fraction: float, seeds: list[str]) -> tuple[str, str]:
    """The (stage, text) of input ``index``: stage is "parse" or "solve"."""
    rng = random.Random(seed * 1_000_003 + index)
    draw = rng.random()
    stage = "solve" if draw < solve_fraction else "parse"
    if solve_fraction <= draw < 1.5 * solve_fraction:  # half as many through simulate
        stage = "simulate"
    built = rng.random() < 0.5
    return stage, grammar_spec(rng) if built else mutated_problem(rng, seeds)


def run_one(stage: str, text: str, folder: Path) -> dict[str, str]:
    """Run one input in this process; classify the outcome."""
    from dynsolve.errors import DynsolveError
    from dynsolve.spec.parser import parse_spec

    try:
        if stage == "parse":
            parse_spec(text, "fuzz.dyn")
            return {"outcome": "ok"}
        if stage == "simulate":
            return _solve_cli(text, folder, ["simulate", "--t-end", "0.2 s", "--samples", "11"])
        return _solve_cli(text, folder)
    except DynsolveError:
        return {"outcome": "clean-error"}
    except MemoryError:
        return {"outcome": "memory"}
    except Exception:
        return {"outcome": "crash", "detail": traceback.format_exc()}


def _solve_cli(text: str, folder: Path, command: list[str] | None = None) -> dict[str, str]:
    """``dynsolve solve`` (or ``command``, e.g. simulate) on the text, classified."""
    from typer.testing import CliRunner

    from dynsolve.cli import app

    path = folder / "fuzz.dyn"
    path.write_text(text, encoding="utf-8")
    if command is None:
        arguments = ["solve", str(path), "--time-budget", "2"]
    else:
        arguments = [command[0], str(path), *command[1:]]
    result = CliRunner().invoke(app, arguments)
    error = result.exception
    if isinstance(error, MemoryError):
        return {"outcome": "memory"}
    if error is not None and not isinstance(error, SystemExit):
        detail = "".join(traceback.format_exception(type(error), error, error.__traceback__))
        return {"outcome": "crash", "detail": detail}
    if result.exit_code not in (0, 1, 2):
        return {"outcome": "crash", "detail": f"exit code {result.exit_code}\n{result.output}"}
    return {"outcome": {0: "ok", 1: "failed-check", 2: "clean-error"}[result.exit_code]}


def worker(memory_mb: int) -> None:
    """Read JSON inputs from stdin, answer one JSON outcome per line."""
    import resource
    import tempfile

    limit = memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    import dynsolve.cli  # noqa: F401  (import once, before timing the first input)

    with tempfile.TemporaryDirectory() as folder:
        print(json.dumps({"outcome": "ready"}), flush=True)
        for line in sys.stdin:
            job = json.loads(line)
            print(json.dumps(run_one(job["stage"], job["text"], Path(folder))), flush=True)


class Worker:
    """A worker subprocess, restarted on death or timeout."""

    def __init__(self, memory_mb: int) -> None:
        self.memory_mb = memory_mb
        self.process: subprocess.Popen[str] | None = None

    def start(self) -> None:
        command = [sys.executable, __file__, "--worker", "--memory-mb", str(self.memory_mb)]
        self.process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1
        )
        assert self._read(120.0) == {"outcome": "ready"}, "worker failed to start"

    def stop(self) -> None:
        if self.process is not None:
            self.process.kill()
            self.process.wait()
            self.process = None

    def run(self, stage: str, text: str, timeout: float) -> dict[str, str]:
        if self.process is None:
            self.start()
        assert self.process is not None and self.process.stdin is not None
        try:
            self.process.stdin.write(json.dumps({"stage": stage, "text": text}) + "\n")
            self.process.stdin.flush()
        except BrokenPipeError:
            self.stop()
            return {"outcome": "died"}
        answer = self._read(timeout)
        if answer is None:
            died = self.process.poll() is not None
            self.stop()
            return {"outcome": "died" if died else "hang"}
        return answer

    def _read(self, timeout: float) -> dict[str, str] | None:
        assert self.process is not None and self.process.stdout is not None
        ready, _, _ = select.select([self.process.stdout], [], [], timeout)
        if not ready:
            return None
        line = self.process.stdout.readline()
        return json.loads(line) if line else None


def signature(detail: str) -> str:
    """A crash's identity: its exception line and the innermost dynsolve frame."""
    lines = [line.strip() for line in detail.strip().splitlines()]
    frames = [line for line in lines if line.startswith("File") and "dynsolve" in line]
    return f"{lines[-1][:120]} @ {frames[-1] if frames else '?'}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--solve-fraction", type=float, default=0.02)
    parser.add_argument("--parse-timeout", type=float, default=5.0)
    parser.add_argument("--solve-timeout", type=float, default=30.0)
    parser.add_argument("--memory-mb", type=int, default=2048)
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.memory_mb)
        return
    seeds = bundled_problems()
    CRASHES.mkdir(exist_ok=True)
    outcomes: Counter[tuple[str, str]] = Counter()
    signatures: Counter[str] = Counter()
    runner = Worker(args.memory_mb)
    started = time.monotonic()
    for index in range(args.count):
        stage, text = make_input(args.seed, index, args.solve_fraction, seeds)
        timeout = args.solve_timeout if stage == "solve" else args.parse_timeout
        answer = runner.run(stage, text, timeout)
        outcome = answer["outcome"]
        outcomes[stage, outcome] += 1
        if outcome not in ("ok", "failed-check", "clean-error"):
            stem = CRASHES / f"{outcome}-{stage}-{args.seed}-{index}"
            stem.with_suffix(".dyn").write_text(text, encoding="utf-8")
            detail = answer.get("detail", outcome)
            stem.with_suffix(".txt").write_text(detail, encoding="utf-8")
            signatures[signature(detail) if outcome == "crash" else outcome] += 1
        if (index + 1) % 5000 == 0:
            print(f"{index + 1} inputs, {time.monotonic() - started:.0f} s", file=sys.stderr)
    runner.stop()
    elapsed = time.monotonic() - started
    print(f"{args.count} inputs in {elapsed:.0f} s (seed {args.seed})")
    for (stage, outcome), n in sorted(outcomes.items()):
        print(f"  {stage:5} {outcome:12} {n}")
    for each, n in signatures.most_common():
        print(f"  {n:6}  {each}")
    print(f"reproducers in {CRASHES}" if signatures else "no crashes, hangs or memory-limit hits")


if __name__ == "__main__":
    os.environ.setdefault("PYTHONHASHSEED", "0")
    main()
