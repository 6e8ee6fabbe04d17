"""Parse spec text into a :class:`~dynsolve.spec.ast.Spec`, with bounded, position-exact errors.

Sections are read line by line here; each body line is parsed by the lark grammar in
``spec.lark`` and turned into AST nodes by a transformer. Nothing is evaluated.

>>> spec = parse_spec('''
... problem: Falling block
... given:
...   m = 2 kg   # block mass
... equations:
...   F = m*g    # weight
... find: F [N]
... ''', "demo.dyn")
>>> spec.title, spec.givens[0].description, str(spec.equations[0].rhs), spec.finds[0].unit.text
('Falling block', 'block mass', 'm*g', 'N')
"""

from __future__ import annotations

import difflib
import functools
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, replace
from fractions import Fraction
from importlib import resources
from pathlib import Path
from typing import Any

import lark
from lark import Token, Transformer_NonRecursive

from dynsolve.errors import Position, SpecError, with_others
from dynsolve.files import read_capped
from dynsolve.spec.ast import (
    Answer,
    Binary,
    Call,
    Direction,
    EquationStmt,
    Expr,
    FindItem,
    Given,
    GradingRule,
    Location,
    Name,
    Num,
    Prop,
    Quantity,
    QuantityRef,
    SceneStmt,
    Spec,
    Tolerance,
    Unary,
    UnitExpr,
    UnitFactor,
    VaryStmt,
)

MAX_FILE_BYTES = 256 * 1024
MAX_ERRORS = 20  # bad lines reported at once
_LINE_BREAK = re.compile(r"\r\n|\r|\n")  # only these end a line (not \f, \v, \u2028 …)
_SPACES = str.maketrans({"\u00a0": " ", "\u2009": " ", "\u202f": " ", "\u2007": " "})
MAX_LINES = 5000
MAX_LINE_LENGTH = 1000
MAX_DEPTH = 40
CHAIN_STEP = 6  # operations of one flat sum (or product) per level of nesting
MAX_DIGITS = 40
MAX_LITERAL_EXPONENT = 100
MAX_POWER = 64
MAX_UNIT_EXPONENT = 12
MAX_STATEMENTS = 1000

SECTIONS = (
    "problem", "source", "units", "given", "scene", "kinematics", "equations", "find", "define",
    "answers", "vary", "grading",
)  # fmt: skip
BLOCK_SECTIONS = (
    "given", "scene", "kinematics", "equations", "find", "define", "answers", "vary", "grading",
)  # fmt: skip
_FIELDS = {
    "given": "givens",
    "scene": "scene",
    "kinematics": "kinematics",
    "equations": "equations",
    "find": "finds",
    "define": "defines",
    "answers": "answers",
    "vary": "vary",
    "grading": "grading",
}
# US customary, as textbooks name it, is FPS (ft, lb, s)
SYSTEMS = {"si": "SI", "fps": "FPS", "us": "FPS", "uscs": "FPS", "us customary": "FPS"}
SYSTEM_ALIASES = {"imperial": "FPS", "metric": "SI", "english": "FPS"}
FUNCTIONS = {
    "sin": 1,
    "cos": 1,
    "tan": 1,
    "asin": 1,
    "acos": 1,
    "atan": 1,
    "atan2": 2,
    "sqrt": 1,
    "exp": 1,
    "log": 1,
    "abs": 1,
}

_EXPECTED_WORDS = {
    "NAME": "a name",
    "NUMBER": "a number",
    "REL": "'=' or a comparison",
    "EQUAL": "'='",
    "COLON": "':'",
    "PLUSMINUS": "'+-'",
    "DIRECTION": "a direction (cw, ccw, up, down, left, right)",
    "METHOD": "a method: ic (instantaneous centres) or relative (v_B = v_A + ω × r_B/A)",
    "BRANCH": "a branch: open or crossed",
    "RPAR": "')'",
    "LPAR": "'('",
    "RSQB": "']'",
    "LSQB": "'['",
    "COMMA": "','",
    "POW": "'^'",
    "MINUS": "'-'",
    "PLUS": "'+'",
    "STAR": "'*'",
    "SLASH": "'/'",
    "UMUL": "'*'",
    "PERCENT": "'%'",
    "$END": "the end of the line",
}


@functools.cache
def _lark() -> lark.Lark:
    grammar = resources.files("dynsolve.spec").joinpath("spec.lark").read_text("utf-8")
    return lark.Lark(
        grammar,
        parser="lalr",
        lexer="contextual",
        start=[
            "given_line",
            "equation_line",
            "find_line",
            "answer_line",
            "answer_formula",
            "unit_line",
            "scene_line",
            "quantity_line",
        ],
        cache=True,
    )


def parse_file(path: str | Path) -> Spec:
    """Read and parse a ``.dyn`` file, bounding its size and checking its encoding."""
    shown = str(path)
    return parse_bytes(read_capped(path, MAX_FILE_BYTES), shown)  # a byte cap, not stat


def parse_bytes(raw: bytes, shown: str = "<spec>") -> Spec:
    """Parse a spec's bytes (read from a file or stdin), bounding their size and encoding.

    >>> parse_bytes(b"given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n").finds[0].name
    'W'
    """
    if len(raw) > MAX_FILE_BYTES:
        raise SpecError(
            f"{shown} is over {MAX_FILE_BYTES} bytes; specs are limited to {MAX_FILE_BYTES} bytes",
            Position(shown, 1, 1),
            hint="split the problem into several files",
        )
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        line_start = raw.rfind(b"\n", 0, exc.start) + 1
        column = len(raw[line_start : exc.start].decode("utf-8", errors="replace")) + 1
        raise SpecError(
            "the file is not valid UTF-8 text",
            Position(shown, line, column),
            hint="save it as UTF-8",
        ) from None
    return parse_spec(text, shown)


@dataclass
class _Sections:
    """Section contents gathered while scanning, before they are frozen into a Spec."""

    title: str = ""
    source: str = ""
    system: str = "SI"
    system_line: int = 0
    givens: list[Given] | None = None
    equations: list[EquationStmt] | None = None
    finds: list[FindItem] | None = None
    answers: list[Answer] | None = None
    scene: list[SceneStmt] | None = None
    kinematics: list[EquationStmt] | None = None
    defines: list[EquationStmt] | None = None
    define_line: int = 0
    vary: list[VaryStmt] | None = None
    grading: list[GradingRule] | None = None


