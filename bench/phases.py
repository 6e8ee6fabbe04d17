"""Where a solve spends its CPU time: each second charged to the innermost phase running.

A phase is a function of dynsolve's pipeline (building the model, the solve, tidying a
form, a second method, ...). :func:`timing` wraps those functions for the duration of a
``with`` block; every CPU second is charged to the innermost phase active at the time
(exclusive time, so the phases add up to the whole), the rest to ``other``. Used by
``bench/accuracy.py --phases`` to show what numeric mode shares with exact mode.

    >>> from collections import Counter
    >>> seconds = Counter()
    >>> with timing(seconds):
    ...     import dynsolve.numbers, sympy
    ...     _ = dynsolve.numbers.tidy(sympy.Symbol("a") * 2 + sympy.Symbol("a"))
    >>> set(seconds) <= set(PHASES) | {"other"}
    True
"""

from __future__ import annotations

import importlib
import sys
import time
from collections import Counter
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

# phase name: (module, function); a function another module imported by name is wrapped
# there too
PHASES: dict[str, tuple[str, str]] = {
    "build: scene": ("dynsolve.modes.scene_mode", "build_scene_problem"),
    "build: 3D scene": ("dynsolve.rigid3d.problem", "build_3d_problem"),
    "build: linkage": ("dynsolve.linkage.problem", "build_linkage_problem"),
    "build: kinematics": ("dynsolve.modes.kinematics_mode", "build_kinematics_problem"),
    "build: equations": ("dynsolve.modes.equation_mode", "build_problem"),
    "solve": ("dynsolve.solver", "solve_system"),
    "tidy": ("dynsolve.numbers", "_tidied"),
    "check: 3D second methods": ("dynsolve.rigid3d.problem", "moment_check"),
    "check: scene second methods": ("dynsolve.modes.scene_mode", "cross_checks"),
    "check: linkage second methods": ("dynsolve.linkage.problem", "cross_checks"),
    "check: assumptions": ("dynsolve.modes.scene_mode", "assess"),
    "check: simulation": ("dynsolve.simulate.legs", "simulation_checks"),
    "show: second moment rows": ("dynsolve.modes.scene_mode", "second_moment_rows"),
    "show: 3D second moment rows": ("dynsolve.rigid3d.problem", "second_moment_rows"),
    "show: answers, key, rows": ("dynsolve.pipeline", "solve_problem"),
}


@contextmanager
def timing(seconds: Counter[str]) -> Iterator[None]:
    """Charge the CPU time of the block to :data:`PHASES` (innermost first) in ``seconds``."""
    stack: list[list[Any]] = [["other", time.process_time()]]

    def wrapped(name: str, function: Callable[..., Any]) -> Callable[..., Any]:
        def run(*args: Any, **kwargs: Any) -> Any:
            now = time.process_time()
            seconds[stack[-1][0]] += now - stack[-1][1]  # the phase it interrupts
            stack.append([name, now])
            try:
                return function(*args, **kwargs)
            finally:
                now = time.process_time()
                done, since = stack.pop()
                seconds[done] += now - since
                stack[-1][1] = now  # the interrupted phase resumes

        return run

    patched: list[tuple[object, str, Callable[..., Any]]] = []
    for name, (module_name, attribute) in PHASES.items():
        module = importlib.import_module(module_name)
        original = getattr(module, attribute)
        replacement = wrapped(name, original)
        for holder in list(sys.modules.values()):
            if getattr(holder, "__name__", "").startswith("dynsolve") and (
                getattr(holder, attribute, None) is original
            ):
                patched.append((holder, attribute, original))
                setattr(holder, attribute, replacement)
    try:
        yield
    finally:
        for holder, attribute, original in patched:
            setattr(holder, attribute, original)
        seconds[stack[0][0]] += time.process_time() - stack[0][1]
