"""Solving one block: linear exactly, nonlinear symbolically within a time budget, else numerically.

A block is a square set of equations (residuals ``lhs - rhs``) in its own unknowns;
knowns and the values of earlier blocks are given. The result is every candidate
root found, each with its values and, when shown, its formulas in terms of the
knowns and earlier unknowns kept as symbols. Choosing among the candidates is
:mod:`dynsolve.solver.roots`'s job.

* linear blocks: ``linear_eq_to_matrix`` + ``linsolve`` — exact, method ``linear``;
  a singular matrix leaves the dependent unknowns *free* (under-determined);
* nonlinear blocks: ``sympy.solve`` under ``options.time_budget`` CPU seconds (SIGPROF,
  else a cooperative clock check; a budget <= 0 skips it), method ``symbolic``; when it times
  out, cannot solve or finds nothing: Newton/secant root finding (mpmath, as
  ``sympy.nsolve`` does) from several starting points, method ``numeric``.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> solution = solve_block([x + y - 3, x - y - 1], [x, y], {})
>>> solution.method, dict(solution.candidates[0].values)
('linear', {x: 2, y: 1})
"""

from __future__ import annotations

import gc
import math
import random
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field, replace
from fractions import Fraction
from types import FrameType
from typing import TypeVar

import mpmath
import sympy
from mpmath.libmp import NoConvergence
from sympy.polys.matrices import DomainMatrix
from sympy.polys.polyerrors import BasePolynomialError
from sympy.solvers.solveset import NonlinearError

from dynsolve.budget import step
from dynsolve.numbers import MAX_DIGITS, mpmath_function, probe_point, real_value, tidy
from dynsolve.solver.evaluate import mp_value
from dynsolve.solver.outcome import Method
from dynsolve.system import SolveOptions

FORMULA_MAX_OPS = 60  # formulas longer than this (sympy.count_ops) are not shown
FORMULA_MAX_UNKNOWNS = 8  # bigger linear blocks are solved with the numbers substituted
START_FACTORS = (1, 0.5, 2, 10, -1, 0.1, -0.5, -2, 100, -10, 0.01, 1000, -100)
NUMERIC_DIGITS = 15
GUARD_DIGITS = 20  # the root finder works this many digits beyond the ones kept (cancellation)
DEFAULT_OPTIONS = SolveOptions()
_SYMPY_GAVE_UP = (
    NotImplementedError,
    ValueError,
    TypeError,
    ArithmeticError,
    RecursionError,
    BasePolynomialError,
)
_TIMEOUT = "symbolic solve exceeded the time budget"
_DIGITS: ContextVar[int] = ContextVar("numeric_digits", default=NUMERIC_DIGITS)

_Result = TypeVar("_Result")


@dataclass(frozen=True)
class Candidate:
    """One root of a block: its values and, when shown, its formulas."""

    values: Mapping[sympy.Symbol, sympy.Expr]
    formulas: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)


@dataclass(frozen=True)
class BlockSolution:
    """Every root found for one block, before any is chosen."""

    unknowns: tuple[sympy.Symbol, ...]
    method: Method
    candidates: tuple[Candidate, ...]
    note: str = ""
    free: tuple[sympy.Symbol, ...] = ()  # unknowns the block leaves undetermined
    missing_equations: int = 0  # independent equations the block lacks
    inconsistent: bool = False  # the block's equations contradict each other
    exhaustive: bool = True  # False when the roots come from a numeric search


def numeric_digits() -> int:
    """The significant digits numeric values are computed to (15, float64-like, by default).

    >>> numeric_digits()
    15
    """
    return _DIGITS.get()


@contextmanager
def working_digits(digits: int) -> Iterator[None]:
    """Compute numeric values to ``digits`` significant digits inside the ``with`` body.

    ``--mode auto`` re-solves at 30 digits to measure how many float64 loses.

    >>> with working_digits(30):
    ...     numeric_digits()
    30
    """
    token = _DIGITS.set(digits)
    try:
        yield
    finally:
        _DIGITS.reset(token)


class BudgetExceeded(BaseException):
    """The symbolic time budget ran out (BaseException so sympy cannot swallow it)."""


def as_expr(value: object) -> sympy.Expr:
    """An internal number or expression as sympy, without parsing (never from text).

    >>> as_expr(3), as_expr(Fraction(1, 4)), as_expr(sympy.pi)
    (3, 1/4, pi)
    """
    if isinstance(value, sympy.Basic):
        return value  # type: ignore[return-value]
    if isinstance(value, int) and not isinstance(value, bool):
        return sympy.Integer(value)
    if isinstance(value, Fraction):
        return sympy.Rational(value.numerator, value.denominator)
    if isinstance(value, float):
        return sympy.Float(value)
    raise TypeError(f"not a number or sympy expression: {value!r}")


@contextmanager
def time_budget(seconds: float) -> Iterator[None]:
    """Raise a private exception inside the ``with`` body once ``seconds`` have passed.

    The seconds are the process's CPU time (a budget that does not shrink when the machine
    is busy, so the path a solve takes is the same on a loaded machine). Uses
    ``SIGPROF``/``setitimer(ITIMER_PROF)`` in the main thread where it exists (the previous
    handler and timer are always restored); elsewhere (Windows, other threads) a
    cooperative check of the CPU clock at each Python function call. The whole run has
    its own wall-clock budget besides (:mod:`dynsolve.budget`).

    >>> with time_budget(5.0):
    ...     total = sum(range(10))
    >>> total
    45
    """
    with step("solving a nonlinear block symbolically (sympy)"):
        if seconds <= 0:
            yield
        elif hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread():
            with _alarm(seconds):
                yield
        else:
            with _cooperative(seconds):
                yield


REPEAT = 0.1  # CPU seconds between repeated expiries of a block's budget


@contextmanager
def _alarm(seconds: float) -> Iterator[None]:
    """The budget by ``SIGPROF``/``setitimer(ITIMER_PROF)`` (POSIX, main thread): seconds of
    the process's CPU time, not of the wall clock, so that which path a solve takes (a
    brief symbolic attempt, or the numeric fallback) does not depend on the machine's load."""
    armed = [True]

    def expire(signum: int, frame: FrameType | None) -> None:
        # again every REPEAT s until the block ends: a bare 'except:' in a library may
        # swallow one, and the work must not go on; not while Python runs a finaliser or
        # a garbage-collection callback (an exception there is "unraisable": it is lost,
        # and a test runner's hook fails on it), where the next expiry raises instead
        if armed[0] and not in_finaliser(frame):
            raise BudgetExceeded

    previous_handler = signal.signal(signal.SIGPROF, expire)
    previous_delay, previous_interval = signal.setitimer(signal.ITIMER_PROF, seconds, REPEAT)
    started = time.process_time()
    try:
        yield
    finally:
        armed[0] = False
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous_handler or signal.SIG_DFL)
        if previous_delay > 0:
            left = max(previous_delay - (time.process_time() - started), 1e-6)
            signal.setitimer(signal.ITIMER_PROF, left, previous_interval)


def in_finaliser(frame: FrameType | None, depth: int = 64) -> bool:
    """Whether ``frame`` (or one of the ``depth`` frames that called it) runs a ``__del__``,
    a garbage-collection callback or the unraisable-exception hook: code that Python calls
    on its own, where an exception cannot reach the solve.

    >>> import sys
    >>> in_finaliser(sys._getframe())
    False
    """
    hook = getattr(sys.unraisablehook, "func", sys.unraisablehook)  # functools.partial
    codes = {getattr(getattr(c, "func", c), "__code__", None) for c in gc.callbacks}
    codes.add(getattr(hook, "__code__", None))
    codes.discard(None)
    while frame is not None and depth > 0:
        if frame.f_code.co_name == "__del__" or frame.f_code in codes:
            return True
        frame, depth = frame.f_back, depth - 1
    return False


@contextmanager
def _cooperative(seconds: float) -> Iterator[None]:
    """The budget without signals (Windows, other threads): a profile hook checks the
    process's CPU time at each Python function call and raises once it is spent."""
    deadline = time.process_time() + seconds
    previous = sys.getprofile()

    def check(frame: FrameType, event: str, argument: object) -> None:
        if event == "call" and time.process_time() > deadline and not in_finaliser(frame):
            sys.setprofile(previous)
            raise BudgetExceeded

    sys.setprofile(check)
    try:
        yield
    finally:
        sys.setprofile(previous)


def _within_budget(work: Callable[[], _Result], seconds: float) -> tuple[_Result | None, bool]:
    """Run ``work`` under a time budget: ``(result, False)`` or ``(None, True)`` on timeout."""
    if seconds <= 0:
        return None, True
    try:
        with time_budget(seconds):
            return work(), False
    except BudgetExceeded:
        return None, True


