"""The stages of a scene: its travels and impacts in the order written, and the states between.

State 1 is the scene as described; stage k (the k-th ``travel`` or ``impact`` line) takes
it from state k to state k + 1, and the velocities at the end of one stage are those at
the start of the next.

>>> import sympy
>>> from dynsolve.model.scene import Impact, Travel
>>> fall = Travel("ball", "by", distance=sympy.Symbol("h"), direction=(0, -1), line=7)
>>> bounce = Impact("ball", "ground", sympy.Rational(1, 2), (0, -1), stmt_line=8)
>>> for stage in stages_of((fall, bounce)):
...     print(stage.title)
stage 1 (state 1 → 2): ball travels by h, work and energy
stage 2 (state 2 → 3): ball strikes the ground, impact
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy

from dynsolve.model.momentum_events import Clutch, Reshape
from dynsolve.model.scene import Impact, Pivot, Scene, Travel, Vec


@dataclass(frozen=True)
class Stage:
    """One event between two numbered states."""

    number: int  # stage k runs from state k to state k + 1
    event: Travel | Impact | Pivot | Clutch | Reshape

    @property
    def principle(self) -> str:
        if isinstance(self.event, Travel):
            return "impulse and momentum" if self.event.kind == "for" else "work and energy"
        if isinstance(self.event, Pivot):
            return "angular momentum about the struck point"
        if isinstance(self.event, Clutch | Reshape):
            return "angular momentum"
        return "impact"

    @property
    def what(self) -> str:
        event = self.event
        if isinstance(event, Impact):
            return f"{event.body} strikes {'the ' if event.other == 'ground' else ''}{event.other}"
        if isinstance(event, Pivot):
            return f"{event.body} strikes {event.name} and turns about it"
        if isinstance(event, Clutch | Reshape):
            return event.what
        how = {
            "to": "to its position",
            "turns": "turns",
            "for": "moves for "
            + sympy.sstr(event.duration)
            + (", until it rolls" if event.until == "rolls" else "")
            + (", until it stops" if event.stops else ""),
            "until": f"moves until {event.until_name or 'contact'} {event.until}",
        }
        if event.kind == "by":
            return f"{event.body} travels by {sympy.sstr(event.distance)}"
        return f"{event.body} {'travels ' if event.kind == 'to' else ''}{how[event.kind]}"

    @property
    def title(self) -> str:
        k = self.number
        return f"stage {k} (state {k} → {k + 1}): {self.what}, {self.principle}"


@dataclass(frozen=True)
class State:
    """The motion at a numbered state: each body's v_G and ω (ccw positive)."""

    number: int
    velocities: Mapping[str, Vec]
    omegas: Mapping[str, sympy.Expr]
    inertias: Mapping[str, sympy.Expr] = field(default_factory=dict)  # I_G changed by a stage


@dataclass(frozen=True)
class StageRecord:
    """What one stage found: its principle, the bodies in it and each force's work."""

    stage: Stage
    bodies: tuple[str, ...]
    works: Mapping[str, sympy.Expr] = field(default_factory=dict)  # U(k→k+1) per force
    equations: tuple[int, ...] = ()  # its equations' indices in the whole chain
    stops: bool = False  # a travel that ends at rest
    start_along: sympy.Expr | None = None  # v_G·Δr at its start (a lone particle's travel)
    approach: sympy.Expr | None = None  # an impact's (v_A − v_B)·n just before it
    pin: str = ""  # a particle's impact on a body turning about this pin (H about it kept)
    pinned: tuple[tuple[str, sympy.Expr], ...] = ()  # its checks: approach, separation, lost
    scene: Scene | None = None  # a travel's moving part, from its start state (simulation)
    slides: tuple[Slide, ...] = ()  # an interval's sliding contacts
    normals: tuple[tuple[str, sympy.Expr], ...] = ()  # an interval's average normal forces
    # an interval's end event: (what, its time, detail with {value})
    events: tuple[tuple[str, sympy.Expr, str], ...] = ()
    # an interval's T_k, each force's work and T_{k+1}, for the work–energy check
    energy: tuple[sympy.Expr, Mapping[str, sympy.Expr], sympy.Expr] | None = None


@dataclass(frozen=True)
class Slide:
    """A contact that slides through an interval: kinetic friction with ``sense`` (±1 along
    the tangent) opposes the slip of the body's contact point, ``start`` at the interval's
    start and ``end`` at its end (checked: the slip keeps its sign in between)."""

    support: str
    sense: int
    start: sympy.Expr
    end: sympy.Expr
    guessed: bool = False  # the sense was not known before solving (assumed, then checked)


def stages_of(events: tuple[Travel | Impact | Pivot | Clutch | Reshape, ...]) -> tuple[Stage, ...]:
    """The events numbered as stages, in the order they were written."""
    return tuple(Stage(k, event) for k, event in enumerate(events, start=1))