def parse_spec(text: str, file: str = "<spec>") -> Spec:
    """Parse spec ``text``; ``file`` names it in error positions."""
    if len(text.encode("utf-8")) > MAX_FILE_BYTES:
        raise SpecError(
            f"the spec exceeds {MAX_FILE_BYTES} bytes", Position(file, 1, 1), hint="split it"
        )
    lines = _LINE_BREAK.split(text)
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) > MAX_LINES:
        raise SpecError(
            f"the spec has more than {MAX_LINES} lines",
            Position(file, MAX_LINES + 1, 1),
            hint="split the problem into several files",
        )
    parts = _Sections()
    errors: list[SpecError] = []
    seen: dict[str, int] = {}
    current: str | None = None
    statements = 0
    for number, raw in enumerate(lines, start=1):
        content, comment = _split_comment(raw.translate(_SPACES))
        if not content.strip():
            continue
        if len(raw) > MAX_LINE_LENGTH:
            raise SpecError(
                f"line is {len(raw)} characters long; the limit is {MAX_LINE_LENGTH}",
                Position(file, number, MAX_LINE_LENGTH + 1),
                hint="break the expression into several equations",
            )
        _check_characters(content, file, number)
        indent = len(content) - len(content.lstrip(" \t"))
        if indent == 0:
            current = _header(content, comment, file, number, parts, seen)
            continue
        if current is None:
            raise SpecError(
                "indented line outside a section",
                Position(file, number, indent + 1),
                hint=f"start a section first, one of: {', '.join(BLOCK_SECTIONS)}",
            )
        statements += 1
        if statements > MAX_STATEMENTS:
            raise SpecError(
                f"more than {MAX_STATEMENTS} statements",
                Position(file, number, indent + 1),
                hint="split the problem into several files",
            )
        try:
            _body_line(current, content.strip(), comment, file, number, indent, parts)
        except SpecError as error:  # report every bad line at once, up to a limit
            errors.append(error)
            if len(errors) >= MAX_ERRORS:
                break
    if errors:
        raise with_others(errors)
    return _finish(parts, file, seen)


def _split_comment(raw: str) -> tuple[str, str]:
    content, hash_, comment = raw.partition("#")
    return content.rstrip(), comment.strip() if hash_ else ""


def _check_characters(content: str, file: str, line: int) -> None:
    depth = 0
    for column, char in enumerate(content, start=1):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if depth > MAX_DEPTH:
            raise SpecError(
                f"parentheses nested more than {MAX_DEPTH} levels deep",
                Position(file, line, column),
                hint="split the expression into several equations",
            )
        if not char.isprintable() and char != "\t":
            raise SpecError(
                f"control character U+{ord(char):04X} in the spec",
                Position(file, line, column),
                hint="remove it",
            )


def _header(
    content: str, comment: str, file: str, line: int, parts: _Sections, seen: dict[str, int]
) -> str | None:
    keyword, colon, rest = content.partition(":")
    key = keyword.strip().lower()
    if not colon or key not in SECTIONS:
        word = keyword.strip().split()[0] if keyword.strip() else keyword
        close = difflib.get_close_matches(word.lower(), SECTIONS, n=1)
        hint = f"did you mean '{close[0]}:'?" if close else f"sections are {', '.join(SECTIONS)}"
        if not colon and key in SECTIONS:
            hint = f"write '{key}:' with a colon"
        elif not colon and key not in SECTIONS and not close:
            hint = "indent the lines that belong to a section"
        raise SpecError(f"expected a section header, found '{word}'", Position(file, line, 1), hint)
    if key in seen:
        raise SpecError(
            f"section '{key}' appears twice (first on line {seen[key]})",
            Position(file, line, 1),
            hint="merge the two sections",
        )
    seen[key] = line
    rest_column = len(keyword) + 2 + (len(rest) - len(rest.lstrip()))
    rest = rest.strip()
    if key == "problem":
        parts.title = rest
    elif key == "source":
        parts.source = rest
    elif key == "units":
        parts.system = _system(rest, file, line, rest_column)
        parts.system_line = line
    else:
        setattr(parts, _FIELDS[key], [])
        parts.define_line = line if key == "define" else parts.define_line
        if rest:
            if key != "find":
                raise SpecError(
                    f"'{key}:' takes its entries on the following, indented lines",
                    Position(file, line, rest_column),
                    hint=f"move '{rest}' to the next line and indent it",
                )
            _body_line(key, rest, comment, file, line, rest_column - 1, parts)
        return key
    return None


def _system(word: str, file: str, line: int, column: int) -> str:
    if " ".join(word.lower().split()) in SYSTEMS:
        return SYSTEMS[" ".join(word.lower().split())]
    alias = SYSTEM_ALIASES.get(word.lower())
    hint = f"write 'units: {alias}'" if alias else "use 'SI' or 'FPS' (US customary)"
    raise SpecError(f"unknown unit system '{word}'", Position(file, line, column), hint)


def _body_line(
    section: str, text: str, comment: str, file: str, line: int, indent: int, parts: _Sections
) -> None:
    offset = indent  # columns before `text` on the line
    if section == "given":
        node = _parse(text, "given_line", file, line, offset)
        assert parts.givens is not None
        parts.givens.append(replace(node, description=comment))
    elif section in ("equations", "kinematics"):
        node = _parse(text, "equation_line", file, line, offset)
        target = parts.equations if section == "equations" else parts.kinematics
        assert target is not None
        lhs, relation, rhs = node
        target.append(EquationStmt(lhs, relation, rhs, text, comment, line, offset + 1))
    elif section == "find":
        assert parts.finds is not None
        parts.finds.extend(_parse(text, "find_line", file, line, offset))
    elif section == "define":
        assert parts.defines is not None
        parts.defines.append(_define(text, comment, file, line, offset))
    elif section == "vary":
        from dynsolve.spec.vary_line import parse_vary_line

        assert parts.vary is not None
        parts.vary.append(parse_vary_line(text, file, line, offset))
    elif section == "grading":
        from dynsolve.spec.grading_line import parse_grading_line

        assert parts.grading is not None
        parts.grading.append(parse_grading_line(text, file, line, offset))
    elif section == "scene":
        assert parts.scene is not None
        parts.scene.append(_parse(text, "scene_line", file, line, offset))
    else:
        assert parts.answers is not None
        parts.answers.append(_parse_answer(text, file, line, offset))


def _parse_answer(text: str, file: str, line: int, offset: int) -> Answer:
    try:
        return _parse(text, "answer_line", file, line, offset)
    except SpecError as as_quantity:
        try:
            return _parse(text, "answer_formula", file, line, offset)
        except SpecError as as_formula:
            assert as_quantity.position and as_formula.position
            further = max(
                (as_quantity, as_formula), key=lambda e: e.position.column if e.position else 0
            )
            raise further from None


def _define(text: str, comment: str, file: str, line: int, offset: int) -> EquationStmt:
    """``NAME = EXPR``: a derived find, an expression of givens, finds and scene
    quantities (``T(ram, 2)``), kept as written for the scene to resolve."""
    lhs, relation, rhs = _parse(text, "equation_line", file, line, offset, scene_calls=True)
    if relation != "=" or not isinstance(lhs, Name):
        raise SpecError(
            "a define line names one quantity: NAME = EXPRESSION",
            Position(file, line, offset + 1),
            hint="e.g. 'dE = T(ram, 2) - T(ram, 3)'",
        )
    return EquationStmt(lhs, "=", rhs, text, comment, line, offset + 1)


def _parse(
    text: str, start: str, file: str, line: int, offset: int, scene_calls: bool = False
) -> Any:
    try:
        tree = _lark().parse(text, start=start)
    except lark.exceptions.UnexpectedInput as exc:
        raise _syntax_error(exc, text, start, file, line, offset) from None
    _check_depth(tree, file, line, offset)
    try:
        return _Builder(file, line, offset, scene_calls).transform(tree)
    except lark.exceptions.VisitError as exc:
        if isinstance(exc.orig_exc, SpecError):
            raise exc.orig_exc from None
        raise


_OPERATIONS = frozenset(("add", "sub", "mul", "div", "pow", "neg", "pos", "call"))
_FAMILIES = {"add": "sum", "sub": "sum", "mul": "product", "div": "product"}
_CHAINS = frozenset(("sum", "product"))  # a chain a + b - c + … nests no deeper than a + b


