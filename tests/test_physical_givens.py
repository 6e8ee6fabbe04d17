"""Physically impossible givens are refused, never solved (issue 25, item 9).

A drum given ``m_d = -60 kg`` was answered with its block rising at 57 m/s² (faster than
g), a crate given μk = −0.2 went faster than on a smooth floor, a negative radius of
gyration was accepted: every check green. A given's sign is fixed by its role in the
scene (the mass of a body, a coefficient of friction, a spring's stiffness …): one that
breaks it is a positioned error at the given (exit 2) with a hint. The mutation test at
the end negates (and, where zero is impossible, zeroes) every such given of every bundled
problem and asserts that none is built, let alone solved.
"""

import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.linkage.model import is_linkage
from dynsolve.pipeline import solve_text
from dynsolve.rigid3d.model import is_3d
from dynsolve.spec.ast import Given, Name, Spec
from dynsolve.spec.parser import parse_spec
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parent.parent
MODES = ["exact", "numeric", "auto"]

DRUM = (ROOT / "problems" / "seed" / "fa_hib_drum.dyn").read_text()

CRATE = """given:
  m = 20 kg
  mu_k = 0.2
  P = 100 N
  dt = 3 s
scene:
  body crate: particle, mass m, at (0, 0)
  contact crate at G: normal up, mu_k mu_k, slides right
  force P on crate at G: right
  gravity
  travel crate: for dt
find: v = speed(crate) [m/s]
"""


def _line_of(text: str, start: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if line.startswith(start))


@pytest.mark.parametrize("mode", MODES)
def test_a_negative_drum_mass_is_refused_at_the_given(mode: str, tmp_path: Path) -> None:
    # m_d = −60 kg would give I_O = m_d k_O² = −3.75 kg·m², α = m_b g r/(I_O + m_b r²)
    # = 78.48/(−0.55) < 0 and a block "rising" at |α| r = 57 m/s² > g: impossible. Refused.
    text = DRUM.replace("m_d = 60 kg", "m_d = -60 kg")
    spec = tmp_path / "drum.dyn"
    spec.write_text(text)
    result = CliRunner().invoke(app, ["solve", str(spec), "--mode", mode])
    assert result.exit_code == 2, result.output
    line = _line_of(text, "  m_d")
    assert f"drum.dyn:{line}:3" in result.output  # the given's own line and column
    assert "m_d = -60 kg is used as a mass" in result.output
    assert "cannot be negative" in result.output and "hint" in result.output


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize(
    ("old", "new", "role"),
    [
        ("mu_k = 0.2", "mu_k = -0.2", "μk"),  # faster than smooth: 17.4 vs 13.0 m/s
        ("m = 20 kg", "m = 0 kg", "a mass"),  # the only body, with no inertia
    ],
)
def test_impossible_crate_givens_are_refused(mode: str, old: str, new: str, role: str) -> None:
    with pytest.raises(SpecError) as error:
        solve_text(CRATE.replace(old, new), options=SolveOptions(mode=mode))
    assert f"is used as {role}" in error.value.message
    assert error.value.position is not None
    assert error.value.position.line == _line_of(CRATE, "  " + old.split(" ")[0])


