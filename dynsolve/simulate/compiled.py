"""Float functions of sympy expressions, written as Python without sympy's code printers.

``sympy.lambdify`` prints each expression with sympy's code printer, which orders the
terms of every sum and product, and with ``cse`` searches it for common subexpressions:
5 to 15 ms for a scene's equation of motion, more than the short integration of a
cross-check that it serves. Here the expression graph is walked once: sympy builds equal
subtrees as one object, so a node met twice outside the branches of a ``Piecewise`` is
computed once into a local of its own, and every other node is written inline, in the
order sympy stores its arguments. Numbers (``3*sqrt(3)/5``) become float literals. A
branch of a ``Piecewise`` is evaluated only when its condition holds, as with lambdify
(a spring's force divides by its length, which is 0 where it is slack). An expression
with a node not listed here is left to lambdify.

>>> q, v = sympy.symbols("q v")
>>> f = float_function([q, v], [q**2 * v / 2, sympy.Piecewise((1 / q, q > 0), (0, True))])
>>> f(2.0, 3.0), f(0.0, 1.0)
((6.0, 0.5), (0.0, 0.0))
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable, Sequence

import sympy

_FUNCTIONS = {  # sympy function → its name in the generated code (math's, or a builtin)
    sympy.sin: "math.sin",
    sympy.cos: "math.cos",
    sympy.tan: "math.tan",
    sympy.asin: "math.asin",
    sympy.acos: "math.acos",
    sympy.atan: "math.atan",
    sympy.atan2: "math.atan2",
    sympy.sinh: "math.sinh",
    sympy.cosh: "math.cosh",
    sympy.tanh: "math.tanh",
    sympy.exp: "math.exp",
    sympy.log: "math.log",
    sympy.Abs: "abs",
    sympy.Max: "max",
    sympy.Min: "min",
    sympy.floor: "math.floor",
    sympy.ceiling: "math.ceil",
}
_RELATIONS = {
    sympy.StrictLessThan: "<",
    sympy.StrictGreaterThan: ">",
    sympy.LessThan: "<=",
    sympy.GreaterThan: ">=",
    sympy.Equality: "==",
    sympy.Unequality: "!=",
}


class NotCompiled(ValueError):
    """An expression holds a node the generator does not write (lambdify it instead)."""


def float_function(
    variables: Sequence[sympy.Symbol], exprs: Sequence[sympy.Expr | int | float]
) -> Callable[..., tuple[float, ...]]:
    """The tuple of ``exprs`` as one Python function of float ``variables`` (math only);
    ``sympy.lambdify(variables, exprs, "math", cse=True)`` where a node is not one the
    generator writes."""
    outputs = [sympy.sympify(e) for e in exprs]
    try:
        source = _Writer(variables, outputs).source()
    except NotCompiled:
        return sympy.lambdify(list(variables), tuple(outputs), "math", cse=True)
    return _compiled(source)


def float_scalar(
    variables: Sequence[sympy.Symbol], expr: sympy.Expr | int | float
) -> Callable[..., float]:
    """One expression as a Python function of float ``variables`` (see
    :func:`float_function`), returning a float, not a tuple.

    >>> x = sympy.Symbol("x")
    >>> float_scalar([x], sympy.sqrt(x) + 1)(4.0)
    3.0
    """
    output = sympy.sympify(expr)
    try:
        source = _Writer(variables, [output]).source(single=True)
    except NotCompiled:
        return sympy.lambdify(list(variables), output, "math", cse=True)
    return _compiled(source)


def _compiled(source: str) -> Callable[..., object]:
    """The function ``_generated`` that ``source`` defines, with math in its namespace."""
    namespace: dict[str, object] = {"math": math}
    exec(compile(source, "<dynsolve float function>", "exec"), namespace)
    return namespace["_generated"]  # type: ignore[return-value]


class _Writer:
    """Writes the Python source of one float function of ``variables``."""

    def __init__(self, variables: Sequence[sympy.Symbol], outputs: Sequence[sympy.Basic]):
        self.names = {v: f"a{i}" for i, v in enumerate(variables)}
        self.outputs = outputs
        self.uses: Counter[sympy.Basic] = Counter()  # parents met outside any branch
        self.lines: list[str] = []
        self.locals: dict[sympy.Basic, str] = {}
        for expr in outputs:
            self._count(expr)

    def source(self, single: bool = False) -> str:
        """The function's source: each shared node once, then the tuple of the outputs
        (with ``single``, the one output itself)."""
        body = ", ".join(self._code(e) for e in self.outputs)
        arguments = ", ".join(self.names.values())
        result = body if single else f"({body},)"
        lines = [f"def _generated({arguments}):", *self.lines, f"    return {result}"]
        return "\n".join(lines) + "\n"

    def _count(self, node: sympy.Basic) -> None:
        """Count the parents of each node computed at every call (not in a branch)."""
        self.uses[node] += 1
        if self.uses[node] > 1 or _is_leaf(node):
            return
        if isinstance(node, sympy.Piecewise):
            self._count(node.args[0].cond)  # later conditions and the branches: lazily
            return
        for argument in node.args:
            self._count(argument)

    def _code(self, node: sympy.Basic) -> str:
        """``node`` as an expression: a local where it is shared, else written inline."""
        if node in self.locals:
            return self.locals[node]
        code = self._written(node)
        if self.uses[node] > 1 and not _is_leaf(node):
            name = f"x{len(self.locals)}"
            self.lines.append(f"    {name} = {code}")
            self.locals[node] = name
            return name
        return code

    def _written(self, node: sympy.Basic) -> str:
        """``node`` written from its arguments' code."""
        if node in self.names:
            return self.names[node]
        if node.is_Boolean and node in (sympy.true, sympy.false):
            return "True" if node is sympy.true else "False"
        if isinstance(node, sympy.Expr) and node.is_number:
            return _literal(node)
        if isinstance(node, sympy.Symbol):
            raise NotCompiled(f"the letter {node} is not a variable")
        if node.is_Add:
            return "(" + " + ".join(self._terms(node.args, sympy.Add)) + ")"
        if node.is_Mul:
            return self._product(node)
        if node.is_Pow:
            return self._power(node)
        if isinstance(node, sympy.Piecewise):
            return self._piecewise(node)
        return self._call(node)

    def _terms(self, arguments: Sequence[sympy.Basic], operation: type) -> list[str]:
        """The code of each argument of a sum or product, its numbers folded into one."""
        numbers = [a for a in arguments if _is_leaf(a) and a not in self.names]
        others = [self._code(a) for a in arguments if not (_is_leaf(a) and a not in self.names)]
        if len(numbers) > 1:
            numbers = [operation(*numbers)]
        return [*(_literal(n) for n in numbers), *others]

    def _product(self, node: sympy.Basic) -> str:
        """A product, its factors with exponent −1 written as divisors."""
        above = self._terms([a for a in node.args if not _reciprocal(a)], sympy.Mul)
        below = [self._code(a.base) for a in node.args if _reciprocal(a)]
        code = "*".join(above) if above else "1.0"
        return "(" + code + "".join(f"/{b}" for b in below) + ")"

    def _power(self, node: sympy.Basic) -> str:
        base, exponent = self._code(node.base), node.exp
        if exponent == sympy.S.Half:
            return f"math.sqrt({base})"
        if exponent == -sympy.S.Half:
            return f"(1.0/math.sqrt({base}))"
        if exponent == -1:
            return f"(1.0/{base})"
        if exponent.is_Integer:
            return f"({base}**{int(exponent)})"
        return f"({base}**{self._code(exponent)})"

    def _piecewise(self, node: sympy.Basic) -> str:
        """Nested conditional expressions: each branch evaluated only when chosen."""
        code = "math.nan"  # no condition holds: undefined, as sympy's Piecewise
        for piece in reversed(node.args):
            if piece.cond is sympy.true:
                code = self._code(piece.expr)
            else:
                code = f"({self._code(piece.expr)} if {self._code(piece.cond)} else {code})"
        return code

    def _call(self, node: sympy.Basic) -> str:
        """A function, a relation or a logical connective of its arguments."""
        arguments = [self._code(a) for a in node.args]
        if type(node) in _RELATIONS:
            return f"({arguments[0]} {_RELATIONS[type(node)]} {arguments[1]})"
        if isinstance(node, sympy.And | sympy.Or):
            joint = " and " if isinstance(node, sympy.And) else " or "
            return "(" + joint.join(arguments) + ")"
        if isinstance(node, sympy.Not):
            return f"(not {arguments[0]})"
        if isinstance(node, sympy.sign):
            return f"(0.0 if {arguments[0]} == 0 else math.copysign(1.0, {arguments[0]}))"
        if node.func.__name__ == "sqrt" and len(arguments) == 1:  # a root left unevaluated
            return f"math.sqrt({arguments[0]})"
        name = _FUNCTIONS.get(node.func)
        if name is None:
            raise NotCompiled(f"no code for {node.func}")
        return f"{name}({', '.join(arguments)})"


def _is_leaf(node: sympy.Basic) -> bool:
    """A variable, a number or a truth value: written where it is used, never a local."""
    return node.is_Atom or (isinstance(node, sympy.Expr) and node.is_number)


def _reciprocal(node: sympy.Basic) -> bool:
    """A factor x**-1 of a product (with x not a number)."""
    return node.is_Pow and node.exp == -1 and not node.base.is_number


def _literal(number: sympy.Expr) -> str:
    """A number as a float literal; NotCompiled where it is not a finite real."""
    try:
        value = float(number)
    except TypeError as exc:  # complex, or not a number after all
        raise NotCompiled(f"{number} is not a real number") from exc
    if not math.isfinite(value):
        raise NotCompiled(f"{number} is not finite")
    return f"({value!r})"
