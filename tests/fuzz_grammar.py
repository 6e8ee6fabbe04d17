"""Random spec texts for fuzzing: built from the grammar's pieces, or mutated bundled problems.

Every generator takes a ``random.Random`` so that one code path serves both the
Hypothesis test (``st.randoms()``, which shrinks) and bench/fuzz.py (a seeded Random).

>>> import random
>>> text = grammar_spec(random.Random(1))
>>> "given:" in text or "scene:" in text or "kinematics:" in text or "equations:" in text
True
"""

from __future__ import annotations

import random
from pathlib import Path

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"

NAMES = ("m", "g", "r", "k_O", "alpha", "omega", "T", "a", "v_0", "x", "theta", "I_O", "t", "y")
UNITS = ("kg", "m", "s", "N", "N*m", "m/s", "m/s^2", "rad/s", "deg", "lb", "ft", "kg*m^2", "1/s")
UNITS_ODD = (
    "N^-2", "m^(1/2)", "kgs", "(m/s)^3", "rev/min", "N·m", "2*m", "m^99", "s^(-1/3)",
    "N^1e99999999", "m^1e400", "s^-1e-30", "kg^(10^10)", "m^(2^2^2^2)",
)  # fmt: skip
FUNCTIONS = ("sin", "cos", "tan", "sqrt", "exp", "log", "atan2", "abs", "asin", "acos")
NUMBERS = ("0", "1", "2", "0.5", "-3", "9.81", "1e3", "1e-9", "1e30", "1e-30", "123456789", ".5")
RELATIONS = ("=", "=", "=", ">=", "<=", ">", "<")
SECTIONS = ("given", "equations", "find", "answers", "scene", "kinematics")
SCENE_LINES = (
    "body B: mass m, disk r, at (0, 0)",
    "body B: weight W, rod L",
    "point A: (0, 0)",
    "point P on B: (r, 0)",
    "pin B at A",
    "contact B at A: normal up, mu_k 0.2",
    "rolls B at (0, -r)",
    "cord C: B at P, up",
    "spring S: B at P to A, k k, unstretched 1 m",
    "spring S: B at P to A, k k, unstretched 1 m, compression only",
    "spring S: B at G to A, k k, unstretched 1 m, tension only",
    "torsion spring W: B, k k",
    "link L: B at P to A",
    "force F on B at P: angle 30 deg",
    "couple M on B: ccw",
    "gravity",
    "omega B: omega ccw",
    "velocity B: v, right",
    "travel B: turns theta ccw",
    "travel B: turns n about (0, 1, 0), from omega w",
    "travel B: by d, right",
    "travel B: for t",
    "impact B with A: e 0.5, line up",
    "motion B: rotation",
    "path B: y = x^2",
    "moves B: along y, speed v",
    "moves B: along y, speed v, constant",
    "bar B: A to P, length r, angle theta",
    "bar C: P to Q to A, mass m",
    "joint P: near (r, 0)",
    "slider Q: along right, through A",
    "slider P: along bar B",
    "alpha B: 0",
    "acceleration P: a, left",
    "branch open",
    "method ic",
    "rolls B: radius r",
    "mesh B with C: radii r, r",
    "mesh B with C: radii 3*r, r, internal",
    "body B: mass m, disk r, at (0, 0, r)",
    "axis B: (1, 0, 0)",
    "body B: mass m, cone r by r, at (0, 0, 0)",
    "inertia B: m*r^2, m*r^2, m*r^2/2, products 0, m*r^2/9, m*r*r",
    "axes B: (1, 0, 0), (0, 1, 0)",
    "rotates B: about (0, 1, 0), through (0, 0, 0), omega w",
    "spins B: about (1, 0, 0), omega w",
    "spins B: about (0, 0, 1), through (0, 0, 0), omega 0, alpha a_s",
    "bearing A: at (0, 0, r), ball",
    "bearing B: at (0, 0, 0), pin",
    "nutates B: about (0, 0, 1), through (0, 0, 0), omega w, alpha a_n",
    "bearing O: at (0, 0, 0), fixed",
    "torque M on B",
    "assume T >= 0",
)


def expression(rng: random.Random, depth: int = 0) -> str:
    """An expression of numbers, names, operators and function calls."""
    pick = rng.randrange(9 if depth < 4 else 2)
    if pick == 0:
        return rng.choice(NUMBERS)
    if pick == 1:
        return rng.choice(NAMES)
    if pick in (2, 3):
        op = rng.choice(("+", "-", "*", "/", "^"))
        return f"{expression(rng, depth + 1)}{op}{expression(rng, depth + 1)}"
    if pick == 4:
        return f"({expression(rng, depth + 1)})"
    if pick == 5:
        return f"-{expression(rng, depth + 1)}"
    function = rng.choice(FUNCTIONS)
    count = 2 if function == "atan2" else 1
    if rng.random() < 0.05:
        count = 3 - count
    args = ", ".join(expression(rng, depth + 1) for _ in range(count))
    return f"{function}({args})"


