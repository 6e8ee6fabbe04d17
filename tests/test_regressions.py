"""One regression test per bug fixed; the specs live in tests/data/regression/.

- collar_symbolic_root_sign: `k*delta_1^2/2 = m*v_0^2/2` with `v_0 >= 0` kept the
  negative root because sympy cannot decide sqrt(L^2 + s^2) - L > 0 (fixed by
  sampling positive givens in the root filter).
- bar_shaft_symbolic_cos_root: `I_B*Omega^2*cos(theta_s) = m*g*L/2` with
  0 < theta_s < pi/2 kept 2*pi - acos(...) (same fix).
- cube_formula_names_an_unknown: a formula key `omega_1 = 3*v_min/(8*a)` was
  rejected because it names another answer (formula keys may now use solved unknowns).
- tilted_gear_dimension_from_key: unknowns whose dimension the equations leave open
  (A_lat + B_lat = 0) stopped the solve although they were not asked for.
"""

from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file

REGRESSION = Path(__file__).resolve().parent / "data" / "regression"


@pytest.mark.parametrize("spec", sorted(p.name for p in REGRESSION.glob("*.dyn")))
def test_regression_spec_passes(spec):
    solution = solve_file(REGRESSION / spec)
    failed = [f"{c.name}: {c.detail}" for c in solution.checks if c.failed]
    assert not failed, failed
    assert solution.key, "each regression spec carries an answer key"
