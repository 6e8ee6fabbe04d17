"""Small sympy helpers: real values of closed expressions, and cheap simplification.

>>> import sympy
>>> real_value(sympy.sqrt(2) * sympy.pi), real_value(sympy.Symbol("x")), real_value(sympy.I)
(4.442882938158366, None, None)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from contextvars import ContextVar

import sympy
from sympy.core.cache import cacheit

IMAGINARY_TOLERANCE = 1e-12
MAX_DIGITS = 400  # evalf may work this many digits through cancellation (sympy: 100)


def real_value(
    expr: sympy.Expr | int, substitution: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> float | None:
    """``expr`` (after ``substitution``) as a float; None if symbols remain or it is not real."""
    value = sympy.Integer(0) + expr
    if substitution:
        # a dict as it is: copying a big scene's values per call is n²
        rule = substitution if isinstance(substitution, dict) else dict(substitution)
        value = value.xreplace(rule)
    return _real_number(value)


@cacheit  # a scene asks for the same numbers again and again (forces, arms, residual terms)
def _real_number(value: sympy.Expr) -> float | None:
    """A closed ``value`` as a float, evaluated to 30 digits; None if symbols remain or
    it is not real."""
    if value.free_symbols:
        return None
    if value.has(sympy.Integral):
        value = quadratures(value)
    number = complex(sympy.N(value, 30, maxn=MAX_DIGITS))
    if abs(number.imag) > IMAGINARY_TOLERANCE * abs(number.real):
        return None
    return number.real


def quadratures(value: sympy.Expr, digits: int = 30) -> sympy.Expr:
    """``value`` with each definite integral of numbers alone replaced by its quadrature
    (mpmath's tanh-sinh to ``digits`` digits, which takes a 1/√ singularity at an end, as
    ∫ dx/v has at a turning point): sympy's own evalf of such an integral substitutes into
    the integrand at each node and takes seconds to minutes. An integral it cannot
    evaluate so (nested, or an integrand mpmath cannot compute) is left as it is.

    >>> u = sympy.Dummy("u")
    >>> round(float(quadratures(sympy.Integral(1 / sympy.sqrt(1 - u**2), (u, 0, 1)))), 12)
    1.570796326795
    """
    import mpmath

    found: dict[sympy.Expr, sympy.Expr] = {}
    for integral in value.atoms(sympy.Integral):
        limits = integral.limits
        if (
            integral.free_symbols
            or len(limits) != 1
            or len(limits[0]) != 3
            or integral.function.has(sympy.Integral)
        ):
            continue
        variable, low, high = limits[0]
        try:
            f = sympy.lambdify(variable, integral.function, "mpmath")
            with mpmath.workdps(digits):
                ends = [mpmath.mpf(str(sympy.N(end, digits))) for end in (low, high)]
                result = mpmath.quad(f, ends)
        except (TypeError, ValueError, ArithmeticError, NameError):
            continue
        real, imaginary = (mpmath.nstr(part, digits) for part in (result.real, result.imag))
        found[integral] = sympy.Float(real, digits) + sympy.I * sympy.Float(imaginary, digits)
    return value.xreplace(found) if found else value


SIMPLIFY_OPS = 40  # sympy.simplify, the last resort, only on forms at most this large
EXPAND_OPS = 60  # distributing products only on forms at most this large
CANCEL_OPS = 0  # without a symbolic denominator, cancel only forms at most this large


@cacheit  # the model asks for the same forms again and again (a third are repeats)
def float_functions(expr: sympy.Expr, digits: int = 30) -> sympy.Expr:
    """``expr`` with each function of numbers alone (cos 37.1234°) as a float of
    ``digits`` digits: sympy solving with an exact cos(pπ/q) of a large q builds its
    minimal polynomial, of degree about q, without end. For numbers only (a solve that
    decides a sense, a scene to integrate), never for a formula shown.

    >>> x = sympy.Symbol("x")
    >>> y = float_functions(x * sympy.cos(sympy.pi * sympy.Rational(371234, 1800000)))
    >>> round(float(y.coeff(x)), 9)
    0.797337508
    """
    numbers = {f: f.evalf(digits) for f in expr.atoms(sympy.Function) if f.is_number}
    return expr.xreplace(numbers) if numbers else expr


def tidy(expr: sympy.Expr | int, light: bool = True) -> sympy.Expr:
    """``expr`` in its tidiest cheap canonical form; ``sympy.simplify`` only as a last resort.

    The candidates are the expression itself, its ``together``-, ``cancel``- and
    ``factor_terms``-ed forms, its products distributed (``expand_mul``, for small forms),
    its roots combined (``powsimp``) and, where sines and cosines appear, each with
    ``sin(u)**2 + cos(u)**2 = 1`` applied; the one that prints shortest wins (ties: fewer
    operations, then the first). ``sympy.simplify`` (which tries far more, at up to a
    hundred times the cost) runs only on a small result that still holds a sine and a
    cosine of one angle, and is kept only when it is smaller still. In numeric mode
    (:func:`light_tidying`) a form that is surely not 0 is left as it is, unless ``light``
    is False (a decision read from the form: its sign, whether it is a sine).

    >>> import sympy
    >>> r, u, a, b = sympy.symbols("r u a b")
    >>> tidy(2 * r), tidy(sympy.sin(r) ** 2 + sympy.cos(r) ** 2)
    (2*r, 1)
    >>> tidy(a * b * sympy.sin(u) ** 2 + a * b * sympy.cos(u) ** 2)
    a*b
    >>> tidy((a * b - b**2) / (a - b))
    b
    """
    expr = sympy.Integer(0) + expr
    if expr.is_Atom or sympy.count_ops(expr) <= 3:
        return expr
    return _tidied(expr, light and _LIGHT.get())


@cacheit  # the model tidies the same form again and again (half of the calls are repeats)
def _tidied(expr: sympy.Expr, light: bool) -> sympy.Expr:
    """:func:`tidy`'s search for the tidiest form of ``expr``, once per form and ``light``
    (numeric mode, where a form surely not 0 is left as it is); sympy's cache, cleared with it."""
    if light and surely_nonzero(expr):
        return expr
    if light and _numerically_zero(expr):
        return sympy.Integer(0)
    best = min(_cheap_forms(expr), key=printed_size)
    if _worth_simplifying(best):
        simpler = sympy.simplify(best)
        if printed_size(simpler) < printed_size(best):
            best = simpler
    return best