def unit(rng: random.Random) -> str:
    """A unit expression, mostly valid ones."""
    return rng.choice(UNITS_ODD) if rng.random() < 0.2 else rng.choice(UNITS)


def quantity(rng: random.Random) -> str:
    """A number with an optional unit."""
    return f"{rng.choice(NUMBERS)} {unit(rng)}" if rng.random() < 0.8 else rng.choice(NUMBERS)


def section_line(rng: random.Random, section: str) -> str:
    """One body line that fits ``section`` (sometimes a line from another section)."""
    if rng.random() < 0.05:
        section = rng.choice(SECTIONS)
    name = rng.choice(NAMES)
    if section == "given":
        if rng.random() < 0.2:
            return f"{name}: {unit(rng)}"
        return f"{name} = {quantity(rng)}"
    if section in ("equations", "kinematics"):
        return f"{expression(rng)} {rng.choice(RELATIONS)} {expression(rng)}"
    if section == "find":
        items = []
        for _ in range(rng.randint(1, 3)):
            item = rng.choice(NAMES)
            if rng.random() < 0.3:
                item += f" = {rng.choice(('y(t)', 'max(y)', 'v(t_f)', 'alpha(B)', 't_at(y, 0)'))}"
            if rng.random() < 0.3:
                item += f" [{unit(rng)}]"
            items.append(item)
        return ", ".join(items)
    if section == "answers":
        if rng.random() < 0.2:
            return f"{name} = {expression(rng)}"
        tolerance = rng.choice(("", " +- 0.5%", " +- 1 N", " +- 2"))
        return f"{name} = {quantity(rng)}{tolerance}{rng.choice(('', ' ccw', ' up'))}"
    return rng.choice(SCENE_LINES)


def grammar_spec(rng: random.Random) -> str:
    """A whole spec: a free mix of sections, or (more often) a coherent equation-mode one."""
    return coherent_spec(rng) if rng.random() < 0.6 else section_mix(rng)


def coherent_spec(rng: random.Random) -> str:
    """An equation-mode spec whose finds are the equations' unknowns, so it reaches the solver."""
    names = rng.sample(NAMES, rng.randint(2, 6))
    unknowns = names[: rng.randint(1, min(3, len(names) - 1))]
    givens = names[len(unknowns) :]
    lines = ["problem: fuzz", f"units: {rng.choice(('SI', 'FPS'))}", "given:"]
    lines.extend(f"  {name} = {quantity(rng)}" for name in givens)
    lines.append("equations:")
    for unknown in unknowns:
        rhs = expression(rng).replace(rng.choice(NAMES), rng.choice(givens))
        relation = "=" if rng.random() < 0.9 else rng.choice(RELATIONS)
        lines.append(f"  {unknown} {relation} {rhs}")
    lines.append(f"find: {', '.join(unknowns)}")
    if rng.random() < 0.5:
        lines.append("answers:")
        for unknown in rng.sample(unknowns, rng.randint(1, len(unknowns))):
            lines.append(f"  {unknown} {section_line(rng, 'answers').partition(' ')[2]}")
    return "\n".join(lines) + "\n"


def section_mix(rng: random.Random) -> str:
    """A header, then a few sections of any kind with a few lines each."""
    lines = ["problem: fuzz"]
    if rng.random() < 0.5:
        lines.append(f"units: {rng.choice(('SI', 'FPS', 'cgs'))}")
    for section in rng.sample(SECTIONS, rng.randint(1, 4)):
        lines.append(f"{section}:")
        lines.extend(f"  {section_line(rng, section)}" for _ in range(rng.randint(0, 4)))
    return "\n".join(lines) + "\n"


def bundled_problems() -> list[str]:
    """The texts of every bundled problem (the mutation seeds)."""
    return [path.read_text(encoding="utf-8") for path in sorted(PROBLEMS.rglob("*.dyn"))]


def mutate(rng: random.Random, text: str) -> str:
    """Apply one to three token-level mutations to ``text``."""
    tokens = text.split(" ")
    for _ in range(rng.randint(1, 3)):
        where = rng.randrange(len(tokens))
        kind = rng.randrange(7)
        if kind == 0 and len(tokens) > 1:
            del tokens[where]
        elif kind == 1:
            tokens.insert(where, tokens[where])
        elif kind == 2:
            other = rng.randrange(len(tokens))
            tokens[where], tokens[other] = tokens[other], tokens[where]
        elif kind == 3:
            tokens[where] = rng.choice(NUMBERS)
        elif kind == 4:
            tokens[where] = unit(rng)
        elif kind == 5:
            token = tokens[where]
            cut = rng.randint(0, len(token))
            char = chr(rng.choice((rng.randint(32, 126), rng.randint(0, 0x2FFF))))
            tokens[where] = token[:cut] + char + token[cut:]
        else:
            tokens[where] = expression(rng)
    return " ".join(tokens)


def mutated_problem(rng: random.Random, seeds: list[str]) -> str:
    """A bundled problem after a few random mutations."""
    return mutate(rng, rng.choice(seeds))
