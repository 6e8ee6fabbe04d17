"""Cold start: what a command imports (regression tests for issue 14's lazy imports).

Timings are measured by bench/cold_start.py; these tests pin the imports that made
the difference, in fresh interpreters.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = ("sympy", "scipy", "numpy", "pydantic", "lark", "mpmath", "matplotlib", "pint")


def _modules_after(code: str, env: dict[str, str] | None = None) -> set[str]:
    probe = code + "\nimport json, sys; print(json.dumps(sorted(sys.modules)))"
    done = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, check=True, cwd=ROOT, env=env
    )
    return {name.split(".")[0] for name in json.loads(done.stdout.splitlines()[-1])}


def test_the_command_line_imports_nothing_heavy_before_a_command_runs() -> None:
    # `dynsolve --help` and `--version` import only the CLI module: no solver libraries
    loaded = _modules_after("import dynsolve.cli")
    assert not loaded & set(HEAVY), loaded & set(HEAVY)


def _warm(code: str, tmp_path: Path) -> dict[str, str]:
    """An environment with its own unit cache, filled by one run of ``code`` (a cold cache
    imports pint, which imports numpy and scipy when they are installed)."""
    env = {**os.environ, "DYNSOLVE_CACHE_DIR": str(tmp_path)}
    _modules_after(code, env)
    return env


def test_a_scene_at_an_instant_does_not_import_the_simulation_libraries(tmp_path: Path) -> None:
    # the drum (Hibbeler 17.11) has no travel: nothing to simulate, so no numpy/scipy
    code = "from dynsolve.pipeline import solve_file\nsolve_file('problems/seed/fa_hib_drum.dyn')"
    loaded = _modules_after(code, _warm(code, tmp_path))
    assert "sympy" in loaded
    assert not loaded & {"scipy", "numpy", "matplotlib", "pydantic"}


def test_a_warm_run_does_not_import_pint(tmp_path: Path) -> None:
    # the unit cache answers every lookup of a spec solved before (units._UnitCache)
    code = "from dynsolve.pipeline import solve_file\nsolve_file('problems/seed/fa_hib_drum.dyn')"
    env = {**os.environ, "DYNSOLVE_CACHE_DIR": str(tmp_path)}
    assert "pint" in _modules_after(code, env)  # a first run fills the empty cache
    assert "pint" not in _modules_after(code, env)


def test_scenes_with_nothing_to_integrate_do_not_import_scipy(tmp_path: Path) -> None:
    # symbolic givens, or an interval of constant forces: the cross-check only notes why
    # it is not simulated (dynsolve.simulate.legs), so scipy's 0.35 s import is not paid
    # (an 'until' event on a circle is integrated since: it pays for a real check)
    for spec in ("seed/we_seed_collar-symbolic.dyn", "scenes/disk_backspin_rolls.dyn"):
        code = f"from dynsolve.pipeline import solve_file\nsolve_file('problems/{spec}')"
        assert "scipy" not in _modules_after(code, _warm(code, tmp_path)), spec
