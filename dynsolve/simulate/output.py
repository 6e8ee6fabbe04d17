"""A simulated history as CSV or JSON text, or a plot (PNG/PDF/SVG bytes, via matplotlib).

Pure functions of a :class:`~dynsolve.simulate.run.History`: the CLI writes the files.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.simulate.run import simulate_spec
>>> text = ("given:\\n  m = 1 kg\\n  L = 1 m\\nscene:\\n  point O: (0, 0)\\n"
...         "  body bar: mass m, rod L, at (L/2, 0)\\n  pin bar at O\\n  gravity\\n")
>>> history = simulate_spec(parse_spec(text, "bar.dyn"), t_end=1.0, samples=3)
>>> history_csv(history).splitlines()[0][:33]
't [s],q [rad],q_dot [rad/s],x_bar'
"""

from __future__ import annotations

import io
import json
import math

from dynsolve.safe_csv import csv_text
from dynsolve.simulate.chain_run import ChainHistory
from dynsolve.simulate.run import History


def summary(history: History | ChainHistory) -> dict[str, object]:
    """What was measured: the run's settings, events, period and energy drift."""
    run = history.run
    return {
        "problem": history.title,
        "file": history.file,
        "coordinate": history.motion.coordinate,
        "method": run.method,
        "rtol": run.rtol,
        "atol": run.atol,
        "t_end": float(run.t[-1]) if run.t.size else 0.0,
        "stopped_by": history.stopped_by,
        "events": [
            {"event": name, "t": t, "q": q, "q_dot": qd} for name, t, q, qd in history.events
        ],
        "period": history.period,
        "small_oscillation_period": history.small_period,
        "equilibrium": history.equilibrium,
        "constant_acceleration": _constant(getattr(history, "constant_acceleration", None)),
        "energy_drift": run.drift,
        "invariant": getattr(history, "invariant", "T + V - U_f"),
        "evaluations": run.evaluations,
        "missed": getattr(history, "missed", ""),
        "contact": _contact(history),
    }


def _contact(history: History | ChainHistory) -> dict[str, object] | None:
    """A particle on a circular path: the path, its side, and where the contact was lost
    (time, angle turned and from the top in degrees, speed, rise of G; None if it held)."""
    from dynsolve.simulate.contact import loss_report

    contact = getattr(history, "contact", None)
    if contact is None:
        return None
    lost = None
    for name, t, q, qd in history.events:
        if name == f"lost({contact.path})":
            lost = loss_report(contact, t, q, qd)
    return {
        "path": contact.path,
        "body": contact.body,
        "force": contact.name,
        "side": "inside" if contact.side > 0 else "outside",
        "radius": contact.radius,
        "lost": lost,
    }


def history_csv(history: History | ChainHistory) -> str:
    """The time history, one row per sample, with a header of names and units."""
    rows = ([repr(v) for v in row] for row in history.rows())
    return csv_text([history.columns(), *rows])


def history_json(history: History | ChainHistory) -> str:
    """The summary and the time history (columns and rows), full precision."""
    data = summary(history) | {
        "columns": list(history.columns()),
        "rows": [[v if math.isfinite(v) else None for v in row] for row in history.rows()],
    }
    return json.dumps(data, indent=1, allow_nan=False)


def history_plot(history: History | ChainHistory, suffix: str = ".png") -> bytes:
    """q(t) and the energy terms over time, as an image in the format of ``suffix``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    run = history.run
    columns = history.columns()
    rows = history.rows()
    contact = getattr(history, "contact", None)
    panels = 3 if contact is not None else 2
    figure, axes = plt.subplots(panels, 1, figsize=(7, 3 * panels), sharex=True)
    top, bottom = axes[0], axes[-1]
    top.plot(run.t, run.q)
    top.set_ylabel(columns[1])
    for name, t, q, _ in history.events:
        top.plot([t], [q], "o", color="C3" if name not in ("max", "min") else "C1")
    top.set_title(f"{history.title}: {history.motion.coordinate}")
    for index in (-3, -2, -1):  # T (or T − Ω·H_O in a turning frame), V, U_friction
        label = columns[index].rsplit(" [", 1)[0]
        bottom.plot(run.t, [row[index] for row in rows], label=label)
    if contact is not None:  # the path's push, and where it falls to zero
        index = columns.index(next(c for c in columns if c.startswith(contact.name + " [")))
        axes[1].plot(run.t, [row[index] for row in rows], color="C2")
        axes[1].axhline(0.0, color="0.6", linewidth=0.8)
        axes[1].set_ylabel(columns[index])
        for name, t, _, _ in history.events:
            if name.startswith("lost(") or name == f"{contact.name} = 0":
                axes[1].plot([t], [0.0], "o", color="C3")
    bottom.set_xlabel("t [s]")
    bottom.set_ylabel(f"energy [{columns[-3].rsplit('[', 1)[1]}")
    bottom.legend()
    buffer = io.BytesIO()
    figure.tight_layout()
    figure.savefig(buffer, format=suffix.lstrip(".") or "png")
    plt.close(figure)
    return buffer.getvalue()


def _constant(pair: tuple[float, float] | None) -> dict[str, float] | None:
    """The constant q'' and the run's largest relative difference from q'₀ t + ½ q'' t²."""
    if pair is None:
        return None
    return {"q_ddot": pair[0], "difference": pair[1]}
