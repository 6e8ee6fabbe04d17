"""Plots of a kinematics problem: x, v and a against t (one line), the path and speed (plane).

The laws are the problem's own formulas with the givens' values put in, evaluated with numpy;
where a law has no formula (an a(v) or a(x) law that was not inverted) the motion is
integrated with scipy's ``solve_ivp`` instead. The time axis runs from t₀ to a little past
the latest time the problem mentions (a given or a found time), except a path, which ends
at that time (past a landing the path would run underground) with each found time marked on
it; axes are labelled with the spec's units (SI or FPS base units).

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.modes.kinematics_mode import build_kinematics_problem
>>> text = "given:\\n  c = 3 m/s^2\\n  t_1 = 2 s\\nkinematics:\\n  x = c*t^2\\nfind: v_1 = v(t_1)"
>>> spec = parse_spec(text, "k.dyn")
>>> image = motion_plot(build_kinematics_problem(spec))
>>> image[:4] == b"\\x89PNG"
True
"""

from __future__ import annotations

import io
import math
from collections.abc import Callable

import sympy

from dynsolve.errors import SpecError
from dynsolve.modes.kinematics_mode import KinematicsProblem
from dynsolve.numbers import real_value
from dynsolve.principles.rectilinear import T, V, X
from dynsolve.units import Dim, natural_unit

SAMPLES = 400
TIME = Dim.of("time")
LAWS = (("x", Dim.of("length")), ("v", Dim.of("velocity")), ("a", Dim.of("acceleration")))
FORMATS = (".png", ".svg", ".pdf")


