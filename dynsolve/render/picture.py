r"""LaTeX picture-mode drawing in millimetres: lines, dashes, arcs, arrowheads, labels.

The free-body diagrams and the linkage figure of a solution sheet are drawn with these
(picture mode needs no package beyond the LaTeX kernel; curves are ``\qbezier``).

>>> picture = Picture()
>>> picture.line((0.0, 0.0), (10.0, 0.0))
>>> picture.render().splitlines()[1]
'\\begin{picture}(16,10)(-5,-5)'
"""

from __future__ import annotations

import math

Point = tuple[float, float]

HEAD_MM, HEAD_HALF_MM = 2.4, 0.9  # arrowhead length and half-width
SQUARE_MM = 8.0  # the side of the square drawn for a shape without a footprint
PT_PER_MM = 72.27 / 25.4


class Picture:
    """Picture-mode commands in millimetres, and the box they cover."""

    def __init__(self, thickness: float = 0.7) -> None:
        self.commands: list[str] = []
        self.thickness = thickness  # pt, as set by the last \linethickness
        self.low = [-SQUARE_MM / 2, -SQUARE_MM / 2]
        self.high = [SQUARE_MM / 2, SQUARE_MM / 2]

    def cover(self, point: Point) -> None:
        for axis in (0, 1):
            self.low[axis] = min(self.low[axis], point[axis])
            self.high[axis] = max(self.high[axis], point[axis])

    def set_thickness(self, points: float) -> None:
        self.thickness = points
        self.commands.append(f"\\linethickness{{{num(points)}pt}}")

    def curve(self, start: Point, control: Point, end: Point) -> None:
        """A quadratic Bezier curve drawn as overlapping square dots of the line's width.

        The dot count is given explicitly: left to itself the kernel divides by zero on a
        curve shorter than a quarter of the line width ("Arithmetic overflow").
        """
        reach = (math.dist(start, control) + math.dist(control, end)) * PT_PER_MM
        dots = max(1, math.ceil(reach / (0.3 * self.thickness)))
        self.commands.append(f"\\qbezier[{dots}]{xy(start)}{xy(control)}{xy(end)}")
        self.cover(start)
        self.cover(end)

    def line(self, start: Point, end: Point) -> None:
        self.curve(start, lerp(start, end, 0.5), end)

    def dashed(self, start: Point, end: Point, dash: float = 1.6, gap: float = 1.0) -> None:
        length = math.dist(start, end)
        if length == 0:
            return
        count = max(1, round((length + gap) / (dash + gap)))
        on = length / (count + (count - 1) * gap / dash)  # dashes at both ends
        step = on * (1 + gap / dash)
        for i in range(count):
            a, b = i * step / length, (i * step + on) / length
            self.line(lerp(start, end, a), lerp(start, end, min(b, 1.0)))

    def put(self, at: Point, content: str) -> None:
        self.commands.append(f"\\put{xy(at)}{{{content}}}")
        self.cover(at)

    def label(self, at: Point, direction: Point, text: str, width: float) -> None:
        """``text`` just beyond ``at`` in ``direction``, aligned so it stays clear of it."""
        dx, dy = direction
        height = 4.0
        if abs(dx) >= abs(dy):
            align = "l" if dx > 0 else "r"
            left = at[0] if dx > 0 else at[0] - width
            low, high = (left, at[1] - height / 2), (left + width, at[1] + height / 2)
        else:
            align = "b" if dy > 0 else "t"
            bottom = at[1] if dy > 0 else at[1] - height
            low, high = (at[0] - width / 2, bottom), (at[0] + width / 2, bottom + height)
        self.put(at, f"\\makebox(0,0)[{align}]{{{text}}}")
        self.cover(low)
        self.cover(high)

    def arrowhead(self, tip: Point, unit: Point) -> None:
        """A filled arrowhead: a fan of lines from the tip to its base."""
        normal = (-unit[1], unit[0])
        base = (tip[0] - HEAD_MM * unit[0], tip[1] - HEAD_MM * unit[1])
        for k in range(-3, 4):
            offset = k / 3 * HEAD_HALF_MM
            self.line(tip, (base[0] + offset * normal[0], base[1] + offset * normal[1]))

    def arc(self, centre: Point, radius: float, start: float, sweep: float, dashed: bool) -> None:
        """A circular arc (degrees, counterclockwise positive) in pieces of at most 45 deg."""
        pieces = max(1, math.ceil(abs(sweep) / (15 if dashed else 45)))
        step = sweep / pieces
        reach = radius / math.cos(math.radians(step / 2))
        for i in range(pieces):
            if dashed and i % 2 and i != pieces - 1:
                continue
            a = start + i * step
            self.curve(
                polar(centre, radius, a),
                polar(centre, reach, a + step / 2),
                polar(centre, radius, a + step),
            )

    def render(self) -> str:
        margin = 1.0
        x0, y0 = self.low[0] - margin, self.low[1] - margin
        width, height = self.high[0] + margin - x0, self.high[1] + margin - y0
        return "\n".join([
            r"{\setlength{\unitlength}{1mm}%",
            f"\\begin{{picture}}({num(width)},{num(height)})({num(x0)},{num(y0)})",
            *self.commands,
            r"\end{picture}}",
        ])  # fmt: skip


def num(value: float) -> str:
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def xy(point: Point) -> str:
    return f"({num(point[0])},{num(point[1])})"


def lerp(a: Point, b: Point, t: float) -> Point:
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))


def polar(centre: Point, radius: float, degrees: float) -> Point:
    angle = math.radians(degrees)
    return (centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle))