def parse_answer_cell(text: str, file: str = "<cell>", line: int = 1) -> Answer:
    """Parse a student's answer, a number with an optional unit and direction word
    (``4.52 m/s^2 down``), with the grammar of an ``answers`` line; nothing is evaluated.

    >>> cell = parse_answer_cell("-4.52 m/s^2")
    >>> cell.quantity.text, cell.quantity.unit.text, cell.direction
    ('-4.52', 'm/s^2', None)
    """
    return _parse("x = " + text, "answer_line", file, line, -4)


def parse_unit(text: str, file: str = "<unit>") -> UnitExpr:
    """Parse a unit expression on its own (``kg*m^2/s``), e.g. an output unit.

    >>> [(f.name, int(f.exponent)) for f in parse_unit("N*m/s^2").factors]
    [('N', 1), ('m', 1), ('s', -2)]
    """
    return _parse(text, "unit_line", file, 1, 0)


def parse_unit_at(text: str, file: str, line: int, offset: int) -> UnitExpr:
    """Parse a unit written at ``file:line`` after ``offset`` columns (errors point there)."""
    return _parse(text, "unit_line", file, line, offset)


def parse_quantity(text: str, file: str = "<value>", line: int = 1, offset: int = 0) -> Quantity:
    """Parse a number with an optional unit, as on a ``given`` line (``45 kg``, ``-3.5``).

    Untrusted text (a cell of a variants file) goes through the same grammar and bounds
    as a spec; nothing is evaluated.

    >>> q = parse_quantity("45 kg")
    >>> q.value, q.unit.text
    (Fraction(45, 1), 'kg')
    """
    if len(text) > MAX_LINE_LENGTH or any(not c.isprintable() for c in text):
        raise SpecError(
            "the value is too long or holds control characters",
            Position(file, line, offset + 1),
            hint="write a number and a unit, e.g. '45 kg'",
        )
    return _parse(text.translate(_SPACES).strip(), "quantity_line", file, line, offset)


def _check_depth(tree: lark.Tree, file: str, line: int, offset: int) -> None:
    """Bound the nesting of operations: each operator or call is one level, except along a
    flat chain of sums (or of products), which counts one level per ``CHAIN_STEP``
    operations, so a 100-term sum is allowed and the true depth stays below
    ``MAX_DEPTH * CHAIN_STEP`` (the recursion of every walker of the tree stays bounded)."""
    stack: list[tuple[Any, int, str, int]] = [(tree, 0, "", 0)]
    while stack:
        node, depth, parent, run = stack.pop()
        if not isinstance(node, lark.Tree):
            continue
        family = _FAMILIES.get(node.data, node.data)
        run = run + 1 if family in _CHAINS and family == parent else 0
        if node.data in _OPERATIONS and run % CHAIN_STEP == 0:
            depth += 1
        if depth > MAX_DEPTH:
            token = next((c for c in node.children if isinstance(c, Token)), None)
            token = token or next(node.scan_values(lambda v: isinstance(v, Token)), None)
            column = offset + (token.column or 1) if token else offset + 1
            raise SpecError(
                f"expression nested more than {MAX_DEPTH} levels deep "
                "(nested operations or a very long chain)",
                Position(file, line, column),
                hint="split it into several equations with intermediate names",
            )
        stack.extend((child, depth, family, run) for child in node.children)


_LINE_KINDS = {
    "given_line": ("a given", "'name = value unit' or 'name: dimension'"),
    "equation_line": ("an equation", "'left = right', e.g. 'T*r = I_O*alpha'"),
    "find_line": ("a find list", "names with optional units, e.g. 'alpha, T [N]'"),
    "answer_line": ("an answer", "'name = value unit', e.g. 'T = 106 N +- 0.5%'"),
    "answer_formula": ("an answer", "'name = value unit' or 'name = formula'"),
    "unit_line": ("a unit", "a unit such as 'm/s^2' or 'N*m'"),
    "quantity_line": ("a value", "a number and a unit, e.g. '45 kg'"),
    "scene_line": (
        "a scene line",
        "e.g. 'body drum: mass m, gyration k_O' (see docs/scene-mode.md)",
    ),
}


def _syntax_error(
    exc: lark.exceptions.UnexpectedInput, text: str, start: str, file: str, line: int, offset: int
) -> SpecError:
    column = getattr(exc, "column", None)
    if not isinstance(column, int) or column < 1:
        column = len(text) + 1
    position = Position(file, line, offset + column)
    what, form = _LINE_KINDS[start]
    if isinstance(exc, lark.exceptions.UnexpectedCharacters):
        char = text[column - 1] if column - 1 < len(text) else ""
        return SpecError(f"unexpected character '{char}' in {what}", position, hint=f"write {form}")
    token = getattr(exc, "token", None)
    expected = sorted(_acceptable(exc))
    words = _expected_words(expected)
    if token is None or token.type == "$END":
        return SpecError(
            f"{what} ends too early; expected {words}",
            Position(file, line, offset + len(text) + 1),
            hint=f"write {form}",
        )
    return SpecError(
        f"unexpected '{token}' in {what}; expected {words}",
        position,
        hint=_unit_hint(str(token), start) or _token_hint(str(token), token.type, expected, form),
    )


# unit symbols a newcomer writes after a number in a scene line
_UNIT_WORDS = frozenset(
    {"m", "s", "kg", "N", "deg", "degree", "degrees", "rad", "ft", "lb", "lbf", "slug", "in"}
    | {"mm", "cm", "km", "rpm", "Hz", "J", "W", "h", "min", "rev", "g", "kN", "ms", "mph"}
)


def _unit_hint(token: str, start: str) -> str:
    """The hint for a unit written in a scene line, which takes none, else ""."""
    if start != "scene_line" or token not in _UNIT_WORDS:
        return ""
    if token in ("deg", "degree", "degrees"):
        return (
            "scene lines take no units: an angle here is in radians (180° is pi: "
            "'angle pi + theta'), or name it under 'given:' (e.g. 'phi = 30 deg') and write "
            "its name here"
        )
    named = (
        "scene lines take no units: give the quantity a name under 'given:' (e.g. "
        "'v_0 = 20 m/s') and write its name here"
    )
    return named + ("; for a product with gravity write '*' (e.g. '2*g')" if token == "g" else "")


def _acceptable(exc: lark.exceptions.UnexpectedInput) -> set[str]:
    """The terminals that could really come next (LALR's lookahead sets are wider)."""
    expected = set(getattr(exc, "expected", set()) or getattr(exc, "allowed", set()))
    interactive = getattr(exc, "interactive_parser", None)
    if interactive is not None:
        try:
            return set(interactive.accepts()) or expected
        except lark.exceptions.LarkError:
            return expected
    return expected


def _expected_words(expected: list[str]) -> str:
    words = []
    for name in expected:
        word = _EXPECTED_WORDS.get(name)
        if word is None and name.startswith("__ANON"):
            continue
        word = word or name.lower()
        if word not in words:
            words.append(word)
    if not words:
        return "something else"
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