@pytest.mark.parametrize("mode", MODES)
def test_zero_friction_is_legitimate(mode: str) -> None:
    # μk = 0 is a smooth floor: v = P Δt/m = 100·3/20 = 15 m/s.
    solution = solve_text(CRATE.replace("mu_k = 0.2", "mu_k = 0"), options=SolveOptions(mode=mode))
    assert float(solution.answers[0].value) == pytest.approx(15.0, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_negative_gyration_and_gravity_are_refused(mode: str) -> None:
    for old, new, role in [
        ("k_O = 0.25 m", "k_O = -0.25 m", "a radius of gyration"),
        ("g   = 9.81 m/s^2", "g   = -9.81 m/s^2", "gravity g"),
    ]:
        with pytest.raises(SpecError, match=role):
            solve_text(DRUM.replace(old, new), options=SolveOptions(mode=mode))


# ---- the mutation test over the bundled problems

# zero is legitimate: smooth, no free length, a massless pulley (inertia 0: newcomer round 7)
NEGATE_ONLY = {"mu_s", "mu_k", "unstretched", "inertia", "gyration"}
ROLE_PROPS = {"mass", "weight", "gyration", "inertia", "density", "thickness", "k", "length"}


def _roles(spec: Spec) -> dict[str, bool]:
    """Each given used alone in a role whose sign physics fixes, read from the scene's text
    (independently of dynsolve's builder): name → whether zero is impossible there too.
    A mass of zero is a massless pulley or link beside bodies with mass: impossible only
    for the one body of a plane scene, and for a 3D body (its inertia tensor)."""
    givens = {g.name for g in spec.givens if g.quantity is not None}
    roles: dict[str, bool] = {}
    massive = [s for s in spec.scene if any(p.key in ("mass", "weight") for p in s.props)]
    lone = is_3d(spec) or (not is_linkage(spec) and len(massive) == 1)

    def note(expr: object, zero_impossible: bool) -> None:
        if isinstance(expr, Name) and expr.text in givens:
            roles[expr.text] = roles.get(expr.text, True) and zero_impossible

    for stmt in spec.scene:
        for prop in stmt.props:
            shape = prop.key == "shape" and stmt.kind != "hole"
            if prop.key in ROLE_PROPS | NEGATE_ONLY or shape:
                zero_impossible = lone if prop.key in ("mass", "weight") else True
                for value in prop.values:
                    note(value, zero_impossible and prop.key not in NEGATE_ONLY)
        if stmt.kind == "gravity":
            note(Name("g", stmt.line, stmt.column), True)
        if stmt.kind == "travel" and stmt.word == "for":
            note(stmt.value, True)
        if stmt.kind == "wheel":
            note(stmt.value, True)
        if stmt.kind == "mesh":
            for value in stmt.vectors[0] if stmt.vectors else ():
                note(value, True)
    return roles


def _mutated(text: str, given: Given, number: str) -> str:
    """The spec's text with ``given``'s number replaced by ``number``."""
    assert given.quantity is not None
    lines = text.splitlines(keepends=True)
    q = given.quantity
    line = lines[q.line - 1]
    start = q.column - 1
    assert line[start : start + len(q.text)] == q.text
    lines[q.line - 1] = line[:start] + number + line[start + len(q.text) :]
    return "".join(lines)


def _build(spec: Spec) -> object:
    """Read the spec's model and equations, without solving them."""
    if is_3d(spec):
        from dynsolve.rigid3d.problem import build_3d_problem

        return build_3d_problem(spec)
    if is_linkage(spec):
        from dynsolve.linkage.problem import build_linkage_problem

        return build_linkage_problem(spec)
    from dynsolve.modes.scene_mode import build_scene_problem

    return build_scene_problem(spec)


def _bundled() -> list[Path]:
    return sorted(p for p in (ROOT / "problems").rglob("*.dyn") if "scene:" in p.read_text())


def test_every_bundled_role_given_negated_or_zeroed_is_refused() -> None:
    started = time.process_time()
    mutations, escaped = 0, []
    for path in _bundled():
        text = path.read_text()
        spec = parse_spec(text, str(path))
        by_name = {g.name: g for g in spec.givens}
        for name, zero_impossible in _roles(spec).items():
            given = by_name[name]
            assert given.quantity is not None
            if float(given.quantity.text.split()[0]) == 0:
                continue  # a zero (a pulley given inertia 0) has no negative to try
            numbers = ["-" + given.quantity.text] + (["0"] if zero_impossible else [])
            for number in numbers:
                mutations += 1
                mutated = parse_spec(_mutated(text, given, number), str(path))
                try:
                    _build(mutated)
                except SpecError as error:
                    assert error.position is not None and error.position.line == given.line
                    continue
                escaped.append(f"{path.name}: {name} = {number}")
    print(f"{mutations} mutations in {time.process_time() - started:.1f} s CPU")
    assert mutations > 150  # the bundled scenes hold this many such givens
    assert not escaped, escaped
    assert time.process_time() - started < 60  # parse and build only: no solve


def test_a_mutated_bundled_problem_exits_2_through_the_cli(tmp_path: Path) -> None:
    # the full path (solve command) for one mutation of each kind of front end
    for name in ["problems/scenes/bungee.dyn", "problems/linkages/slider_crank_forces.dyn"]:
        path = ROOT / name
        spec = parse_spec(path.read_text(), str(path))
        role = next(iter(_roles(spec)))
        given = next(g for g in spec.givens if g.name == role)
        mutated = tmp_path / path.name
        mutated.write_text(_mutated(path.read_text(), given, "-" + given.quantity.text))
        result = CliRunner().invoke(app, ["solve", str(mutated)])
        assert result.exit_code == 2, (name, role, result.output)
        assert f"{path.name}:{given.line}:{given.column}" in result.output


@pytest.mark.parametrize("mode", MODES)
def test_a_pulley_given_inertia_zero_is_legitimate(mode: str) -> None:
    """Newcomer round 7: `I_0 = 0 kg*m^2` for a massless movable pulley was refused ("must
    be positive"). By hand (massless pulleys, s_A + 2 s_B = const, so a_A = 2 a_B):
    T = m_A a_A and m_B g - 2 T = m_B a_B give a_B = m_B g/(m_B + 4 m_A) = 196.2/60
    = 3.27 m/s^2 and a_A = 6.54 m/s^2 (m_A = 10 kg, m_B = 20 kg)."""
    path = Path(__file__).parent.parent / "problems/scenes/movable_pulley_inertia_zero.dyn"
    solution = solve_text(path.read_text(), path.name, options=SolveOptions(mode=mode))
    values = {a.name: float(a.value) for a in solution.answers}
    assert values["a_A"] == pytest.approx(6.54, rel=1e-9)
    assert values["a_B"] == pytest.approx(3.27, rel=1e-9)
    assert {a.name: a.direction for a in solution.answers}["a_B"] == "down"
