"""Print spec expressions as written: plain text with Greek letters, or LaTeX.

The user's own form is kept (no reordering, no simplification), so a derivation shows
each equation the way it was written.

>>> from dynsolve.spec.parser import parse_spec
>>> eq = parse_spec("equations:\\n  T*r = I_O*alpha/2 + sqrt(x^2)", "p.dyn").equations[0]
>>> statement_text(eq)
'T*r = I_O*α/2 + sqrt(x^2)'
>>> statement_latex(eq)
'T r = \\\\frac{I_{O} \\\\alpha}{2} + \\\\sqrt{x^{2}}'
"""

from __future__ import annotations

from collections.abc import Callable

from dynsolve.names import latex_name, pretty
from dynsolve.spec.ast import Binary, Call, EquationStmt, Expr, Name, Num, Unary

_LEVEL = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}
_LATEX_RELATION = {"=": "=", ">=": "\\ge", "<=": "\\le", ">": ">", "<": "<"}
_LATEX_FUNCTION = {
    "sin": "\\sin", "cos": "\\cos", "tan": "\\tan", "asin": "\\arcsin", "acos": "\\arccos",
    "atan": "\\arctan", "exp": "\\exp", "log": "\\ln", "atan2": "\\operatorname{atan2}",
}  # fmt: skip


def _level(expr: Expr) -> int:
    if isinstance(expr, Binary):
        return _LEVEL[expr.op]
    if isinstance(expr, Unary) or (isinstance(expr, Num) and expr.value < 0):
        return 3
    return 5


def expr_text(expr: Expr, name: Callable[[str], str] = pretty) -> str:
    """``expr`` as text; ``name`` maps each name for display (Greek letters by default)."""
    if isinstance(expr, Num):
        return expr.text
    if isinstance(expr, Name):
        return "π" if expr.text == "pi" and name is pretty else name(expr.text)
    if isinstance(expr, Unary):
        return "-" + _wrapped(expr.operand, 3, name)
    if isinstance(expr, Call):
        return f"{expr.function}({', '.join(expr_text(a, name) for a in expr.args)})"
    level = _LEVEL[expr.op]
    if expr.op == "^":
        return f"{_wrapped(expr.left, level + 1, name)}^{_wrapped(expr.right, level, name)}"
    right_level = level + 1 if expr.op in "-/" else level
    spaced = f" {expr.op} " if expr.op in "+-" else expr.op
    return f"{_wrapped(expr.left, level, name)}{spaced}{_wrapped(expr.right, right_level, name)}"


def _wrapped(expr: Expr, level: int, name: Callable[[str], str]) -> str:
    text = expr_text(expr, name)
    return f"({text})" if _level(expr) < level else text


def statement_text(statement: EquationStmt) -> str:
    """An equation or constraint as text with Greek letters."""
    return f"{expr_text(statement.lhs)} {statement.relation} {expr_text(statement.rhs)}"


def expr_latex(expr: Expr) -> str:
    """``expr`` as LaTeX math, keeping the written order of terms."""
    if isinstance(expr, Num):
        return expr.text.replace("e", "\\times 10^{").rstrip() + ("}" if "e" in expr.text else "")
    if isinstance(expr, Name):
        return "\\pi" if expr.text == "pi" else latex_name(expr.text)
    if isinstance(expr, Unary):
        return "-" + _latex_wrapped(expr.operand, 3)
    if isinstance(expr, Call):
        if expr.function == "sqrt":
            return f"\\sqrt{{{expr_latex(expr.args[0])}}}"
        if expr.function == "abs":
            return f"\\left|{expr_latex(expr.args[0])}\\right|"
        args = ", ".join(expr_latex(a) for a in expr.args)
        return f"{_LATEX_FUNCTION[expr.function]}\\left({args}\\right)"
    if expr.op == "/":
        return f"\\frac{{{expr_latex(expr.left)}}}{{{expr_latex(expr.right)}}}"
    if expr.op == "^":
        return f"{_latex_wrapped(expr.left, 5)}^{{{expr_latex(expr.right)}}}"
    if expr.op == "*":
        left, right = _latex_wrapped(expr.left, 2), _latex_wrapped(expr.right, 2)
        joiner = " \\cdot " if isinstance(expr.right, Num) else " "
        return f"{left}{joiner}{right}"
    right_level = 2 if expr.op == "-" else 1
    return f"{_latex_wrapped(expr.left, 1)} {expr.op} {_latex_wrapped(expr.right, right_level)}"


def _latex_wrapped(expr: Expr, level: int) -> str:
    text = expr_latex(expr)
    if isinstance(expr, Binary) and expr.op == "/" and level <= 4:
        return text
    return f"\\left({text}\\right)" if _level(expr) < level else text


def statement_latex(statement: EquationStmt) -> str:
    """An equation or constraint as LaTeX math."""
    relation = _LATEX_RELATION[statement.relation]
    return f"{expr_latex(statement.lhs)} {relation} {expr_latex(statement.rhs)}"