def _token_hint(token: str, kind: str, expected: list[str], form: str) -> str:
    if kind == "NAME" and "NUMBER" in expected and "NAME" not in expected:
        if token == "pi":  # a value is a decimal number: pi belongs in the equations
            return (
                "a value is a number and a unit: write pi/2 rad/s as 1.570796 rad/s, or give "
                "the number that multiplies pi and write pi in the equations"
            )
        return f"a value comes before its unit: write a number before '{token}', e.g. 'm = 60 kg'"
    operator_expected = any(e in expected for e in ("STAR", "PLUS", "MINUS", "SLASH", "REL"))
    if kind in ("NAME", "NUMBER", "LPAR") and operator_expected:
        return f"write an operator before '{token}', e.g. '*' for a product"
    if kind == "NUMBER" and "NAME" in expected:
        return "names start with a letter"
    return f"write {form}"


class _Builder(Transformer_NonRecursive):
    """Turns lark's tree into AST nodes, enforcing number and exponent bounds."""

    def __init__(self, file: str, line: int, offset: int, scene_calls: bool = False) -> None:
        super().__init__()
        self.file, self.line, self.offset = file, line, offset
        self.scene_calls = scene_calls  # a define line: T(ram, 2) names a scene quantity

    def _at(self, token: Token) -> Position:
        return Position(self.file, self.line, self.offset + (token.column or 1))

    def _col(self, token: Token) -> int:
        return self.offset + (token.column or 1)

    # ---- numbers
    def _fraction(self, token: Token) -> Fraction:
        text = str(token)
        mantissa, _, exponent = text.lower().partition("e")
        if len(mantissa.replace(".", "").lstrip("0")) > MAX_DIGITS:
            raise SpecError(
                f"number has more than {MAX_DIGITS} digits", self._at(token), "round it"
            )
        if exponent and abs(int(exponent)) > MAX_LITERAL_EXPONENT:
            raise SpecError(
                f"exponent {exponent} is out of range (±{MAX_LITERAL_EXPONENT})",
                self._at(token),
                hint="choose units that keep numbers moderate",
            )
        return Fraction(text)

    def number(self, children: list[Token]) -> Num:
        (token,) = children
        return Num(self._fraction(token), str(token), self.line, self._col(token))

    def signed_number(self, children: list[Token]) -> tuple[Fraction, str, int]:
        token = children[-1]
        value = self._fraction(token)
        negative = len(children) == 2
        first = children[0]
        return (-value if negative else value, ("-" if negative else "") + token, self._col(first))

    # ---- expressions
    def name(self, children: list[Token]) -> Name:
        (token,) = children
        if str(token) in FUNCTIONS:
            raise SpecError(
                f"'{token}' is a function and needs an argument",
                self._at(token),
                hint=f"write {token}(x)",
            )
        return Name(str(token), self.line, self._col(token))

    def call(self, children: list[Any]) -> Call:
        token, *args = children
        function = str(token)
        if function not in FUNCTIONS and self.scene_calls:
            return Call(function, tuple(args), self.line, self._col(token))  # e.g. T(ram, 2)
        if function not in FUNCTIONS:
            close = difflib.get_close_matches(function, FUNCTIONS, n=1)
            hint = (
                f"did you mean '{close[0]}'?"
                if close
                else "known functions: " + ", ".join(FUNCTIONS)
            )
            if not close:
                hint += f"; for a product write {function}*(...)"
            raise SpecError(f"unknown function '{function}'", self._at(token), hint)
        if len(args) != FUNCTIONS[function]:
            raise SpecError(
                f"{function} takes {FUNCTIONS[function]} argument(s), got {len(args)}",
                self._at(token),
                hint="atan2 takes (y, x); the others take one argument",
            )
        return Call(function, tuple(args), self.line, self._col(token))

    def _binary(self, op: str, left: Expr, right: Expr) -> Binary:
        return Binary(op, left, right, left.line, left.column)  # type: ignore[arg-type]

    def add(self, c: list[Any]) -> Binary:
        return self._binary("+", c[0], c[2])

    def sub(self, c: list[Any]) -> Binary:
        return self._binary("-", c[0], c[2])

    def mul(self, c: list[Any]) -> Binary:
        return self._binary("*", c[0], c[1])

    def div(self, c: list[Any]) -> Binary:
        return self._binary("/", c[0], c[1])

    def pow(self, c: list[Any]) -> Binary:
        base, token, exponent = c
        literal = _literal_value(exponent)
        if literal is not None and abs(literal) > MAX_POWER:
            raise SpecError(
                f"exponent {literal} is too large (limit ±{MAX_POWER})",
                self._at(token),
                hint="dynamics needs small powers; check the expression",
            )
        return self._binary("^", base, exponent)

    def neg(self, c: list[Any]) -> Expr:
        token, operand = c
        if isinstance(operand, Num):
            return Num(-operand.value, "-" + operand.text, self.line, self._col(token))
        return Unary("-", operand, self.line, self._col(token))

    def pos(self, c: list[Any]) -> Expr:
        return c[1]

    # ---- units
    def unit_name(self, c: list[Token]) -> tuple[UnitFactor, ...]:
        (token,) = c
        return (UnitFactor(str(token), Fraction(1), self.line, self._col(token)),)

    def unit_number(self, c: list[Token]) -> tuple[UnitFactor, ...]:
        (token,) = c
        if str(token) != "1":
            raise SpecError(
                f"a number '{token}' inside a unit",
                self._at(token),
                hint="only '1' may appear in a unit, as in 1/s",
            )
        return ()

    def unit_mul(self, c: list[Any]) -> tuple[UnitFactor, ...]:
        return c[0] + c[2]

    def unit_div(self, c: list[Any]) -> tuple[UnitFactor, ...]:
        return c[0] + tuple(_power(f, Fraction(-1)) for f in c[1])

    def unit_exponent(self, c: list[Token]) -> Fraction:
        sign = -1 if str(c[0]) == "-" else 1
        numbers = [t for t in c if t.type == "NUMBER"]
        # _fraction bounds digits and e-exponent as text, before any Fraction is built
        denominator = self._fraction(numbers[1]) if len(numbers) > 1 else Fraction(1)
        if denominator == 0:
            raise SpecError(
                "unit exponent divides by zero", self._at(numbers[1]), "fix the fraction"
            )
        value = self._fraction(numbers[0]) / denominator
        if abs(value) > MAX_UNIT_EXPONENT or value.denominator > MAX_UNIT_EXPONENT:
            shown = str(value) if len(str(value)) <= 20 else f"{str(value)[:12]}…"
            raise SpecError(
                f"unit exponent {shown} is out of range (limit ±{MAX_UNIT_EXPONENT}, "
                f"denominator at most {MAX_UNIT_EXPONENT})",
                self._at(numbers[0]),
                hint="units in dynamics need small powers such as m/s^2",
            )
        return sign * value

    def unit_pow(self, c: list[Any]) -> tuple[UnitFactor, ...]:
        return tuple(_power(f, c[2]) for f in c[0])

    def unit_line(self, c: list[Any]) -> UnitExpr:
        return c[0]

    def quantity_line(self, c: list[Any]) -> Quantity:
        return c[0]

    def unit_expr(self, c: list[Any]) -> UnitExpr:
        (factors,) = c
        line, column = (factors[0].line, factors[0].column) if factors else (self.line, 0)
        return UnitExpr(unit_text(factors), factors, line, column)

    # ---- lines
    def quantity(self, c: list[Any]) -> Quantity:
        value, text, column = c[0]
        unit = c[1] if len(c) > 1 else None
        return Quantity(value, text, unit, self.line, column)

    def given_value(self, c: list[Any]) -> Given:
        token, quantity = c
        return Given(str(token), quantity, None, "", self.line, self._col(token))

    def given_symbolic(self, c: list[Any]) -> Given:
        token, unit = c
        return Given(str(token), None, unit, "", self.line, self._col(token))

    def equation_line(self, c: list[Any]) -> tuple[Expr, str, Expr]:
        lhs, relation, rhs = c
        return lhs, str(relation), rhs

    def find_item(self, c: list[Any]) -> FindItem:
        token = c[0]
        ref = next((x for x in c[1:] if isinstance(x, QuantityRef)), None)
        unit = next((x for x in c[1:] if isinstance(x, UnitExpr)), None)
        return FindItem(str(token), unit, self.line, self._col(token), ref)

    def quantity_ref(self, c: list[Token]) -> QuantityRef:
        function, *args = c
        return QuantityRef(
            str(function), tuple(str(a) for a in args), self.line, self._col(function)
        )

    # ---- scene
    def _stmt(self, kind: str, token: Token, **fields: Any) -> SceneStmt:
        return SceneStmt(kind, line=self.line, column=self._col(token), **fields)

    def body_stmt(self, c: list[Any]) -> SceneStmt:
        return self._stmt("body", c[0], name=str(c[0]), props=tuple(c[1:]))

    def part_stmt(self, c: list[Any]) -> SceneStmt:
        kind, body, *props = c
        return self._stmt(str(kind), body, body=str(body), props=tuple(props))

    def point_stmt(self, c: list[Any]) -> SceneStmt:
        name, *rest = c
        body = str(rest[0]) if isinstance(rest[0], Token) else ""
        return self._stmt("point", name, name=str(name), body=body, vectors=(rest[-1],))

    def pin_stmt(self, c: list[Token]) -> SceneStmt:
        body, point = c
        return self._stmt("pin", body, body=str(body), name=str(point))

    def contact_stmt(self, c: list[Any]) -> SceneStmt:
        body, location, props = c
        return self._stmt("contact", body, body=str(body), location=location, props=props)

    def rolls_stmt(self, c: list[Any]) -> SceneStmt:
        body, location, *props = c
        props = props[0] if props else ()
        return self._stmt("rolls", body, body=str(body), location=location, props=props)

    def rolls3_stmt(self, c: list[Any]) -> SceneStmt:
        """``rolls B at (x, y, z)``: in a 3D scene, the point of B there rolls without
        slipping on a fixed surface (a fixed gear): its velocity is zero."""
        body, at = c
        return self._stmt("rolls3", body, body=str(body), vectors=(at,))

    def base_stmt(self, c: list[Any]) -> SceneStmt:
        name, body, start, end, *props = c
        props = props[0] if props else ()
        return self._stmt(
            "base", name, name=str(name), body=str(body), vectors=(start, end), props=props
        )

    def cord_stmt(self, c: list[Any]) -> SceneStmt:
        name, body, location, *rest = c
        fixed = bool(rest) and isinstance(rest[-1], Token) and rest[-1].type == "FIXED"
        if fixed:
            rest = rest[:-1]
        direction = rest[-1]
        other = str(rest[0]) if len(rest) > 1 else ""
        other_location = rest[1] if len(rest) > 2 else None
        return self._stmt(
            "cord",
            name,
            name=str(name),
            body=str(body),
            location=location,
            other=other,
            other_location=other_location,
            direction=direction,
            word="fixed" if fixed else "",
        )

    def spring_stmt(self, c: list[Any]) -> SceneStmt:
        one_way = c[-1].type if isinstance(c[-1], Token) else ""
        one_way = one_way if one_way in ("TENSION", "COMPRESSION") else ""
        tension_only = one_way == "TENSION"
        c = c[:-1] if one_way else c
        wound = isinstance(c[-1], Token) and c[-1].type == "WOUND"
        name, body, location, other, *rest = c[:-1] if wound else c
        other_location = rest[0] if len(rest) == 3 else None
        stiffness, unstretched = rest[-2], rest[-1]
        extra = (Prop("wound", line=self.line, column=self.offset + 1),) if wound else ()
        if tension_only:  # an elastic cord: it pulls, never pushes
            extra += (Prop("tension_only", line=self.line, column=self.offset + 1),)
        elif one_way:  # a spring the body only rests against: it pushes, never pulls
            extra += (Prop("compression_only", line=self.line, column=self.offset + 1),)
        return self._stmt(
            "spring",
            name,
            name=str(name),
            body=str(body),
            location=location,
            other=str(other),
            other_location=other_location,
            props=(
                Prop("k", values=(stiffness,), line=self.line, column=self.offset + 1),
                Prop("unstretched", values=(unstretched,), line=self.line, column=self.offset + 1),
                *extra,
            ),
        )

    def torsion_stmt(self, c: list[Any]) -> SceneStmt:
        name, body, stiffness = c
        return self._stmt(
            "torsion",
            name,
            name=str(name),
            body=str(body),
            props=(Prop("k", values=(stiffness,), line=self.line, column=self.offset + 1),),
        )

    def link_stmt(self, c: list[Any]) -> SceneStmt:
        name, body, location, other, *rest = c
        return self._stmt(
            "link",
            name,
            name=str(name),
            body=str(body),
            location=location,
            other=str(other),
            other_location=rest[0] if rest else None,
        )

    def force_stmt(self, c: list[Any]) -> SceneStmt:
        name, body, location, direction = c
        return self._stmt(
            "force", name, name=str(name), body=str(body), location=location, direction=direction
        )

    def couple_stmt(self, c: list[Token]) -> SceneStmt:
        name, body, sense = c
        self._sense(sense)
        return self._stmt("couple", name, name=str(name), body=str(body), word=str(sense))

    def gravity_stmt(self, c: list[Any]) -> SceneStmt:
        direction = c[0] if c else None
        return SceneStmt("gravity", direction=direction, line=self.line, column=self.offset + 1)

    def omega_stmt(self, c: list[Any]) -> SceneStmt:
        body, value, *_ = c
        return self._stmt("omega", body, body=str(body), value=value, word=self._turn("omega", c))

    def pivot_stmt(self, c: list[Any]) -> SceneStmt:
        body, point, restitution, *line = c
        return self._stmt(
            "pivot",
            body,
            body=str(body),
            name=str(point),
            value=restitution,
            direction=line[0] if line else None,
        )

    def impact_stmt(self, c: list[Any]) -> SceneStmt:
        body, other, restitution, *line = c
        return self._stmt(
            "impact",
            body,
            body=str(body),
            other=str(other),
            value=restitution,
            direction=line[0] if line else None,
        )

    def clutch_stmt(self, c: list[Token]) -> SceneStmt:
        body, other = c
        return self._stmt("clutch", body, body=str(body), other=str(other))

    def change_gyration_stmt(self, c: list[Any]) -> SceneStmt:
        body, value = c
        return self._stmt("change", body, body=str(body), value=value, word="gyration")

    def change_inertia_stmt(self, c: list[Any]) -> SceneStmt:
        body, value = c
        return self._stmt("change", body, body=str(body), value=value, word="inertia")

    def path_stmt(self, c: list[Any]) -> SceneStmt:
        name, lhs, relation, rhs = c
        if str(relation) != "=":
            raise SpecError(
                "a path is an equation in x and y", self._at(relation), "write it with '='"
            )
        return self._stmt("path", name, name=str(name), vectors=((lhs, rhs),))

    def moves_stmt(self, c: list[Any]) -> SceneStmt:
        name, path, speed, *constant = c
        word = "constant" if constant and constant[0] is not None else ""
        return self._stmt("moves", name, name=str(name), other=str(path), value=speed, word=word)

    def assume_stmt(self, c: list[Any]) -> SceneStmt:
        lhs, relation, rhs = c
        return SceneStmt(
            "assume",
            vectors=((lhs, rhs),),
            word=str(relation),
            line=self.line,
            column=self.offset + 1,
        )

    def _stops(self, c: list[Any]) -> tuple[list[Any], tuple[Prop, ...]]:
        """Split a trailing ', stops' (at rest in state 2; also ', until stops') or
        ', until rolls' (slides until it rolls) off a travel line."""
        if isinstance(c[-1], Token) and c[-1].type == "STOPS":
            where = {"line": self.line, "column": self._col(c[-1])}
            if str(c[-1]).rstrip().endswith("rolls"):
                return c[:-1], (Prop("until", word="rolls", **where),)
            return c[:-1], (Prop("stops", **where),)
        return c, ()

    def travel_stmt(self, c: list[Any]) -> SceneStmt:
        (body, target), stops = self._stops(c)
        return self._stmt("travel", body, body=str(body), vectors=(target,), props=stops)

    def travel_by_stmt(self, c: list[Any]) -> SceneStmt:
        (body, distance, direction), stops = self._stops(c)
        return self._stmt(
            "travel", body, body=str(body), value=distance, direction=direction, props=stops
        )

    def travel_for_stmt(self, c: list[Any]) -> SceneStmt:
        (body, duration), stops = self._stops(c)
        return self._stmt("travel", body, body=str(body), value=duration, word="for", props=stops)

    def travel_until_stmt(self, c: list[Any]) -> SceneStmt:
        """``travel B: until NAME slack`` or ``until contact lost``: a particle on a circle
        (a cord or link to a fixed point, or a circular path) goes on until the cord's
        tension or the surface's push falls to zero."""
        body, until, first, *rest = c
        words = (str(first), *(str(w) for w in rest))
        event = " ".join(words[1:])
        if words in (("rolls",), ("stops",)):
            raise SpecError(
                f"'until {words[0]}' ends an interval whose time is named",
                self._at(first),
                hint=f"write e.g. 'travel {body}: for t_1, until {words[0]}' and find t_1",
            )
        if len(words) != 2 or event not in ("slack", "lost"):
            raise SpecError(
                f"unknown end of a travel: 'until {' '.join(words)}'",
                self._at(first),
                hint="write 'until CORD slack', 'until contact lost' (or, on a 'for' line, "
                "', until rolls' / ', until stops')",
            )
        prop = Prop("until", word=event, about=words[0], line=self.line, column=self._col(until))
        return self._stmt("travel", body, body=str(body), word="until", props=(prop,))

    def travel_turns_stmt(self, c: list[Any]) -> SceneStmt:
        (body, angle, sense), stops = self._stops(c)
        self._sense(sense)
        return self._stmt("travel", body, body=str(body), value=angle, word=str(sense), props=stops)

    def travel_turns3_stmt(self, c: list[Any]) -> SceneStmt:
        """``travel B: turns EXPR about (ux, uy, uz) [, from omega W]``: in a 3D scene,
        state 2 is reached when the frame that ``rotates`` has turned through EXPR about u
        (right-hand); state 1 is at rest, or has the frame turning at W."""
        body, angle, axis, *start = c
        props = tuple(
            Prop("from", values=(w,), line=self.line, column=self.offset + 1) for w in start
        )
        return self._stmt(
            "travel3", body, body=str(body), value=angle, vectors=(axis,), props=props
        )

    def prop_guide(self, c: list[Any]) -> Prop:
        return self._prop("guide", c)

    def velocity_stmt(self, c: list[Any]) -> SceneStmt:
        body, value, direction = c
        return self._stmt("velocity", body, body=str(body), value=value, direction=direction)

    def motion_stmt(self, c: list[Token]) -> SceneStmt:
        body, motion = c
        return self._stmt("motion", body, body=str(body), word=str(motion))

    # ---- linkage lines (dynsolve.linkage)
    def bar_stmt(self, c: list[Any]) -> SceneStmt:
        """``bar BC: B to C [to E …] [, length L] [, angle theta]``: a rigid link through
        joint points, in order; its length and direction (from the first point to the
        second) may fix where the second point is."""
        name, *rest = c
        points = tuple(str(t) for t in rest if isinstance(t, Token))
        props = tuple(p for p in rest if isinstance(p, Prop))
        return self._stmt("bar", name, name=str(name), other=" ".join(points), props=props)

    def prop_length(self, c: list[Any]) -> Prop:
        return self._prop("length", c, values=(c[0],))

    def prop_angle(self, c: list[Any]) -> Prop:
        return self._prop("angle", c, values=(c[0],))

    def joint_stmt(self, c: list[Any]) -> SceneStmt:
        """``joint C: (x, y)`` (where C is at the instant) or ``joint C: near (x, y)``
        (roughly where: it picks the assembly)."""
        name, *rest = c
        near = isinstance(rest[0], Token) and rest[0].type == "NEAR"
        return self._stmt(
            "joint", name, name=str(name), vectors=(rest[-1],), word="near" if near else ""
        )

    def slider_stmt(self, c: list[Any]) -> SceneStmt:
        """``slider C: along DIR [, through A] [, mass m]``: joint C slides in a fixed
        straight guide; with a mass, C carries a block (a piston) of that mass."""
        name, direction, *rest = c
        through = [t for t in rest if isinstance(t, Token)]
        return self._stmt(
            "slider",
            name,
            name=str(name),
            direction=direction,
            other=str(through[0]) if through else "",
            props=tuple(p for p in rest if isinstance(p, Prop)),
        )

    def rolls_wheel_stmt(self, c: list[Any]) -> SceneStmt:
        """``rolls W: radius r [, normal DIR]``: the bar W is a wheel centred on its first
        point, rolling without slipping on fixed ground whose normal is DIR (up)."""
        name, radius, *normal = c
        return self._stmt(
            "wheel", name, body=str(name), value=radius, direction=normal[0] if normal else None
        )

    def mesh_stmt(self, c: list[Any]) -> SceneStmt:
        """``mesh A with B: radii r_A, r_B[, internal][, pressure angle phi]``: gears A and
        B (bars centred on their first points) in mesh, their pitch circles rolling on each
        other: outside each other, or (``internal``) the smaller inside the larger, a ring
        gear; the teeth push along the line of action at ``phi`` to the common tangent."""
        first, second, r_first, r_second, *rest = c
        internal = any(isinstance(t, Token) and t.type == "INTERNAL" for t in rest)
        pressure = [e for e in rest if e is not None and not isinstance(e, Token)]
        return self._stmt(
            "mesh",
            first,
            body=str(first),
            other=str(second),
            vectors=((r_first, r_second),),
            word="internal" if internal else "",
            value=pressure[0] if pressure else None,
        )

    def slider_bar_stmt(self, c: list[Any]) -> SceneStmt:
        """``slider B: along bar CD``: joint B slides along the (moving) bar CD, a pin
        in a slot or a collar on a rod (``, mass m``: a collar of that mass)."""
        name, bar, *props = c
        return self._stmt("slider", name, name=str(name), body=str(bar), props=tuple(props))

    def alpha_stmt(self, c: list[Any]) -> SceneStmt:
        body, value, *_ = c
        return self._stmt("alpha", body, body=str(body), value=value, word=self._turn("alpha", c))

    def _turn(self, kind: str, c: list[Any]) -> str:
        """The sense of an ``omega``/``alpha`` line: cw or ccw, required unless the value is
        a literal 0 (left out, ccw was taken silently and a cw drive came out mirrored)."""
        body, value, *sense = c
        if sense:
            self._sense(sense[0])
            return str(sense[0])
        if isinstance(value, Num) and value.value == 0:
            return "ccw"
        raise SpecError(
            f"the sense of {kind} {body} is missing",
            self._at(body),
            f"write '{kind} {body}: {value} cw' or '… ccw' (the figure's arrow)",
        )

    def acceleration_stmt(self, c: list[Any]) -> SceneStmt:
        point, value, direction = c
        return self._stmt("acceleration", point, body=str(point), value=value, direction=direction)

    def branch_stmt(self, c: list[Token]) -> SceneStmt:
        return self._stmt("branch", c[0], word=str(c[0]))

    def method_stmt(self, c: list[Token]) -> SceneStmt:
        return self._stmt("method", c[0], word=str(c[0]))

    def _sense(self, token: Token) -> None:
        if str(token) not in ("cw", "ccw"):
            raise SpecError(
                f"'{token}' is not a sense of rotation", self._at(token), "write cw or ccw"
            )

    def _prop(self, key: str, c: list[Any], **fields: Any) -> Prop:
        return Prop(key, line=self.line, column=self.offset + 1, **fields)

    def prop_mass(self, c: list[Any]) -> Prop:
        return self._prop("mass", c, values=(c[0],))

    def prop_weight(self, c: list[Any]) -> Prop:
        return self._prop("weight", c, values=(c[0],))

    def prop_gyration(self, c: list[Any]) -> Prop:
        return self._prop("gyration", c, values=(c[0],), about=str(c[1]) if len(c) > 1 else "")

    def prop_inertia(self, c: list[Any]) -> Prop:
        return self._prop("inertia", c, values=(c[0],), about=str(c[1]) if len(c) > 1 else "")

    def prop_at(self, c: list[Any]) -> Prop:
        return self._prop("at", c, vector=c[0])

    def prop_density(self, c: list[Any]) -> Prop:
        return self._prop("density", c, values=(c[0],))

    def prop_thickness(self, c: list[Any]) -> Prop:
        return self._prop("thickness", c, values=(c[0],))

    def prop_composite(self, c: list[Any]) -> Prop:
        return self._prop("composite", c)

    def prop_shape(self, c: list[Any]) -> Prop:
        shape, *sizes = c
        return self._prop("shape", c, word=str(shape), values=tuple(sizes))

    def prop_list(self, c: list[Prop]) -> tuple[Prop, ...]:
        return tuple(c)

    def prop_normal(self, c: list[Any]) -> Prop:
        return self._prop("normal", c, direction=c[0])

    def prop_smooth(self, c: list[Any]) -> Prop:
        return self._prop("smooth", c)

    def prop_mu_s(self, c: list[Any]) -> Prop:
        return self._prop("mu_s", c, values=(c[0],))

    def prop_mu_k(self, c: list[Any]) -> Prop:
        return self._prop("mu_k", c, values=(c[0],))

    def prop_slides(self, c: list[Any]) -> Prop:
        return self._prop("slides", c, direction=c[0])

    def prop_axes(self, c: list[Token]) -> Prop:
        return self._prop("components", c, word=str(c[0]))

    def at_point(self, c: list[Token]) -> Location:
        return Location(point=str(c[0]), line=self.line, column=self._col(c[0]))

    def at_vector(self, c: list[Any]) -> Location:
        return Location(vector=c[0], line=self.line, column=self.offset + 1)

    def vector(self, c: list[Any]) -> tuple[Expr, Expr]:
        return (c[0], c[1])

    def vector3(self, c: list[Any]) -> tuple[Expr, Expr, Expr]:
        return (c[0], c[1], c[2])

    def prop_at3(self, c: list[Any]) -> Prop:
        return self._prop("at3", c, vector=c[0])

    # ---- 3D scene lines (dynsolve.rigid3d)
    def rotates_stmt(self, c: list[Any]) -> SceneStmt:
        """``rotates B: about (u), through (P), omega w [, alpha a]``: B turns about a
        fixed axis."""
        body, axis, through, omega, *alpha = c
        props = tuple(
            Prop("alpha", values=(a,), line=self.line, column=self.offset + 1) for a in alpha
        )
        return self._stmt(
            "rotates", body, body=str(body), vectors=(axis, through), value=omega, props=props
        )

    def spins_stmt(self, c: list[Any]) -> SceneStmt:
        """``spins B: about (s), omega w_s [, alpha a_s]``: B spins about its own axis s
        relative to the frame that ``rotates`` (precesses)."""
        body, axis, omega, *alpha = c
        props = tuple(
            Prop("alpha", values=(a,), line=self.line, column=self.offset + 1) for a in alpha
        )
        return self._stmt("spins", body, body=str(body), vectors=(axis,), value=omega, props=props)

    def spins_through_stmt(self, c: list[Any]) -> SceneStmt:
        """``spins B: about (s), through (P), omega w_s [, alpha a_s]``: B turns about an
        axis s through P that the frame carries (a bar pinned to a turning shaft)."""
        body, axis, through, omega, *alpha = c
        props = tuple(
            Prop("alpha", values=(a,), line=self.line, column=self.offset + 1) for a in alpha
        )
        return self._stmt(
            "spins", body, body=str(body), vectors=(axis, through), value=omega, props=props
        )

    def nutates_stmt(self, c: list[Any]) -> SceneStmt:
        """``nutates B: about (n), through (P), omega w_n [, alpha a_n]``: B's axis turns
        about n through P, both carried by the frame that ``rotates`` (a top's nutation,
        an arm being raised while it precesses)."""
        body, axis, through, omega, *alpha = c
        props = tuple(
            Prop("alpha", values=(a,), line=self.line, column=self.offset + 1) for a in alpha
        )
        return self._stmt(
            "nutates", body, body=str(body), vectors=(axis, through), value=omega, props=props
        )

    def bearing_stmt(self, c: list[Any]) -> SceneStmt:
        name, at, kind = c
        return self._stmt("bearing", name, name=str(name), vectors=(at,), word=str(kind))

    def axis_stmt(self, c: list[Any]) -> SceneStmt:
        body, vector = c
        return self._stmt("axis", body, body=str(body), vectors=(vector,))

    def axes_stmt(self, c: list[Any]) -> SceneStmt:
        body, x_axis, y_axis = c
        return self._stmt("axes", body, body=str(body), vectors=(x_axis, y_axis))

    def inertia3_stmt(self, c: list[Any]) -> SceneStmt:
        body, *values = c
        vectors = (tuple(values[:3]),)
        if len(values) > 3:  # ', products I_xy, I_yz, I_zx'
            vectors += (tuple(values[3:]),)
        return self._stmt("inertia3", body, body=str(body), vectors=vectors)

    def torque_stmt(self, c: list[Any]) -> SceneStmt:
        name, body = c
        return self._stmt("torque", name, name=str(name), body=str(body))

    def dir_word(self, c: list[Token]) -> Direction:
        return Direction("word", word=str(c[0]), line=self.line, column=self._col(c[0]))

    def dir_angle(self, c: list[Any]) -> Direction:
        return Direction("angle", angle=c[0], line=self.line, column=self.offset + 1)

    def dir_toward(self, c: list[Token]) -> Direction:
        return Direction("toward", point=str(c[0]), line=self.line, column=self._col(c[0]))

    def dir_vector(self, c: list[Any]) -> Direction:
        return Direction("vector", vector=c[0], line=self.line, column=self.offset + 1)

    def find_line(self, c: list[Any]) -> list[FindItem]:
        return [item for item in c if isinstance(item, FindItem)]

    def _tolerance_value(self, c: list[Any]) -> tuple[Fraction, str]:
        value, text, column = c[1]
        if value < 0:
            raise SpecError(
                "a tolerance cannot be negative",
                Position(self.file, self.line, column),
                hint=f"write '+- {text.lstrip('-')}'",
            )
        return value, text

    def rel_tolerance(self, c: list[Any]) -> Tolerance:
        value, text = self._tolerance_value(c)
        return Tolerance("rel", value / 100, None, f"± {text}%")

    def abs_tolerance(self, c: list[Any]) -> Tolerance:
        value, text = self._tolerance_value(c)
        unit = c[2] if len(c) > 2 else None
        return Tolerance("abs", value, unit, f"± {text}")

    def answer_line(self, c: list[Any]) -> Answer:
        token, quantity, *rest = c
        tolerance = next((r for r in rest if isinstance(r, Tolerance)), None)
        direction = next((str(r) for r in rest if isinstance(r, Token)), None)
        return Answer(
            str(token),
            quantity,
            None,
            tolerance,
            direction,
            self.line,
            self._col(token),  # type: ignore[arg-type]
        )

    def answer_formula(self, c: list[Any]) -> Answer:
        token, formula = c
        return Answer(str(token), None, formula, None, None, self.line, self._col(token))