def substitute(expr: sympy.Expr, given: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """Replace given symbols by their values (structural replacement, evaluated).

    >>> import sympy
    >>> m, g = sympy.symbols("m g")
    >>> substitute(m * g, {m: 2, g: sympy.Rational(981, 100)})
    981/50
    """
    expr = as_expr(expr)
    # only the symbols present: converting every given per call is quadratic in big scenes
    return expr.xreplace({k: as_expr(given[k]) for k in expr.free_symbols if k in given})


def is_finite(value: sympy.Expr) -> bool:
    """False when ``value`` holds an infinity or ``nan`` (e.g. after dividing by zero).

    >>> import sympy
    >>> is_finite(sympy.Rational(1, 2)), is_finite(sympy.zoo)
    (True, False)
    """
    return not value.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo)


def solve_block(
    residuals: Sequence[sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    given: Mapping[sympy.Symbol, sympy.Expr],
    options: SolveOptions = DEFAULT_OPTIONS,
) -> BlockSolution:
    """Find every root of ``residuals = 0`` for ``unknowns``, with ``given`` values substituted.

    >>> import sympy
    >>> v, g, h = sympy.symbols("v g h")
    >>> solution = solve_block([v**2 - 2 * g * h], [v], {g: 10, h: 5})
    >>> solution.method, [c.values[v] for c in solution.candidates]
    ('symbolic', [-10, 10])
    >>> [c.formulas[v] for c in solution.candidates]
    [-sqrt(2)*sqrt(g*h), sqrt(2)*sqrt(g*h)]
    """
    unknowns = tuple(unknowns)
    present = set().union(*(as_expr(r).free_symbols for r in residuals))
    given = {k: as_expr(given[k]) for k in present if k in given}  # not all: n² in big scenes
    try:
        matrix, rhs = sympy.linear_eq_to_matrix(list(residuals), list(unknowns))
    except NonlinearError:
        return _solve_nonlinear(list(residuals), unknowns, given, options)
    return _solve_linear(matrix, rhs, unknowns, given, options)


# --- linear blocks -----------------------------------------------------------------


def _solve_linear(
    matrix: sympy.Matrix,
    rhs: sympy.Matrix,
    unknowns: tuple[sympy.Symbol, ...],
    given: Mapping[sympy.Symbol, sympy.Expr],
    options: SolveOptions,
) -> BlockSolution:
    """Solve ``matrix * unknowns = rhs`` exactly; formulas first when they are shown.

    Numeric mode solves a block whose entries are all numbers once the knowns are put in
    in floating point (:func:`solve_linear_in_floats`), without formulas."""
    numbers = matrix.xreplace(given), rhs.xreplace(given)
    if options.mode == "numeric" or _inexact(*numbers, unknowns):
        floats = solve_linear_in_floats(*numbers, unknowns)
        if floats is not None:
            return floats
    if options.show_formulas and len(unknowns) <= FORMULA_MAX_UNKNOWNS:
        formulas, _ = _within_budget(
            lambda: _unique_linear_solution(matrix, rhs, unknowns), options.time_budget
        )
        if formulas is not None:
            values = {u: substitute(f, given) for u, f in formulas.items()}
            if all(is_finite(v) for v in values.values()):
                candidate = Candidate(_in_mode(values, options), shown_formulas(formulas))
                return BlockSolution(unknowns, "linear", (candidate,))
    return _solve_linear_values(*numbers, unknowns, options)


INEXACT_FORMULA_UNKNOWNS = 3  # a larger block with decimals in it is solved in floats


def _inexact(matrix: sympy.Matrix, rhs: sympy.Matrix, unknowns: tuple[sympy.Symbol, ...]) -> bool:
    """A block too large for formulas whose entries hold decimals already (a linkage placed
    by loop closure): its formulas would be long sums of 30-digit numbers, and eliminating
    them exactly grows their exponents without bound (10^36683 seen in a loaded four-bar),
    so it is solved in floating point with guard digits, as numeric mode does.

    >>> x, y, z, w = sympy.symbols("x y z w")
    >>> eye = sympy.eye(4) * sympy.Float(0.5)
    >>> _inexact(eye, sympy.zeros(4, 1), (x, y, z, w)), _inexact(sympy.eye(4), eye[:, 0], (x,))
    (True, False)
    """
    if len(unknowns) <= INEXACT_FORMULA_UNKNOWNS:
        return False
    return matrix.has(sympy.Float) or rhs.has(sympy.Float)


def _unique_linear_solution(
    matrix: sympy.Matrix, rhs: sympy.Matrix, unknowns: tuple[sympy.Symbol, ...]
) -> dict[sympy.Symbol, sympy.Expr] | None:
    """The unique (generic) solution of a linear system, or None if there is none."""
    solution = linear_solution(matrix, rhs, unknowns)
    if solution is None or any(set(unknowns) & expr.free_symbols for expr in solution):
        return None
    return dict(zip(unknowns, solution, strict=True))


def _solve_linear_values(
    matrix: sympy.Matrix,
    rhs: sympy.Matrix,
    unknowns: tuple[sympy.Symbol, ...],
    options: SolveOptions,
) -> BlockSolution:
    """Solve the substituted linear system; report dependent or contradictory equations."""
    solution = linear_solution(matrix, rhs, unknowns)
    if solution is None:
        note = "the equations of this block contradict each other"
        return BlockSolution(unknowns, "linear", (), note=note, inconsistent=True)
    mine = set(unknowns)
    parameters = mine & set().union(*(e.free_symbols for e in solution))
    pairs = list(zip(unknowns, solution, strict=True))
    free = tuple(u for u, e in pairs if not e.free_symbols.isdisjoint(mine))
    values = {u: e for u, e in pairs if u not in free}
    note = ""
    if free:
        names = ", ".join(map(str, free))
        note = f"the equations of this block are dependent: {names} not determined"
    return BlockSolution(
        unknowns,
        "linear",
        (Candidate(_in_mode(values, options)),),
        note=note,
        free=free,
        missing_equations=len(parameters),
    )


def linear_solution(
    matrix: sympy.Matrix, rhs: sympy.Matrix, unknowns: Sequence[sympy.Symbol]
) -> tuple[sympy.Expr, ...] | None:
    """The solution of ``matrix * unknowns = rhs`` as ``linsolve`` gives it (an unknown
    left free stands for itself, the ones depending on it hold it), or None when the
    equations contradict each other.

    A matrix of rational numbers, or of polynomials and ratios of them in letters with
    rational coefficients, is reduced to row echelon form as a sparse ``DomainMatrix``
    over that field: the reduced form is unique, so the solution is linsolve's, but a chain
    of 319 unknowns takes 0.01 s instead of 0.17 s and a block of one unknown half the
    time. Other entries (floats, numeric radicals) go to ``linsolve``, which puts them in
    an algebraic field.

    >>> x, y, z = sympy.symbols("x y z")
    >>> linear_solution(sympy.Matrix([[1, 1, 0], [0, 1, 1]]), sympy.Matrix([3, 1]), (x, y, z))
    (z + 2, 1 - z, z)
    >>> linear_solution(sympy.Matrix([[1, 1], [2, 2]]), sympy.Matrix([1, 3]), (x, y)) is None
    True
    """
    if matrix.shape == (1, 1) and _number_times_polynomial(matrix[0, 0], rhs[0, 0]):
        return (sympy.expand(rhs[0, 0] / matrix[0, 0]),)
    augmented = DomainMatrix.from_Matrix(matrix.row_join(rhs))
    if not _rational(augmented.domain):
        solutions = sympy.linsolve((matrix, rhs), list(unknowns))
        if not isinstance(solutions, sympy.FiniteSet) or not solutions:
            return None
        return tuple(solutions.args[0])
    reduced, pivots = augmented.to_sparse().to_field().rref()
    n, field, pivot_columns = len(unknowns), reduced.domain, set(pivots)
    if n in pivot_columns:  # a pivot in the right-hand side: 0 = 1
        return None
    rows: dict[int, list[sympy.Expr]] = {i: [] for i in range(len(pivots))}
    for (i, j), entry in reduced.to_dok().items():
        if j not in pivot_columns:  # the pivot itself is 1, its unknown is the row's
            term = field.to_sympy(entry)
            rows[i].append(term if j == n else -term * unknowns[j])
    solution: list[sympy.Expr] = list(unknowns)
    for i, j in enumerate(pivots):
        solution[j] = sympy.Add(*rows[i])
    return tuple(solution)


def _number_times_polynomial(coefficient: sympy.Expr, rhs: sympy.Expr) -> bool:
    """One equation ``coefficient * x = rhs`` whose reduced form is ``expand(rhs /
    coefficient)``: a nonzero rational coefficient and a polynomial right-hand side in
    letters with rational coefficients. Its sum of monomials is the one the field of
    polynomials over QQ prints, without building that field (two thirds of the time of a
    block of one unknown).

    >>> x, y = sympy.symbols("x y")
    >>> _number_times_polynomial(sympy.Integer(2), x * (y + 1)), linear_solution(
    ...     sympy.Matrix([[2]]), sympy.Matrix([x * (y + 1)]), (sympy.Symbol("z"),))
    (True, (x*y/2 + x/2,))
    >>> _number_times_polynomial(x, y), _number_times_polynomial(sympy.Integer(1), 1 / x)
    (False, False)
    """
    if not coefficient.is_Rational or coefficient == 0:
        return False
    stack = [rhs]
    while stack:
        node = stack.pop()
        if node.is_Add or node.is_Mul:
            stack.extend(node.args)
        elif node.is_Pow:
            if not (node.exp.is_Integer and node.exp >= 0):
                return False
            stack.append(node.base)
        elif not (node.is_Symbol or node.is_Rational):
            return False
    return True


def _rational(domain: sympy.polys.domains.Domain) -> bool:
    """QQ, ZZ, or polynomials or fractions of them over these (exact zero tests)."""
    if domain.is_PolynomialRing or domain.is_FractionField:
        domain = domain.domain
    return bool(domain.is_ZZ or domain.is_QQ)


FLOAT_LINEAR_UNKNOWNS = 40  # bigger numeric blocks are solved exactly (mpmath LU is O(n³))
FLOAT_LINEAR_NOTE = "numeric mode: the numbers put in, solved in floating point"


def solve_linear_in_floats(
    matrix: sympy.Matrix, rhs: sympy.Matrix, unknowns: tuple[sympy.Symbol, ...]
) -> BlockSolution | None:
    """Numeric mode's linear solve: ``matrix * unknowns = rhs`` with numbers only, in
    floating point with :data:`GUARD_DIGITS` beyond the ones kept; None (solve it exactly)
    when an entry is a letter or not real, the block is large, or the matrix is singular
    or so ill-conditioned that the guard digits would not cover what it loses.

    The matrix is equilibrated (rows, then columns, scaled to a largest entry of 1; then,
    while the condition is too large, sweeps by geometric means: :func:`_equilibrated`),
    so unknowns of sizes 1e9 and 1 side by side are not "ill-conditioned". An unknown whose
    value is below the working precision next to the terms it is the sum of is exactly 0
    (a sum that cancels exactly, as exact arithmetic would find).

    >>> x, y = sympy.symbols("x y")
    >>> found = solve_linear_in_floats(
    ...     sympy.Matrix([[1, 1], [1, -1]]), sympy.Matrix([sympy.sqrt(2), sympy.sqrt(2)]), (x, y)
    ... )
    >>> found.candidates[0].values
    {x: 1.41421356237310, y: 0}
    >>> solve_linear_in_floats(sympy.Matrix([[1, 2], [2, 4]]), sympy.Matrix([1, 2]), (x, y))
    """
    n = len(unknowns)
    if n > FLOAT_LINEAR_UNKNOWNS or matrix.shape != (n, n) or matrix.free_symbols:
        return None
    if rhs.free_symbols:
        return None
    digits = numeric_digits() + GUARD_DIGITS
    with mpmath.workdps(digits):
        try:
            A = [[_mp_real(matrix[i, j], digits) for j in range(n)] for i in range(n)]
            b = [_mp_real(rhs[i], digits) for i in range(n)]
        except (TypeError, ValueError):
            return None  # a complex or non-finite entry: the exact path says what it is
        if n == 1:  # a x = b: x = b/a, the one division the scaled solve below makes
            if A[0][0] == 0:
                return None
            quotient = b[0] / A[0][0]
            value = sympy.Integer(0) if quotient == 0 else sympy.Float(quotient, numeric_digits())
            return BlockSolution(
                unknowns, "linear", (Candidate({unknowns[0]: value}),), note=FLOAT_LINEAR_NOTE
            )
        columns = [mpmath.mpf(1)] * n
        for sweep in range(EQUILIBRATION_SWEEPS):
            A, b, columns = _equilibrated(A, b, columns, geometric=sweep > 0)
            scaled = mpmath.matrix(A)
            try:
                inverse = mpmath.inverse(scaled)
            except ZeroDivisionError:
                return None
            condition = mpmath.mnorm(scaled, 1) * mpmath.mnorm(inverse, 1)
            if condition <= mpmath.mpf(10) ** (GUARD_DIGITS - 5):
                break
        else:
            return None  # (nearly) singular: dependent or contradictory equations, exactly
        tiny = mpmath.mpf(10) ** (3 - digits)
        values: dict[sympy.Symbol, sympy.Expr] = {}
        for j, unknown in enumerate(unknowns):
            terms = [inverse[j, i] * b[i] for i in range(n)]
            total = mpmath.fsum(terms)
            if abs(total) <= tiny * mpmath.fsum(abs(t) for t in terms):
                values[unknown] = sympy.Integer(0)
            else:
                values[unknown] = sympy.Float(total / columns[j], numeric_digits())
    candidate = Candidate(values)
    return BlockSolution(unknowns, "linear", (candidate,), note=FLOAT_LINEAR_NOTE)


EQUILIBRATION_SWEEPS = 12  # a matrix scaled by 1e9 (a change of units) needs 5 to 10


def _equilibrated(
    A: list[list[mpmath.mpf]], b: list[mpmath.mpf], columns: list[mpmath.mpf], geometric: bool
) -> tuple[list[list[mpmath.mpf]], list[mpmath.mpf], list[mpmath.mpf]]:
    """One sweep of equilibration of ``A x = b``: each row, then each column divided by its
    largest entry, or with ``geometric`` by the geometric mean of its nonzero entries (the
    sweeps of Curtis and Reid's scaling, which undo a change of units where scaling by the
    largest entries stops at a matrix still 1e17-conditioned); ``columns`` gathers the
    column factors (x_j = y_j / columns[j]). A diagonal scaling: it changes the condition,
    not the solution, and keeps each entry's relative rounding error.

    >>> A, b, c = _equilibrated([[4, 0], [0, 1e-8]], [8, 1e-8], [1, 1], geometric=False)
    >>> A, b, c
    ([[1.0, 0.0], [0.0, 1.0]], [2.0, 1.0], [1.0, 1.0])
    """
    n = len(A)
    rows = [_scale([a for a in row if a], geometric) for row in A]
    A = [[a / rows[i] for a in A[i]] for i in range(n)]
    b = [b[i] / rows[i] for i in range(n)]
    scale = [_scale([A[i][j] for i in range(n) if A[i][j]], geometric) for j in range(n)]
    A = [[A[i][j] / scale[j] for j in range(n)] for i in range(n)]
    return A, b, [columns[j] * scale[j] for j in range(n)]


def _scale(entries: list[mpmath.mpf], geometric: bool) -> mpmath.mpf:
    """The largest of |entries|, or their geometric mean; 1 for none."""
    if not entries:
        return mpmath.mpf(1)
    if not geometric:
        return max(abs(a) for a in entries)
    return mpmath.exp(mpmath.fsum(mpmath.log(abs(a)) for a in entries) / len(entries))


def _mp_real(entry: sympy.Expr, digits: int) -> mpmath.mpf:
    """A real sympy number as an mpmath number at ``digits`` (ValueError if not real/finite)."""
    if entry.is_Integer:
        return mpmath.mpf(int(entry))
    if entry.is_Rational:
        return mpmath.mpf(int(entry.p)) / int(entry.q)
    if entry.is_Float and mpmath.isfinite(mpmath.mpf(entry._mpf_)):
        return mpmath.mpf(entry._mpf_)
    number = sympy.N(entry, digits, maxn=MAX_DIGITS)
    if not number.is_Float:
        if number.is_zero:
            return mpmath.mpf(0)
        raise ValueError(f"not a real number: {entry}")
    value = mpmath.mpf(number._mpf_)
    if not mpmath.isfinite(value):
        raise ValueError(f"not a finite number: {entry}")
    return value


def _in_mode(
    values: Mapping[sympy.Symbol, sympy.Expr], options: SolveOptions
) -> dict[sympy.Symbol, sympy.Expr]:
    """Exact values as they are; in numeric mode, floating point numbers, while a value that
    still holds a letter (a symbolic given) stays the exact formula: floats in a formula
    only make it harder to read and to compare with a key (never exactly 0).

    >>> g, v, w = sympy.symbols("g v w")
    >>> _in_mode({v: sympy.sqrt(2), w: sympy.sqrt(2) * g}, SolveOptions(mode="numeric"))
    {v: 1.41421356237310, w: sqrt(2)*g}
    """
    if options.mode == "numeric":
        return {
            u: v if v.free_symbols else v.evalf(numeric_digits(), maxn=MAX_DIGITS)
            for u, v in values.items()
        }
    return dict(values)


def shown_formulas(
    formulas: Mapping[sympy.Symbol, sympy.Expr],
) -> dict[sympy.Symbol, sympy.Expr]:
    """The formulas worth showing: empty when any of them is too long to read.

    >>> import sympy
    >>> a, b = sympy.symbols("a b")
    >>> shown_formulas({a: 2 * b})
    {a: 2*b}
    """
    if any(sympy.count_ops(f) > FORMULA_MAX_OPS for f in formulas.values()):
        return {}
    return dict(formulas)


# --- nonlinear blocks: symbolic ----------------------------------------------------


def _solve_nonlinear(
    residuals: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    given: Mapping[sympy.Symbol, sympy.Expr],
    options: SolveOptions,
) -> BlockSolution:
    """Symbolic solve within the time budget, else numeric root finding."""
    substituted = [substitute(r, given) for r in residuals]
    letters = set().union(*(r.free_symbols for r in substituted)) - set(unknowns)
    names = ", ".join(sorted(map(str, letters)))
    if options.mode == "numeric" and not letters:
        every_root = _eliminated_roots(substituted, unknowns)
        if every_root is None:
            every_root = _polynomial_roots(substituted, unknowns, options)
        if every_root is None and given:
            every_root = _briefly_symbolic(residuals, unknowns, given, options)
        return every_root or solve_numerically(substituted, unknowns, "numeric mode")
    solution, reason = _solve_symbolically(residuals, substituted, unknowns, given, options)
    if solution is not None and options.mode == "numeric":
        note = f"numeric mode needs values for {names}; solved symbolically"
        return replace(solution, note=f"{note}. {solution.note}" if solution.note else note)
    if solution is not None:
        return solution
    if letters:
        note = f"{reason}; numeric root finding needs values for {names}"
        return BlockSolution(unknowns, "symbolic", (), note=note, exhaustive=False)
    return solve_numerically(substituted, unknowns, reason)


ELIMINATION_NOTE = (
    "numeric mode: a polynomial block, every root (by elimination), in floating point"
)
BRANCH_POINT = 1e-20  # a cosine or sine this close to ±1 (relative): its angle is left to sympy


def _eliminated_roots(
    residuals: list[sympy.Expr], unknowns: tuple[sympy.Symbol, ...]
) -> BlockSolution | None:
    """Numeric mode's path for a polynomial block of several unknowns, or one whose angle
    enters through one cosine, sine or tangent (:func:`_one_trig_atom`: the block is then
    polynomial in that function's value): every root, by exact elimination down to one
    polynomial whose roots are found in floating point
    (:func:`~dynsolve.solver.elimination.every_root`); an angle's branches as exact mode's
    solve gives them (:func:`_back`). The roots its unknowns' assumptions allow (a positive
    speed), as sympy's solve keeps them; all of them when none is allowed, for the root
    choice to say why. None when the block is not of this kind, or an angle is at the
    branch point of its inverse (cos θ = 1: ±acos would split a double root in two).

    >>> v, c = sympy.symbols("v c", positive=True)
    >>> found = _eliminated_roots([v - 2 * c, c**2 - 1], (v, c))
    >>> [(float(x.values[v]), float(x.values[c])) for x in found.candidates]
    [(2.0, 1.0)]
    """
    from dynsolve.solver.elimination import every_root

    reduced = _one_trig_atom(residuals, unknowns)
    if reduced is None and len(unknowns) < 2:
        return None
    targets = tuple(reduced.unknowns) if reduced is not None else unknowns
    if len(targets) > POLYNOMIAL_UNKNOWNS:
        return None
    found = every_root(reduced.residuals if reduced is not None else residuals, targets)
    if found is None:
        return None
    with mpmath.workdps(numeric_digits() + GUARD_DIGITS):
        roots = [r for root in found for r in _angle_branches(root, reduced)]
    if any(r is None for r in roots):
        return None
    candidates = [Candidate({u: _to_sympy(root[u]) for u in unknowns}) for root in roots]
    allowed = [c for c in candidates if all(_allowed(u, v) for u, v in c.values.items())]
    return BlockSolution(unknowns, "numeric", tuple(allowed or candidates), note=ELIMINATION_NOTE)


def _angle_branches(
    root: Mapping[sympy.Symbol, mpmath.mpc | mpmath.mpf], reduced: _TrigReduced | None
) -> list[dict[sympy.Symbol, mpmath.mpc | mpmath.mpf] | None]:
    """The roots in the block's own unknowns: a reduced block's function value gives its
    angle's branches as :func:`_back` (cos: ±acos, sin: asin and π − asin, tan: atan, less
    the constant added to the angle); [None] at a branch point (cos θ = ±1)."""
    if reduced is None:
        return [dict(root)]
    value = root[reduced.atom]
    rest = {u: x for u, x in root.items() if u != reduced.atom}
    shift = mp_value(reduced.call.args[0] - reduced.angle, {})
    if reduced.call.func is not sympy.tan and min(abs(value - 1), abs(value + 1)) <= BRANCH_POINT:
        return [None]
    inverse = {
        sympy.cos: lambda a: (mpmath.acos(a), -mpmath.acos(a)),
        sympy.sin: lambda a: (mpmath.asin(a), mpmath.pi - mpmath.asin(a)),
        sympy.tan: lambda a: (mpmath.atan(a),),
    }[reduced.call.func]
    return [{**rest, reduced.angle: branch - shift} for branch in inverse(value)]


def _allowed(unknown: sympy.Symbol, value: sympy.Expr) -> bool:
    """Whether a number is one ``unknown``'s assumptions allow: real (within 1e-20 of its
    size), positive, nonnegative, as declared (sympy's solve keeps no other root)."""
    try:
        number = complex(value if value.is_Float else sympy.N(value, 30, maxn=MAX_DIGITS))
    except (TypeError, ValueError, ArithmeticError):
        return False
    if not (math.isfinite(number.real) and math.isfinite(number.imag)):
        return False
    real = abs(number.imag) <= 1e-20 * abs(number.real)
    if unknown.is_real and not real:
        return False
    if unknown.is_positive and not number.real > 0:
        return False
    return not (unknown.is_nonnegative and number.real < 0)


BRIEF_BUDGET = 0.25  # seconds numeric mode gives sympy on a block before its root search


def _briefly_symbolic(
    residuals: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    given: Mapping[sympy.Symbol, sympy.Expr],
    options: SolveOptions,
) -> BlockSolution | None:
    """Numeric mode's short symbolic attempt at a transcendental block, with the knowns as
    letters as exact mode solves it (the numbers of a problem scaled by 1e-9 slow sympy
    down; the letters do not), its roots in floating point; None when sympy does not
    finish within :data:`BRIEF_BUDGET` (then the root search runs)."""
    seconds = min(BRIEF_BUDGET, options.time_budget)
    attempt, _ = _symbolic_candidates(residuals, unknowns, seconds, given, check=False)
    if attempt is None or not attempt.candidates or attempt.free:
        return None
    candidates = tuple(Candidate(_in_mode(c.values, options)) for c in attempt.candidates)
    note = "numeric mode: solved by sympy with the knowns as letters, in floating point"
    return BlockSolution(unknowns, "numeric", candidates, note=note)


POLYNOMIAL_DEGREE = 4  # numeric mode solves polynomial blocks up to this degree exactly
POLYNOMIAL_UNKNOWNS = 4


def _polynomial_roots(
    residuals: list[sympy.Expr], unknowns: tuple[sympy.Symbol, ...], options: SolveOptions
) -> BlockSolution | None:
    """Numeric mode's path for a small polynomial block (numbers only): every root, from
    sympy's algebraic solve, in floating point. Faster than a root search from many
    starting points, and sure to miss none; None when the block is not such a polynomial
    or sympy does not finish within the block's budget.

    >>> import sympy
    >>> w = sympy.Symbol("w")
    >>> found = _polynomial_roots([sympy.Float(2) * w**2 - 8], (w,), SolveOptions(mode="numeric"))
    >>> sorted(float(c.values[w]) for c in found.candidates), found.exhaustive
    ([-2.0, 2.0], True)
    """
    if len(unknowns) > POLYNOMIAL_UNKNOWNS:
        return None
    for residual in residuals:
        numerator = sympy.fraction(sympy.together(residual))[0]
        if not numerator.is_polynomial(*unknowns):
            return None
        if sympy.Poly(numerator, *unknowns).total_degree() > POLYNOMIAL_DEGREE:
            return None
    if len(unknowns) == 1:
        roots = _univariate_roots(residuals[0], unknowns[0])
        if roots is not None:
            note = "numeric mode: a polynomial, every root (mpmath.polyroots), in floating point"
            candidates = tuple(Candidate({unknowns[0]: _to_sympy(r)}) for r in roots)
            return BlockSolution(unknowns, "numeric", candidates, note=note)
    from dynsolve.solver.elimination import exact_numbers

    exact = [exact_numbers(r) for r in residuals]
    attempt, _ = _symbolic_candidates(exact, unknowns, options.time_budget, None, check=False)
    if attempt is None or not attempt.candidates:
        # sympy keeps only the roots its assumptions allow (t_s positive): without them,
        # every root, as a numeric search would find them, for the root choice to judge
        plain = {u: sympy.Dummy(u.name) for u in unknowns}
        back = {d: u for u, d in plain.items()}
        residuals_plain = [r.xreplace(plain) for r in exact]
        attempt, _ = _symbolic_candidates(
            residuals_plain, tuple(plain.values()), options.time_budget, None, check=False
        )
        if attempt is not None:
            attempt = replace(
                attempt,
                candidates=tuple(
                    Candidate({back[d]: v for d, v in c.values.items()}) for c in attempt.candidates
                ),
            )
    if attempt is None or not attempt.candidates or attempt.free:
        return None
    candidates = tuple(Candidate(_in_mode(c.values, options)) for c in attempt.candidates)
    note = "numeric mode: a polynomial block, every root (sympy), in floating point"
    return BlockSolution(unknowns, "numeric", candidates, note=note)


def _univariate_roots(residual: sympy.Expr, unknown: sympy.Symbol) -> list[mpmath.mpf] | None:
    """Every root of a polynomial in one unknown with number coefficients, by
    ``mpmath.polyroots`` with :data:`GUARD_DIGITS` beyond the ones kept; None (let sympy
    solve it exactly) when a coefficient is not a real number, the search does not
    converge, a root is repeated (where the digits a float search keeps are halved) or
    the unknown is in a denominator.

    >>> w = sympy.Symbol("w")
    >>> [mpmath.nstr(r, 6) for r in _univariate_roots(2 * w**2 - 8, w)]
    ['-2.0', '2.0']
    >>> _univariate_roots((w - 1) ** 2, w) is None
    True
    """
    numerator, denominator = sympy.fraction(sympy.together(residual))
    if unknown in denominator.free_symbols:
        return None
    digits = numeric_digits() + GUARD_DIGITS
    try:
        coefficients = sympy.Poly(numerator, unknown).all_coeffs()
        if len(coefficients) < 2:
            return None
        with mpmath.workdps(digits):
            numbers = [_mp_real(c, digits) for c in coefficients]
            if numbers[0] == 0:
                return None
            roots = [
                _polished(numbers, r)
                for r in mpmath.polyroots(numbers, maxsteps=100, extraprec=2 * digits)
            ]
            for i, a in enumerate(roots):
                for b in roots[i + 1 :]:
                    if abs(a - b) <= mpmath.mpf(10) ** -8 * max(abs(a), abs(b)):
                        return None
            return list(roots)
    except (sympy.PolynomialError, ValueError, TypeError, ArithmeticError, NoConvergence):
        return None


def _polished(coefficients: list[mpmath.mpf], root: mpmath.mpc) -> mpmath.mpc:
    """``root`` refined by Newton steps on the polynomial: the search's error is absolute
    (a root of 1e-200 beside one of 1 comes out 1e-36), a Newton step's is relative.

    >>> c = [mpmath.mpf(1), mpmath.mpf(1), -mpmath.mpf(10) ** -200]  # x² + x − 1e-200
    >>> mpmath.nstr(_polished(c, mpmath.mpf(3e-36)), 8)
    '1.0e-200'
    """
    for _ in range(8):
        value, slope = mpmath.polyval(coefficients, root, derivative=True)
        if slope == 0:
            break
        step = value / slope
        root -= step
        if abs(step) <= mpmath.eps * abs(root):
            break
    return root


def _solve_symbolically(
    residuals: list[sympy.Expr],
    substituted: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    given: Mapping[sympy.Symbol, sympy.Expr],
    options: SolveOptions,
) -> tuple[BlockSolution | None, str]:
    """``sympy.solve`` within the budget: the solution, or None and why not.

    With formulas shown, the first half of the budget goes to solving with the knowns
    as letters; if that fails, the rest to solving with the numbers substituted (a
    block without knowns gets one attempt with the whole budget).
    """
    deadline = time.process_time() + options.time_budget  # CPU seconds, as the budget
    reasons: list[str] = []
    nothing_given = substituted == residuals  # then one symbolic attempt says it all
    # numeric mode checks a root with letters at sample points (sympy's checksol, a
    # simplify of every residual, is most of the solve's time)
    check = options.mode != "numeric" or not _samples_decide(residuals, unknowns, given)
    if options.show_formulas:
        share = options.time_budget if nothing_given else options.time_budget / 2
        attempt, reason = _symbolic_candidates(residuals, unknowns, share, given, check)
        if attempt is not None:
            return attempt, ""
        reasons.append(reason)
    if not (reasons and nothing_given):
        seconds = deadline - time.process_time()
        attempt, reason = _symbolic_candidates(substituted, unknowns, seconds, None, check)
        if attempt is not None:
            return replace(attempt, note=f"no formula: {reasons[0]}" if reasons else ""), ""
        reasons.append(reason)
    if _TIMEOUT in reasons:
        return None, f"symbolic solve exceeded {options.time_budget:g} s budget"
    return None, reasons[-1]


def _symbolic_candidates(
    residuals: list[sympy.Expr],
    unknowns: tuple[sympy.Symbol, ...],
    seconds: float,
    given: Mapping[sympy.Symbol, sympy.Expr] | None,
    check: bool = True,
) -> tuple[BlockSolution | None, str]:
    """``sympy.solve`` within ``seconds``; with ``given``, roots are formulas to substitute into.
    Without ``check`` (numeric mode, whose roots are numbers), sympy's own check of each
    root (``checksol``, a ``simplify`` of every residual: most of the solve's time) is
    replaced by :func:`_holds`, in numbers.

    Returns the solution, or None and the reason it could not be used.
    """
    if len(unknowns) == 1:  # a lone equation solves about twice as fast as a one-item list
        # its common factors out first: sin θ (Ω² cos θ − 3g/2L) is solved factor by factor
        # (θ = acos(3g/(2LΩ²)), not sympy's 2 atan(…) of the whole, in a third of the time)
        problem: object = sympy.factor_terms(residuals[0])
        targets: object = unknowns[0]
    else:
        problem, targets = residuals, list(unknowns)
    reduced = _one_trig_atom(residuals, unknowns)
    if reduced is not None:  # cos(θ + φ0) as one unknown c: an algebraic block, then θ
        problem, targets = reduced.residuals, list(reduced.unknowns)
    try:
        # sympy's own simplify of every root costs more than the solve; tidy() does it cheaply
        roots, timed_out = _within_budget(
            lambda: _tidy_roots(
                _back(
                    reduced, sympy.solve(problem, targets, dict=True, simplify=False, check=check)
                )
            ),
            seconds,
        )
    except _SYMPY_GAVE_UP:
        return None, "sympy found no closed form"
    if timed_out or roots is None:
        return None, _TIMEOUT
    complete = [r for r in roots if _determines(r, unknowns)]
    if roots and not complete:
        missing = sum(all(u not in r for r in roots) for u in unknowns)
        note = "the equations of this block are dependent"
        return BlockSolution(
            unknowns, "symbolic", (), note=note, free=unknowns, missing_equations=max(missing, 1)
        ), ""
    complete = _principal_angles(complete, residuals, unknowns, given)
    candidates = [_candidate(r, unknowns, given) for r in complete]
    candidates = [c for c in candidates if c is not None]
    if not check:
        candidates = [c for c in candidates if _holds(residuals, unknowns, c.values, given or {})]
    if not candidates:
        return None, "sympy found no solution" if not roots else "formulas undefined here"
    return BlockSolution(unknowns, "symbolic", tuple(candidates)), ""


UNCHECKED_RESIDUAL = 1e-15  # relative residual (30 digits) up to which an unchecked root holds


def _holds(
    residuals: Sequence[sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    values: Mapping[sympy.Symbol, sympy.Expr],
    given: Mapping[sympy.Symbol, sympy.Expr],
) -> bool:
    """sympy's check of an unchecked root, in numbers: every value a number its unknown's
    assumptions allow (real, positive, nonnegative: ``oo*I`` or −2 for a positive time is
    not a root), and every residual at the root, evaluated to 30 digits, within
    :data:`UNCHECKED_RESIDUAL` of 0 relative to the size of its terms (a root of a squared
    equation, or one that zeroes a denominator, is off by far more). False when any of
    it cannot be decided. A root that holds letters (symbolic givens, all positive:
    :func:`_samples_decide`) is judged by :func:`_holds_at_samples`."""
    from dynsolve.solver.residuals import term_size

    at_root = {u: substitute(values[u], given) for u in unknowns}
    if any(value.free_symbols for value in at_root.values()):
        return _holds_at_samples(residuals, at_root, given)
    if not all(_allowed(u, value) for u, value in at_root.items()):
        return False
    point = {**given, **at_root}
    for residual in residuals:
        at = substitute(residual, point)
        if at.free_symbols:
            return False
        try:
            size = abs(complex(sympy.N(at, 30, maxn=MAX_DIGITS)))
            scale = term_size(as_expr(residual), point)
        except (TypeError, ValueError, ArithmeticError):
            return False
        if not math.isfinite(size) or size > UNCHECKED_RESIDUAL * scale:
            return False
    return True


CHECK_POINTS = 3  # seeded points of the letters a symbolic root is checked at
CHECK_SEED = 4104


def _samples_decide(
    residuals: Sequence[sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    given: Mapping[sympy.Symbol, sympy.Expr],
) -> bool:
    """Whether the roots of a block with letters can be checked at sample points: every
    letter left once ``given`` is put in is declared positive (a given magnitude), so
    its sample values are values it may take."""
    letters = set().union(*(substitute(r, given).free_symbols for r in residuals))
    return all(s.is_positive for s in letters - set(unknowns))


def _holds_at_samples(
    residuals: Sequence[sympy.Expr],
    at_root: Mapping[sympy.Symbol, sympy.Expr],
    given: Mapping[sympy.Symbol, sympy.Expr],
) -> bool:
    """sympy's check of a root in formulas (``check_assumptions`` and ``checksol``), with
    the residuals at :data:`CHECK_POINTS` seeded positive values of the letters instead of
    ``simplify``: a root sympy's checks would keep is kept. Its values must not contradict
    their unknowns' assumptions (sympy's own test, on the formulas); a residual that is
    not 0 (more than 1e-20 of the size of its terms, 40 digits) or not defined at every
    point (a spurious root of a squared equation, one that zeroes a denominator) is what
    ``checksol`` proves nonzero, so the root goes; one that is 0 at a point may be 0
    everywhere, so the root stays, as sympy keeps a root it cannot disprove.

    >>> a, x = sympy.Symbol("a", positive=True), sympy.Symbol("x", positive=True)
    >>> r = [x**2 - a]
    >>> _holds_at_samples(r, {x: sympy.sqrt(a)}, {}), _holds_at_samples(r, {x: -sympy.sqrt(a)}, {})
    (True, False)
    >>> _holds_at_samples([x - a], {x: 2 * a}, {})  # not a root
    False
    """
    from sympy.core.assumptions import check_assumptions

    for unknown, value in at_root.items():
        if check_assumptions(value, **unknown.assumptions0) is False:
            return False
    forms = [substitute(r, given) for r in residuals]
    letters = set().union(
        *(f.free_symbols for f in forms), *(v.free_symbols for v in at_root.values())
    )
    letters = sorted(letters - set(at_root), key=lambda s: s.name)
    rng = random.Random(CHECK_SEED)
    nonzero = [0] * len(forms)
    for _ in range(CHECK_POINTS):
        point = {s: sympy.Rational(rng.randint(10, 1000), 100) for s in letters}
        for i, form in enumerate(forms):
            if not _zero_at(form, at_root, point):
                nonzero[i] += 1
    return all(count < CHECK_POINTS for count in nonzero)


def _zero_at(
    form: sympy.Expr,
    at_root: Mapping[sympy.Symbol, sympy.Expr],
    point: Mapping[sympy.Symbol, sympy.Rational],
) -> bool:
    """Whether ``form`` with the root put in is 0 at ``point`` (within 1e-20 of the size of
    its terms, at 40 digits); False where it is not defined."""
    from dynsolve.solver.evaluate import NotQuick, mp_size

    with mpmath.workdps(40):
        letters = {s: mpmath.mpf(int(v.p)) / int(v.q) for s, v in point.items()}
        try:
            shared: dict[sympy.Basic, object] = {}
            values = {u: mp_value(v, letters, shared) for u, v in at_root.items()}
            seen: dict[sympy.Basic, object] = {}
            value = mp_value(form, {**letters, **values}, seen)
            size = mp_size(form, {**letters, **values}, seen)
        except (NotQuick, ArithmeticError, ValueError, TypeError):
            exact = form.xreplace(dict(at_root)).xreplace(dict(point))
            try:
                value = mpmath.mpmathify(complex(sympy.N(exact, 40, maxn=MAX_DIGITS)))
            except (TypeError, ValueError, ArithmeticError):
                return False
            size = abs(value)  # no term sizes: 0 only when evalf finds it 0
        if not (mpmath.isfinite(value) and mpmath.isfinite(size)):
            return False
        return abs(value) <= mpmath.mpf(10) ** -20 * size


@dataclass(frozen=True)
class _TrigReduced:
    """A block whose unknown ``angle`` enters only through one atom cos/sin/tan(angle + c),
    with that atom replaced by the unknown ``atom``."""

    residuals: list[sympy.Expr]
    unknowns: tuple[sympy.Symbol, ...]
    angle: sympy.Symbol
    atom: sympy.Symbol
    call: sympy.Expr  # the replaced cos(angle + c)


def _one_trig_atom(
    residuals: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol]
) -> _TrigReduced | None:
    """The block with an angle that enters only as one cos, sin or tan of itself plus a
    constant (a particle leaving a circle from off its top: cos(θ + φ0)) rewritten with
    that function's value as the unknown: sympy solves the algebraic block at once where
    it spends seconds on the trigonometric one. None when there is no such angle.

    >>> t, v, p = sympy.symbols("theta v phi", real=True)
    >>> r = _one_trig_atom([v**2 - 2 * (1 - sympy.cos(t + p)), v**2 - sympy.cos(t + p)], [v, t])
    >>> r.angle, r.call
    (theta, cos(phi + theta))
    """
    exprs = [sympy.Integer(0) + r for r in residuals]
    for angle in unknowns:
        calls = {
            c
            for e in exprs
            for c in e.atoms(sympy.cos, sympy.sin, sympy.tan)
            if angle in c.free_symbols
        }
        if len(calls) != 1:
            continue
        (call,) = calls
        rest = call.args[0] - angle
        if angle in rest.free_symbols or set(unknowns) & rest.free_symbols:
            continue
        atom = sympy.Dummy(f"{call.func.__name__}_{angle.name}", real=True)
        replaced = [e.xreplace({call: atom}) for e in exprs]
        if any(angle in e.free_symbols for e in replaced):
            continue
        others = tuple(u for u in unknowns if u != angle)
        return _TrigReduced(replaced, (*others, atom), angle, atom, call)
    return None


def _back(
    reduced: _TrigReduced | None, roots: list[dict[sympy.Symbol, sympy.Expr]]
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """The roots of a reduced block in its own unknowns: each value of the function gives
    the angle's roots within one turn (cos: ±acos; sin: asin and π − asin; tan: atan)."""
    if reduced is None:
        return roots
    shift = reduced.call.args[0] - reduced.angle
    out = []
    for root in roots:
        if reduced.atom not in root:
            continue
        value = root[reduced.atom]
        inverse = {
            sympy.cos: (sympy.acos(value), -sympy.acos(value)),
            sympy.sin: (sympy.asin(value), sympy.pi - sympy.asin(value)),
            sympy.tan: (sympy.atan(value),),
        }[reduced.call.func]
        rest = {u: x for u, x in root.items() if u != reduced.atom}
        for branch in dict.fromkeys(inverse):
            out.append({**rest, reduced.angle: branch - shift})
    return out


def _tidy_roots(roots: list[dict[sympy.Symbol, sympy.Expr]]) -> list[dict]:
    """Each root's value in its tidiest cheap form (:func:`~dynsolve.numbers.tidy`)."""
    return [
        {u: tidy(v) if sympy.count_ops(v) <= FORMULA_MAX_OPS else v for u, v in r.items()}
        for r in roots
    ]


def _determines(root: Mapping[sympy.Symbol, sympy.Expr], unknowns: Sequence[sympy.Symbol]) -> bool:
    """True when ``root`` gives every unknown a value free of the block's unknowns."""
    return all(u in root and not set(unknowns) & root[u].free_symbols for u in unknowns)


def _candidate(
    root: Mapping[sympy.Symbol, sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    given: Mapping[sympy.Symbol, sympy.Expr] | None,
) -> Candidate | None:
    """A candidate from a sympy root: substitute ``given`` into formulas, if any."""
    if given is None:
        return Candidate({u: root[u] for u in unknowns})
    values = {u: substitute(root[u], given) for u in unknowns}
    if not all(is_finite(v) for v in values.values()):
        return None
    return Candidate(values, shown_formulas({u: root[u] for u in unknowns}))


# --- nonlinear blocks: numeric -----------------------------------------------------


def solve_numerically(
    residuals: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol], reason: str
) -> BlockSolution:
    """Root finding from several starting points; the residuals must hold only ``unknowns``.

    ``reason`` says why the numeric path was taken; it starts the block's note.

    >>> import sympy
    >>> x = sympy.Symbol("x")
    >>> solution = solve_numerically([x - sympy.cos(x)], [x], "transcendental")
    >>> [round(float(c.values[x]), 6) for c in solution.candidates], solution.note
    ([0.739085], 'transcendental; solved numerically')
    """
    roots = numeric_roots(residuals, unknowns)
    candidates = tuple(Candidate(dict(zip(unknowns, r, strict=True))) for r in roots)
    if candidates:
        note = f"{reason}; solved numerically"
    elif _infinite(residuals):
        note = f"{reason}; an equation holds an infinite value (a division by zero?): no root"
    else:
        starts = len(_starting_points(residuals, unknowns))
        note = f"{reason}; numeric search from {starts} starting points found no root"
    return BlockSolution(tuple(unknowns), "numeric", candidates, note=note, exhaustive=False)


def _infinite(residuals: Sequence[sympy.Expr]) -> bool:
    """Whether a residual holds ∞, complex ∞ or nan (``x/0`` written in a spec).

    >>> x = sympy.Symbol("x")
    >>> _infinite([x / sympy.Integer(0)]), _infinite([x - 1])
    (True, False)
    """
    return any(as_expr(r).has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo) for r in residuals)


def numeric_roots(
    residuals: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol]
) -> list[tuple[sympy.Expr, ...]]:
    """Distinct roots found by mpmath ``findroot`` from scaled starting points.

    >>> import sympy
    >>> x = sympy.Symbol("x")
    >>> sorted(float(r[0]) for r in numeric_roots([x**2 - 4], [x]))
    [-2.0, 2.0]
    """
    unknowns = list(unknowns)
    if _infinite(residuals):  # zoo cannot be evaluated (nor printed for mpmath)
        return []
    function = mpmath_function(unknowns, list(residuals))
    size = mpmath_function(unknowns, [_term_size(r) for r in residuals])
    matrix = sympy.Matrix(residuals).jacobian(unknowns)
    jacobian = mpmath_function(unknowns, matrix)
    guard = finite_guard(unknowns, [*residuals, *matrix])
    found: list[list[mpmath.mpc | mpmath.mpf]] = []
    for start in _starting_points(residuals, unknowns):
        root = _find_root(function, jacobian, start, size, guard)
        if root is None or _seen(root, found):
            continue
        if _converged(function, size, jacobian, root):
            found.append(root)
    periodic = [_periodic(u, residuals) for u in unknowns]
    if any(periodic):  # an angle seen only in sin, cos, tan of whole multiples: (−π, π]
        reduced: list[list[mpmath.mpc | mpmath.mpf]] = []
        for root in found:
            root = [_principal(x) if p else x for x, p in zip(root, periodic, strict=True)]
            if not any(_same_angles(root, old, periodic) for old in reduced):
                reduced.append(root)
        found = reduced
    return [tuple(_to_sympy(x) for x in root) for root in found]


def _periodic(unknown: sympy.Symbol, residuals: Sequence[sympy.Expr]) -> bool:
    """Whether ``unknown`` enters ``residuals`` only as whole multiples inside sin, cos and
    tan (its roots repeat every 2π: a root search may land a period away).

    >>> t, x = sympy.symbols("t x")
    >>> _periodic(t, [sympy.sin(2 * t) - x]), _periodic(t, [sympy.sin(t / 2)]), _periodic(t, [t])
    (True, False, False)
    """
    trig = (sympy.sin, sympy.cos, sympy.tan)
    calls = [
        c
        for r in residuals
        for c in (sympy.Integer(0) + r).atoms(*trig)
        if unknown in c.free_symbols
    ]
    if not calls:
        return False
    for call in calls:
        for term in sympy.Add.make_args(call.args[0]):
            if unknown in term.free_symbols:
                coefficient, rest = term.as_coeff_Mul()
                if rest != unknown or not coefficient.is_Integer:
                    return False
    exprs = [sympy.Integer(0) + r for r in residuals]
    bare = [e.xreplace({c: sympy.Dummy() for c in e.atoms(*trig)}) for e in exprs]
    return not any(unknown in b.free_symbols for b in bare)


def _same_angles(a: Sequence[object], b: Sequence[object], periodic: Sequence[bool]) -> bool:
    """Two roots alike: an angle to 1e-9 rad round the circle (−π is π, −1e-14 is 0), any
    other unknown to about nine digits (relative)."""
    for x, y, angle in zip(a, b, periodic, strict=True):
        gap = abs(x - y)
        if angle and not isinstance(gap, mpmath.mpc):
            if min(gap, 2 * mpmath.pi - gap) > 1e-9:
                return False
        elif gap > 1e-9 * max(abs(x), abs(y)):
            return False
    return True


def _principal_angles(
    roots: list[dict[sympy.Symbol, sympy.Expr]],
    residuals: Sequence[sympy.Expr],
    unknowns: Sequence[sympy.Symbol],
    given: Mapping[sympy.Symbol, sympy.Expr] | None,
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """sympy's roots with each angle that enters only through sin, cos, tan of whole
    multiples of itself written in (−π, π], as the root search writes it (2π − acos(c) is
    −acos(c)): an ``assume theta > 0`` line then reads the angles it was written for; a
    root met twice so is kept once. An angle whose value cannot be had (letters without a
    probe value) is kept as sympy wrote it.

    >>> t = sympy.Symbol("t", real=True)
    >>> _principal_angles([{t: 2 * sympy.pi - sympy.acos(sympy.Rational(1, 3))}],
    ...                   [sympy.cos(t) - sympy.Rational(1, 3)], [t], {})
    [{t: -acos(1/3)}]
    """
    periodic = [u for u in unknowns if _periodic(u, residuals)]
    if not periodic:
        return roots
    turn, kept = 2 * sympy.pi, []
    for root in roots:
        root = dict(root)
        for u in periodic:
            value = substitute(root[u], given or {}) if u in root else None
            if value is None:
                continue
            point = probe_point(value)
            number = real_value(value, point) if point is not None else None
            if number is not None and number > math.pi:
                root[u] = tidy(root[u] - turn)
            elif number is not None and number <= -math.pi:
                root[u] = tidy(root[u] + turn)
        if root not in kept:
            kept.append(root)
    return kept


def _principal(angle: mpmath.mpc | mpmath.mpf) -> mpmath.mpc | mpmath.mpf:
    """A real angle in (−π, π]; anything else as it is."""
    if isinstance(angle, mpmath.mpc) and angle.imag != 0:
        return angle
    turn = 2 * mpmath.pi
    value = mpmath.re(angle) % turn
    return value - turn if value > mpmath.pi else value


def finite_guard(
    unknowns: Sequence[sympy.Symbol], exprs: Sequence[sympy.Expr]
) -> Callable[[Sequence[object]], bool]:
    """A cheap test, in complex float64, that ``exprs`` stay finite at a point: mpmath would
    otherwise build numbers such as exp(1e30) digit by digit, for gigabytes.

    >>> x = sympy.Symbol("x")
    >>> ok = finite_guard([x], [sympy.exp(x) - 1])
    >>> ok([1.0]), ok([1e30])
    (True, False)
    """
    import numpy

    renamed = {v: sympy.Dummy(f"u{i}") for i, v in enumerate(unknowns)}
    compiled = sympy.lambdify(
        list(renamed.values()), [e.xreplace(renamed) for e in exprs], modules="numpy"
    )

    def finite(point: Sequence[object]) -> bool:
        try:
            values = [complex(v) for v in point]  # type: ignore[arg-type]
            with numpy.errstate(all="ignore"):
                results = numpy.asarray(compiled(*values), dtype=complex)
        except (ArithmeticError, ValueError, TypeError):
            return False
        return bool(numpy.isfinite(results).all())

    return finite


def _term_size(residual: sympy.Expr) -> sympy.Expr:
    """Sum of the magnitudes of the residual's terms: the scale its zero is judged on."""
    terms = sympy.Add.make_args(sympy.expand(residual)) if residual.is_Add else (residual,)
    return sympy.Add(*(sympy.Abs(t) for t in terms))


def _starting_points(
    residuals: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol]
) -> list[list[float]]:
    """Starting vectors: each factor of START_FACTORS times 1 and times the data's scale;
    and, where some unknowns are angles (arguments of sin, cos, tan), the angles near 1
    and the others at the data's scale: a pendulum of length 1e9 m has speeds of 1e9 but
    its angle is still about 1 rad (starting it at 1e9 rad finds roots 1e12 rad away).

    In several unknowns the entries are spread a little (1, 1.13, 1.26, ...) so a
    symmetric system does not start on its singular diagonal.

    >>> x, th = sympy.symbols("x theta")
    >>> starts = _starting_points([x - 10**9 * sympy.cos(th)], [x, th])
    >>> [1e8, 1.13] in [[round(a, 2) for a in s] for s in starts]
    True
    """
    n = len(unknowns)
    scales = [1.0]
    numbers = [abs(float(a)) for r in residuals for a in r.atoms(sympy.Number) if a != 0]
    numbers = [x for x in numbers if 0 < x < math.inf]  # an underflow is no scale for log
    if numbers:
        typical = math.exp(sum(math.log(x) for x in numbers) / len(numbers))
        if not 0.3 < typical < 3:
            scales.append(typical)
    starts = [[s * f * (1 + 0.13 * i) for i in range(n)] for s in scales for f in START_FACTORS]
    trigonometric = (sympy.sin, sympy.cos, sympy.tan)
    inside = set().union(*(f.free_symbols for r in residuals for f in r.atoms(*trigonometric)))
    angles = [u in inside for u in unknowns]
    if len(scales) > 1 and any(angles) and not all(angles):
        starts += [
            [(1.0 if angles[i] else scales[1] * f) * (1 + 0.13 * i) for i in range(n)]
            for f in START_FACTORS
        ]
    return starts


def _find_root(
    function: Callable[..., list[object]],
    jacobian: Callable[..., object],
    start: list[float],
    size: Callable[..., list[object]] | None = None,
    finite: Callable[[Sequence[object]], bool] | None = None,
) -> list[mpmath.mpc | mpmath.mpf] | None:
    """Damped Newton from ``start`` with scale-free stopping rules.

    mpmath's ``findroot`` stops on an absolute residual (``MDNewton``) or an absolute step
    (``Secant``, which also starts 0.25 from ``x0``): a problem whose residuals are 1e-27
    stopped where it started. Here the search stops when a step no
    longer moves any unknown relative to itself. Steps are damped on a norm of the residuals
    weighted by the size of their terms at the start (fixed for the search, so the Newton
    step is always a descent direction).

    >>> import sympy
    >>> x = sympy.Symbol("x")
    >>> f = mpmath_function([x], [x**2 - sympy.Float("1e-400")])
    >>> J = mpmath_function([x], sympy.Matrix([[2 * x]]))
    >>> root = _find_root(f, J, [3e-200])
    >>> float(root[0] / sympy.Float("1e-200"))
    1.0
    """
    try:
        with mpmath.workdps(numeric_digits() + GUARD_DIGITS):
            x = mpmath.matrix([mpmath.mpf(v) for v in start])
            tiny = mpmath.mpf(10) ** -(numeric_digits() + 3)
            if finite is not None and not finite(list(x)):
                return None  # beyond float range at the start: no place to search from
            values = mpmath.matrix(function(*x))
            weights = _weights(size, x, len(values))
            measure = _measure(values, weights)
            for _ in range(NEWTON_STEPS):
                if measure == 0:
                    break
                step = _newton_step(_as_matrix(jacobian(*x), len(start)), values)
                if all(abs(step[i]) <= tiny * abs(x[i]) for i in range(len(x))):
                    break  # converged: the step is below the working precision
                damping = mpmath.mpf(1)
                while True:
                    trial = x - damping * step
                    if finite is not None and not finite(list(trial)):
                        damping /= 2  # the step leaves float range: shorten it
                        if damping < 1e-6:
                            return None
                        continue
                    trial_values = mpmath.matrix(function(*trial))
                    trial_measure = _measure(trial_values, weights)
                    if trial_measure < measure or damping < 1e-6:
                        break
                    damping /= 2
                moved = any(abs(trial[i] - x[i]) > tiny * abs(x[i]) for i in range(len(x)))
                if trial_measure >= measure and damping < 1e-6:
                    break  # no descent: a minimum of the residuals or a stationary point
                x, values, measure = trial, trial_values, trial_measure
                if not moved:
                    break
            return [x[i] for i in range(len(start))]
    except (ArithmeticError, ValueError, TypeError):
        return None


NEWTON_STEPS = 100


def _as_matrix(value: object, n: int) -> mpmath.matrix:
    """A Jacobian as an mpmath matrix (lambdify may give a matrix, list or a number)."""
    if isinstance(value, mpmath.matrix):
        return value
    return mpmath.matrix(value) if n > 1 else mpmath.matrix([[value]])


def _newton_step(J: mpmath.matrix, F: mpmath.matrix) -> mpmath.matrix:
    """Solve ``J step = F`` with rows, then columns, scaled to a largest entry of 1.

    mpmath's LU calls a matrix singular relative to its largest entry, so unknowns of
    very different sizes (v_G = 2e9 ft/s beside omega = 2.65 rad/s) looked singular.

    >>> J = mpmath.matrix([[1, -8e8], [1.2e9, 5e26]])
    >>> step = _newton_step(J, J * mpmath.matrix([2e9, 2.5]))
    >>> [mpmath.nstr(s, 6) for s in step]
    ['2.0e+9', '2.5']
    """
    n = J.rows
    rows = [max(abs(J[i, j]) for j in range(n)) or 1 for i in range(n)]
    scaled = mpmath.matrix(n, n)
    for i in range(n):
        for j in range(n):
            scaled[i, j] = J[i, j] / rows[i]
    columns = [max(abs(scaled[i, j]) for i in range(n)) or 1 for j in range(n)]
    for i in range(n):
        for j in range(n):
            scaled[i, j] /= columns[j]
    y = mpmath.lu_solve(scaled, mpmath.matrix([F[i] / rows[i] for i in range(n)]))
    return mpmath.matrix([y[j] / columns[j] for j in range(n)])


def _weights(size: Callable[..., list[object]] | None, x: mpmath.matrix, n: int) -> list[object]:
    """Fixed weights for one search: 1 / the size of each residual's terms at the start."""
    sizes = size(*x) if size is not None else [1] * n
    return [1 / abs(s) if s and mpmath.isfinite(abs(s)) else mpmath.mpf(1) for s in sizes]


def _measure(values: mpmath.matrix, weights: list[object]) -> mpmath.mpf:
    """The weighted 2-norm of the residuals (a fixed norm, so Newton's step is a descent)."""
    return mpmath.sqrt(mpmath.fsum((w * abs(values[i])) ** 2 for i, w in enumerate(weights)))


def _converged(
    function: Callable[..., list[object]],
    size: Callable[..., list[object]],
    jacobian: Callable[..., object],
    root: Sequence[mpmath.mpc | mpmath.mpf],
) -> bool:
    """True when ``root`` really is a root, not a point where the residuals merely fade.

    Either every residual is tiny next to the size of its terms (catches sums like
    ``x**2 - 2*x + 1``), or one more Newton step would barely move ``root`` (catches
    products like ``sin(x)``, while ``exp(x) = 0`` far out on the left fails both).
    """
    try:
        with mpmath.workdps(numeric_digits() + GUARD_DIGITS):
            values, sizes = function(*root), size(*root)
            if all(
                abs(v) == 0 or abs(v) <= 1e-10 * abs(s) for v, s in zip(values, sizes, strict=True)
            ):
                return True
            step = _newton_step(_as_matrix(jacobian(*root), len(root)), mpmath.matrix(values))
            scale = max(abs(x) for x in root)  # relative: a root of 1e-200 is not "about 0"
            return all(abs(step[i]) <= 1e-9 * (abs(x) or scale) for i, x in enumerate(root))
    except (ArithmeticError, ValueError, TypeError):
        return False


def _seen(root: Sequence[object], found: list[list[mpmath.mpc | mpmath.mpf]]) -> bool:
    """True when ``root`` equals an earlier root to about nine digits (relative, so scale-free)."""
    return any(
        all(abs(a - b) <= 1e-9 * max(abs(a), abs(b)) for a, b in zip(root, old, strict=True))
        for old in found
    )


def _to_sympy(x: mpmath.mpc | mpmath.mpf) -> sympy.Expr:
    """An mpmath number as a sympy Float (complex when its imaginary part is not negligible)."""
    real, imag, digits = mpmath.re(x), mpmath.im(x), numeric_digits()
    if abs(imag) <= 1e-12 * abs(real) or imag == 0:
        return sympy.Float(real, digits)
    return sympy.Float(real, digits) + sympy.I * sympy.Float(imag, digits)