def motion_plot(problem: KinematicsProblem, suffix: str = ".png") -> bytes:
    """The figure of ``problem``'s motion as an image in the format of ``suffix``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    values = dict(problem.system.knowns)
    system = problem.spec.system
    formulas = problem.motion.formulas
    plane = any(k in formulas for k in ("y(t)", "r(t)"))
    t_0, t_end = _time_span(problem, values, margin=0.0 if plane else 0.1)
    times = np.linspace(t_0, t_end, SAMPLES)
    if plane:
        marked = [t for _, t in _marks(problem, values)]
        curves = _plane(formulas, values, np.union1d(times, marked))
    else:
        curves = _line(problem, values, times)
    figure, axes = plt.subplots(len(curves), 1, figsize=(7, 2.4 * len(curves)))
    axes = np.atleast_1d(axes)
    for axis, (label, dim, xs, ys, x_label) in zip(axes, curves, strict=True):
        axis.plot(xs, ys)
        axis.set_ylabel(f"{label} [{natural_unit(dim, system)}]")
        axis.set_xlabel(x_label.format(unit=natural_unit(Dim.of("length"), system)))
        axis.grid(True, linewidth=0.3)
        if label == "y":
            axis.set_aspect("equal", adjustable="datalim")
            _mark_path(axis, xs, ys, _marks(problem, values), times=curves[1][2])
    axes[0].set_title(problem.spec.title or problem.spec.file)
    figure.tight_layout()
    buffer = io.BytesIO()
    figure.savefig(buffer, format=suffix.lstrip(".") or "png")
    plt.close(figure)
    return buffer.getvalue()


Curve = tuple[str, Dim, object, object, str]


def _line(problem: KinematicsProblem, values: dict, times: object) -> list[Curve]:
    """x, v and a against t of a one-line motion."""
    import numpy as np

    formulas, motion = problem.motion.formulas, problem.motion
    laws = {name: _law(formulas.get(f"{name}(t)"), values) for name, _ in LAWS}
    if (laws["x"] is None or laws["v"] is None) and motion.given.startswith("a("):
        x, v = _integrated(problem, values, times)
        laws["x"], laws["v"] = (lambda t: x), (lambda t: v)
        rate = _rate(formulas[motion.given], motion.given, values)
        laws["a"] = lambda t: np.array([rate(*args) for args in zip(t, x, v, strict=True)])
    out: list[Curve] = []
    for name, dim in LAWS:
        law = laws[name]
        if law is not None:
            out.append((name, dim, times, np.broadcast_to(law(times), np.shape(times)), "t [s]"))
    return out


def _plane(formulas: dict, values: dict, times: object) -> list[Curve]:
    """The path y(x) and the speed against t of a plane motion."""
    import numpy as np

    if "x(t)" in formulas:
        x, y = (_law(formulas[f"{c}(t)"], values) for c in "xy")
    else:
        r, theta = _law(formulas["r(t)"], values), _law(formulas["theta(t)"], values)
        if r is None or theta is None:
            raise _nothing("the path r(t), θ(t) has no values to draw")
        x = lambda t: r(t) * np.cos(theta(t))  # noqa: E731
        y = lambda t: r(t) * np.sin(theta(t))  # noqa: E731
    if x is None or y is None:
        raise _nothing("the path has no values to draw")
    xs = np.broadcast_to(x(times), np.shape(times))
    ys = np.broadcast_to(y(times), np.shape(times))
    speed = np.hypot(np.gradient(xs, times), np.gradient(ys, times))
    return [
        ("y", Dim.of("length"), xs, ys, "x [{unit}]"),
        ("speed", Dim.of("velocity"), times, speed, "t [s]"),
    ]


def _law(expr: sympy.Expr | None, values: dict) -> Callable | None:
    """``expr`` in t with the values put in, as a numpy function; None if symbols remain."""
    if expr is None:
        return None
    law = (sympy.Integer(0) + expr).xreplace(values)
    if law.free_symbols - {T}:
        return None
    return sympy.lambdify(T, law, "numpy")


def _rate(a: sympy.Expr, kind: str, values: dict) -> Callable:
    variable = {"a(t)": T, "a(v)": V, "a(x)": X}[kind]
    rate = sympy.lambdify(variable, a.xreplace(values), "math")
    return lambda t, x, v: rate({"a(t)": t, "a(v)": v, "a(x)": x}[kind])


def _integrated(problem: KinematicsProblem, values: dict, times: object) -> tuple[object, object]:
    """x and v at ``times`` by integrating the acceleration law (no formula to evaluate)."""
    from scipy.integrate import solve_ivp

    motion = problem.motion
    rate = _rate(motion.formulas[motion.given], motion.given, values)
    x_0, v_0 = (_given(problem, name, values) for name in ("x_0", "v_0"))
    start = float(times[0])  # type: ignore[index]
    run = solve_ivp(
        lambda t, s: [s[1], rate(t, s[0], s[1])],
        (start, float(times[-1])),  # type: ignore[index]
        [x_0, v_0],
        t_eval=times,
        method="DOP853",
        rtol=1e-10,
    )
    if run.status != 0:
        raise _nothing(f"the motion cannot be integrated over the plotted times ({run.message})")
    return run.y[0], run.y[1]


def _given(problem: KinematicsProblem, name: str, values: dict) -> float:
    symbol = problem.symbols.get(name)
    value = real_value(symbol, values) if symbol is not None else None
    return value or 0.0


def _marks(problem: KinematicsProblem, values: dict) -> list[tuple[str, float]]:
    """The found times (name, t) with a value, to mark on a path."""
    marks = []
    for target in problem.targets:
        if target.dim == TIME and target.expr is not None:
            t = real_value(target.expr, values)
            if t is not None and math.isfinite(t):
                marks.append((target.name, t))
    return marks


def _mark_path(axis: object, xs: object, ys: object, marks: list, times: object) -> None:
    """A dot and the found time's name where the path is at each found time."""
    import numpy as np

    for name, t in marks:
        i = int(np.argmin(np.abs(np.asarray(times) - t)))
        axis.plot([xs[i]], [ys[i]], "o", markersize=4)  # type: ignore[attr-defined]
        base, _, sub = name.partition("_")
        label = f"${base}_{{{sub}}}$" if sub.isalnum() and base.isalpha() else name
        axis.annotate(  # type: ignore[attr-defined]
            f"{label} = {t:.4g} s",
            (xs[i], ys[i]),
            textcoords="offset points",
            xytext=(-4, 6),
            ha="right",
        )


def _time_span(
    problem: KinematicsProblem, values: dict, margin: float = 0.1
) -> tuple[float, float]:
    """From t₀ to ``margin`` past the latest time a given or an answer names (1 s when none)."""
    t_0 = _given(problem, "t_0", values)
    latest = [g.value for g in problem.givens if g.dim == TIME and g.value is not None]
    latest = [real_value(v) for v in latest]
    latest += [
        real_value(t.expr, values) for t in problem.targets if t.dim == TIME and t.expr is not None
    ]
    later = [t for t in latest if t is not None and math.isfinite(t) and t > t_0]
    end = max(later) if later else t_0 + 1.0
    return t_0, t_0 + (1.0 + margin) * (end - t_0)


def _nothing(why: str) -> SpecError:
    return SpecError(f"nothing to plot: {why}", None, "give the givens values")


def not_plottable(file: str) -> SpecError:
    """The error for --plot on a spec without a ``kinematics:`` section."""
    return SpecError(
        f"--plot draws the motion of a kinematics: section (x, v, a against t, or a path); "
        f"{file} has none",
        None,
        hint="for a scene's travel use 'dynsolve simulate FILE --plot FIG.png'",
    )