def unit_text(factors: tuple[UnitFactor, ...]) -> str:
    """Canonical, pint-parsable text of unit factors: ``kg*m^2/s^2``.

    >>> unit_text((UnitFactor("N", Fraction(1), 1, 1), UnitFactor("s", Fraction(-2), 1, 3)))
    'N/s^2'
    """

    def power(name: str, exponent: Fraction) -> str:
        if exponent == 1:
            return name
        shown = str(exponent) if exponent.denominator == 1 else f"({exponent})"
        return f"{name}^{shown}"

    top = [power(f.name, f.exponent) for f in factors if f.exponent > 0]
    bottom = [power(f.name, -f.exponent) for f in factors if f.exponent < 0]
    text = "*".join(top) or ("1" if bottom else "")
    if bottom:
        text += "/" + (bottom[0] if len(bottom) == 1 else "(" + "*".join(bottom) + ")")
    return text


def _power(factor: UnitFactor, exponent: Fraction) -> UnitFactor:
    return UnitFactor(factor.name, factor.exponent * exponent, factor.line, factor.column)


def _literal_value(expr: Expr) -> Fraction | None:
    if isinstance(expr, Num):
        return expr.value
    if isinstance(expr, Unary) and isinstance(expr.operand, Num):
        return -expr.operand.value
    return None