def abs_resolved(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with each |x| written as x or −x by the sign of x in ``values`` (a length
    |E − P| = L_0 − δ where L_0 > δ), then tidied; an |x| whose sign is not known is kept.

    >>> L, d = sympy.symbols("L_0 delta", positive=True)
    >>> abs_resolved(sympy.Abs(L - d) - L, {L: 1, d: sympy.Rational(1, 5)})
    -delta
    """

    def signed(argument: sympy.Expr) -> sympy.Expr:
        value = real_value(argument, values)
        if value is None or value == 0:
            return sympy.Abs(argument)
        return argument if value > 0 else -argument

    return tidy((sympy.Integer(0) + expr).replace(sympy.Abs, signed))


_LIGHT: ContextVar[bool] = ContextVar("light_tidy", default=False)


@contextmanager
def light_tidying(on: bool = True) -> Iterator[None]:
    """While ``on`` (numeric mode), :func:`tidy` leaves a form that is not 0 as it is (no
    ``cancel``, Pythagoras or ``simplify``): numeric mode shows the model's formulas as the
    model wrote them, and solves with numbers. A form that may be 0 (numerically 0 at a point
    where every letter has a value its assumptions allow, or not a number there) still
    gets the full :func:`tidy`, so every test ``tidy(x) == 0`` answers as in exact mode:
    were ``x`` identically 0, it would be 0 at that point."""
    token = _LIGHT.set(on)
    try:
        yield
    finally:
        _LIGHT.reset(token)


def tidying_lightly() -> bool:
    """True inside :func:`light_tidying` (numeric mode's model building)."""
    return _LIGHT.get()


def _probe(symbol: sympy.Symbol, salt: int = 0) -> sympy.Rational | None:
    """A value for ``symbol`` its assumptions allow (None for an integer or a symbol whose
    sign is not known as such): 1 + (a number in [0, 1) from its name and ``salt``, which
    picks another point), negative where it must be."""
    if symbol.is_integer:
        return None
    value = sympy.Rational(1 + (sum(map(ord, symbol.name)) + 31 * salt) % 89, 89) + 1
    value += sympy.Rational((len(symbol.name) + 3 * salt) % 7, 701 + 2 * salt)
    if symbol.is_negative or symbol.is_nonpositive:
        return -value
    return value


def probe_point(expr: sympy.Expr, salt: int = 0) -> dict[sympy.Symbol, sympy.Rational] | None:
    """A point of the domain of ``expr``'s letters: each a value its assumptions allow
    (from its name and ``salt``, which picks another point); None when a letter has none
    (an integer, or a symbol whose sign is not known as such).

    >>> m = sympy.Symbol("m", positive=True)
    >>> point = probe_point(m - 1)
    >>> 1 < point[m] < 3, probe_point(sympy.Symbol("n", integer=True)) is None
    (True, True)
    """
    point = {}
    for symbol in expr.free_symbols:
        value = _probe(symbol, salt) if isinstance(symbol, sympy.Symbol) else None
        if value is None:
            return None
        point[symbol] = value
    return point


def surely_nonzero(expr: sympy.Expr) -> bool:
    """True when ``expr`` is a number not 0, to the digits sympy's ``evalf`` guarantees,
    at one point of the letters' domain: then it is not identically 0. False (not known)
    when a letter has no probe value, the value is not a number, or it has no digits."""
    point = probe_point(expr)
    if point is None:
        return False
    try:
        value = sympy.N(expr.xreplace(point), 15, maxn=MAX_DIGITS)
    except (TypeError, ValueError, ArithmeticError, RecursionError):
        return False
    if not value.is_number:
        return False
    if value.is_Rational:
        return value != 0
    return any(f._prec > 10 and f != 0 for f in value.atoms(sympy.Float))


ZERO_POINTS = 3  # numeric mode's zero test: points of the letters' domain
ZERO_DIGITS = 30  # digits each is evaluated to
ZERO_TOLERANCE = 1e-20  # |value| next to the sum of its terms' sizes that counts as 0


def _numerically_zero(expr: sympy.Expr) -> bool:
    """Numeric mode's test of a form that is not surely nonzero: True when it is 0 at
    :data:`ZERO_POINTS` points of its letters' domain, each evaluated to
    :data:`ZERO_DIGITS` digits (a sum within :data:`ZERO_TOLERANCE` of the sizes of its
    terms), so that numeric mode need not search for its tidiest form to find 0 (a
    form that is 0 at three points with irrational-free but unrelated coordinates and
    not identically 0 would have to vanish there by coincidence). False (not known) when
    a letter has no probe value or a point gives no number.

    >>> a, b = sympy.symbols("a b", positive=True)
    >>> _numerically_zero((a * b - b**2) / (a - b) - b), _numerically_zero(a - b)
    (True, False)
    """
    terms = sympy.Add.make_args(expr)
    for salt in range(ZERO_POINTS):
        point = probe_point(expr, salt)
        if point is None:
            return False
        quick = _quick_zero(expr, point)
        if quick is not None:
            if not quick:
                return False
            continue
        try:  # the sum to 30 digits (evalf works through its cancellation), terms' sizes
            total = complex(sympy.N(expr.xreplace(point), ZERO_DIGITS, maxn=MAX_DIGITS))
            size = sum(abs(complex(sympy.N(t.xreplace(point), 15))) for t in terms)
        except (TypeError, ValueError, ArithmeticError, RecursionError):
            return False
        if not abs(total) <= ZERO_TOLERANCE * size:  # (a nan is not 0)
            return False
    return True


def _quick_zero(expr: sympy.Expr, point: Mapping[sympy.Symbol, sympy.Rational]) -> bool | None:
    """Whether ``expr`` is 0 at ``point`` by a walk over its nodes in mpmath at
    ZERO_DIGITS + 15 digits, against the size of its sums taken as sums of magnitudes (an
    evalf of a long trigonometric form costs ten times as much); None when a node is not
    one the walk knows (the caller uses evalf).

    >>> a, b = sympy.symbols("a b", positive=True)
    >>> _quick_zero(sympy.sin(a)**2 + sympy.cos(a)**2 - 1, {a: sympy.Rational(3, 2)})
    True
    >>> _quick_zero(a - b, {a: sympy.Integer(2), b: sympy.Integer(3)})
    False
    """
    import mpmath

    from dynsolve.solver.evaluate import NotQuick, mp_size, mp_value

    with mpmath.workdps(ZERO_DIGITS + 15):
        try:
            at = {s: mpmath.mpf(int(v.p)) / int(v.q) for s, v in point.items()}
            seen: dict[sympy.Basic, object] = {}
            total = mp_value(expr, at, seen)  # type: ignore[arg-type]
            size = mp_size(expr, at, seen)  # type: ignore[arg-type]
        except (NotQuick, ZeroDivisionError, ValueError, TypeError, ArithmeticError):
            return None
        if not (mpmath.isfinite(total) and mpmath.isfinite(size)):
            return None
        return bool(abs(total) <= ZERO_TOLERANCE * size)


@cacheit  # the same candidate forms come back (an expression and its factor_terms)
def printed_size(expr: sympy.Expr) -> tuple[int, int]:
    """How long a form prints, then how many operations it has: the smaller, the tidier."""
    return len(sympy.sstr(expr)), sympy.count_ops(expr)


def _cheap_forms(expr: sympy.Expr) -> list[sympy.Expr]:
    """The canonical forms :func:`tidy` chooses from; the costlier ones only where they can
    change the form (a symbolic denominator or a small form for ``cancel``, a product of a
    sum for ``expand_mul``, a root for ``powsimp``, a sine or cosine for Pythagoras)."""
    forms = [expr, sympy.factor_terms(expr)]
    distributable = [expr]
    arguments = {f.args[0] for f in expr.atoms(sympy.sin, sympy.cos)}
    reduced = _pythagoras_forms(expr) if arguments else None
    denominator = _symbolic_denominator(expr)
    if denominator and reduced is None:  # (the reduced forms are cancelled without sines)
        forms.append(sympy.together(expr))
    if reduced is None and (denominator or sympy.count_ops(expr) <= CANCEL_OPS):
        try:
            cancelled = sympy.cancel(expr)
            forms += [cancelled, sympy.factor_terms(cancelled)]
            distributable.append(cancelled)
        except sympy.PolynomialError:  # a form cancel cannot treat as a rational function
            pass
    if any(any(f.is_Add for f in m.args) for m in expr.atoms(sympy.Mul)):
        forms += [sympy.expand_mul(f) for f in distributable if sympy.count_ops(f) <= EXPAND_OPS]
    if any(p.exp.is_Rational and not p.exp.is_Integer for p in expr.atoms(sympy.Pow)):
        forms += [sympy.powsimp(f) for f in distributable]  # sqrt(3)*sqrt(x) = sqrt(3*x)
    if reduced is not None:
        forms += reduced
    elif arguments:
        one = {sympy.sin(u) ** 2: 1 - sympy.cos(u) ** 2 for u in arguments}
        for form in list(forms):
            replaced = form.subs(one)
            if replaced != form:
                forms += [replaced, sympy.factor_terms(sympy.cancel(replaced))]
    return list(dict.fromkeys(forms))  # each distinct form once, in order


FACTOR_OPS = 80  # sympy.factor only on reduced forms at most this large


def _pythagoras_forms(expr: sympy.Expr) -> list[sympy.Expr] | None:
    """The forms of a polynomial in sines and cosines reduced by sin² + cos² = 1
    (:func:`dynsolve.trig.pythagoras`'s canonical remainder): with its common factors out,
    cancelled, and factored where no sine or cosine is left (a part's distance² from a
    composite's G, (L − 2d)² m_s²/(4 (m_rod + m_s)²)); None where ``expr`` is not such a
    polynomial (a sine under a root or in a denominator) or holds a sine of a sum of angles
    (a phase, A sin(ω t + φ), is kept as written)."""
    from dynsolve.trig import reduced_form

    reduced = reduced_form(expr, sums=False)
    if reduced is None:
        return None
    forms = [sympy.factor_terms(reduced)]
    if not reduced.has(sympy.sin, sympy.cos) and sympy.count_ops(reduced) <= FACTOR_OPS:
        forms.append(sympy.factor(reduced))
    else:
        forms.append(sympy.factor_terms(sympy.cancel(reduced)))
    return forms


def _symbolic_denominator(expr: sympy.Expr) -> bool:
    """A power with a negative exponent of something with a symbol (``1/(a + b)``, ``a**-2``)."""
    return any(p.exp.is_negative and p.base.free_symbols for p in expr.atoms(sympy.Pow))


def _worth_simplifying(expr: sympy.Expr) -> bool:
    """A small form with a sine and a cosine of the same angle, where ``simplify`` may still
    find an identity the cheap forms miss (``sin(u)*cos(u) = sin(2*u)/2``), unless every
    sine and cosine stands alone in its term, of a plain angle (``a*sin(u) + b*cos(u)``):
    no identity shortens that (a spring on an incline spent 0.3 s in it, 2026-11-25).
    Elsewhere it hardly ever finds a shorter form in the bundled problems (8 of 98 calls,
    2026-11-24).

    >>> u, v, a, b = sympy.symbols("u v a b")
    >>> _worth_simplifying(a * sympy.sin(u) * sympy.cos(u) + b)
    True
    >>> _worth_simplifying(sympy.sin(u + v) - sympy.sin(u) * sympy.cos(v) + sympy.cos(u))
    True
    >>> _worth_simplifying(sympy.sqrt(a * sympy.sin(u) + b * sympy.cos(u)))
    False
    """
    if sympy.count_ops(expr) > SIMPLIFY_OPS:
        return False
    sines = {f.args[0] for f in expr.atoms(sympy.sin)}
    if not any(f.args[0] in sines for f in expr.atoms(sympy.cos)):
        return False
    return any(_trigonometric_interplay(node) for node in sympy.preorder_traversal(expr))


def _is_trig(expr: sympy.Expr) -> bool:
    return isinstance(expr, sympy.sin | sympy.cos)


def _trigonometric_interplay(node: sympy.Expr) -> bool:
    """A sine or cosine of a sum, a power of one (not the first), or a product of two."""
    if _is_trig(node):
        return node.args[0].is_Add
    if node.is_Pow:
        return _is_trig(node.base) and node.exp != 1
    if node.is_Mul:
        return sum(_is_trig(factor.as_base_exp()[0]) for factor in node.args) >= 2
    return False


def mpmath_function(
    variables: Sequence[sympy.Symbol], expr: sympy.Expr | sympy.Matrix | list[sympy.Expr]
) -> Callable[..., object]:
    """``expr`` as a function of ``variables`` evaluated with mpmath.

    The variables are renamed first: lambdify puts every symbol of a matrix into the
    generated code's namespace under its own name, so an unknown called ``mpf`` would
    replace mpmath's ``mpf`` (and every constant written ``mpf(1)/mpf(2)`` would fail).

    >>> mpf, x = sympy.symbols("mpf x")
    >>> jacobian = mpmath_function([mpf, x], sympy.Matrix([[mpf / 2 + x]]))
    >>> jacobian(3, 1)
    matrix(
    [['2.5']])
    """
    renamed = {v: sympy.Dummy(f"u{i}") for i, v in enumerate(variables)}
    plain = (
        [e.xreplace(renamed) for e in expr] if isinstance(expr, list) else expr.xreplace(renamed)
    )
    return sympy.lambdify(list(renamed.values()), plain, modules="mpmath")
