"""Stages that keep angular momentum without an impact: a clutch, a body changing its inertia.

>>> Clutch("A", "B", 9).what
'A and B locked by a clutch'
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy


@dataclass(frozen=True)
class Clutch:
    """``clutch A with B``: two coaxial rotors (pinned on one axis) locked to turn as one."""

    body: str
    other: str
    line: int = 0
    column: int = 0

    @property
    def what(self) -> str:
        return f"{self.body} and {self.other} locked by a clutch"


@dataclass(frozen=True)
class Reshape:
    """``change B: gyration k`` (or ``inertia I``): B's moment of inertia about G becomes
    ``I_G`` (a diver tucking, a skater pulling in the arms); ``how`` is the line's words."""

    body: str
    I_G: sympy.Expr
    how: str
    line: int = 0
    column: int = 0

    @property
    def what(self) -> str:
        return f"{self.body} changes its inertia ({self.how})"