def _finish(parts: _Sections, file: str, lines: Mapping[str, int]) -> Spec:
    """The sections frozen into a Spec; ``lines`` are their headers' lines. Sections no
    front end reads together are an error, never one of them silently ignored; so is a
    section header with nothing under it."""
    for key, line in lines.items():
        if key in _FIELDS and key != "find" and not getattr(parts, _FIELDS[key]):
            raise SpecError(
                f"section '{key}:' is empty",
                Position(file, line, 1),
                hint=f"indent the lines of '{key}:' under it, or remove the header",
            )
    if parts.scene and parts.kinematics:
        raise SpecError(
            f"a scene: section cannot yet be combined with a kinematics: section "
            f"(line {lines['kinematics']}): one of them would be ignored",
            Position(file, lines["scene"], 1),
            hint="solve the particle's motion law (kinematics:) and the scene in two specs, "
            "or write the motion in the scene with travel lines",
        )
    if parts.defines and parts.scene is None and parts.kinematics is None:
        raise SpecError(
            "'define:' lists quantities of a scene or a motion; this spec has no 'scene:' "
            "or 'kinematics:' section",
            Position(file, parts.define_line, 1),
            hint="in equation mode write the expression as an equation: 'dE = T1 - T2'",
        )
    givens = tuple(parts.givens or ())
    _check_given_names(givens, file)
    return Spec(
        file=file,
        title=parts.title or Path(file).stem,
        source=parts.source,
        system=parts.system,  # type: ignore[arg-type]
        givens=givens,
        equations=tuple(parts.equations or ()),
        finds=tuple(parts.finds or ()),
        answers=tuple(parts.answers or ()),
        system_line=parts.system_line,
        scene=tuple(parts.scene or ()),
        kinematics=tuple(parts.kinematics or ()),
        defines=tuple(parts.defines or ()),
        vary=_checked_vary(tuple(parts.vary or ()), givens, file),
        grading=tuple(parts.grading or ()),
    )


def _checked_vary(
    vary: tuple[VaryStmt, ...], givens: tuple[Given, ...], file: str
) -> tuple[VaryStmt, ...]:
    """Only a given with a value may vary, and each at most once."""
    valued = {g.name for g in givens if g.quantity is not None}
    seen: dict[str, int] = {}
    for stmt in vary:
        where = Position(file, stmt.line, stmt.column)
        if stmt.kind == "allow":
            continue
        if stmt.name not in valued:
            symbolic = any(g.name == stmt.name for g in givens)
            close = difflib.get_close_matches(stmt.name, sorted(valued), n=1)
            hint = (
                "give it a value in 'given:' first"
                if symbolic
                else f"did you mean '{close[0]}'?"
                if close
                else "only givens with a value can vary: " + (", ".join(sorted(valued)) or "none")
            )
            what = "a symbolic given" if symbolic else "not a given"
            raise SpecError(f"'{stmt.name}' cannot vary: it is {what}", where, hint=hint)
        if stmt.name in seen:
            raise SpecError(
                f"'{stmt.name}' varies twice (first on line {seen[stmt.name]})",
                where,
                hint="keep one vary line per given",
            )
        seen[stmt.name] = stmt.line
    return vary


def _check_given_names(givens: tuple[Given, ...], file: str) -> None:
    seen: dict[str, int] = {}
    for given in givens:
        where = Position(file, given.line, given.column)
        if given.name in FUNCTIONS or given.name == "pi":
            raise SpecError(
                f"'{given.name}' is reserved (a function or constant)",
                where,
                hint="choose another name",
            )
        if given.name in seen:
            raise SpecError(
                f"'{given.name}' is given twice (first on line {seen[given.name]})",
                where,
                hint="remove one of them",
            )
        seen[given.name] = given.line


def iter_names(expr: Expr) -> Iterator[Name]:
    """Every :class:`Name` in ``expr``, left to right.

    >>> [n.text for n in iter_names(Binary("*", Name("m", 1, 1), Name("g", 1, 3), 1, 1))]
    ['m', 'g']
    """
    stack: list[Expr] = [expr]
    while stack:
        node = stack.pop()
        if isinstance(node, Name):
            yield node
        elif isinstance(node, Unary):
            stack.append(node.operand)
        elif isinstance(node, Binary):
            stack.extend((node.right, node.left))
        elif isinstance(node, Call):
            stack.extend(reversed(node.args))
