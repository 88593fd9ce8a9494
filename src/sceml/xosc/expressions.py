"""A small safe evaluator for OpenSCENARIO `${...}` expressions (1.1+ grammar, used for 1.0 too).

Numbers, `$parameter`s, + - * / %, unary minus, parentheses, the functions of the standard
(round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos, atan, sign, abs, max, min), the
constant `pi` and the boolean operators (not, and, or, comparisons) are read by a
recursive-descent parser; nothing is ever handed to Python's eval. It is bounded: nesting
(MAX_DEPTH), length (MAX_LENGTH), and every value a finite double, so a hostile expression is an
ExpressionError, never a RecursionError or an overflow.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping

_TOKEN = re.compile(
    r"\s*(?:(?P<number>\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)"
    r"|(?P<parameter>\$[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<op>==|!=|<=|>=|[-+*/%(),<>]))"
)

_FUNCTIONS: dict[str, Callable[..., float]] = {
    "round": lambda x: float(math.floor(x + 0.5)),
    "floor": lambda x: float(math.floor(x)),
    "ceil": lambda x: float(math.ceil(x)),
    "sqrt": math.sqrt,
    "pow": math.pow,
    "sin": math.sin,
    "cos": math.cos,
    "tan": math.tan,
    "asin": math.asin,
    "acos": math.acos,
    "atan": math.atan,
    "sign": lambda x: float((x > 0) - (x < 0)),
    "abs": abs,
    "max": max,
    "min": min,
}


_COMPARISONS: dict[str, Callable[[float, float], bool]] = {
    "==": lambda a, b: a == b,
    "!=": lambda a, b: a != b,
    "<": lambda a, b: a < b,
    "<=": lambda a, b: a <= b,
    ">": lambda a, b: a > b,
    ">=": lambda a, b: a >= b,
}


#: Parentheses and calls nested deeper than this are refused (the parser recurses per level).
MAX_DEPTH = 100
#: Longer expressions are refused before they are read.
MAX_LENGTH = 100_000
#: Named constants (esmini reads `pi`).
_CONSTANTS = {"pi": math.pi}


class ExpressionError(ValueError):
    """The expression cannot be read or computed; the message says why."""


def _finite(value: float) -> float:
    """`value`, or ExpressionError when it overflowed (OpenSCENARIO numbers are doubles)."""
    if not math.isfinite(value):
        raise ExpressionError("the value is too large (beyond a double)")
    return value


def _tokens(text: str) -> list[tuple[str, str]]:
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"the expression is longer than {MAX_LENGTH:,} characters")
    found, position = [], 0
    text = text.rstrip()
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None or match.end() == position:
            raise ExpressionError(f"unexpected {text[position:].strip()[:10]!r}")
        kind = match.lastgroup or ""
        found.append((kind, match.group(kind)))
        position = match.end()
    return found


class _Parser:
    def __init__(self, text: str, values: Mapping[str, str]) -> None:
        self.tokens = _tokens(text)
        self.at = 0
        self.values = values
        self.depth = 0

    def peek(self) -> str | None:
        return self.tokens[self.at][1] if self.at < len(self.tokens) else None

    def take(self, expected: str | None = None) -> tuple[str, str]:
        if self.at >= len(self.tokens):
            raise ExpressionError("the expression ends too early")
        token = self.tokens[self.at]
        if expected is not None and token[1] != expected:
            raise ExpressionError(f"expected {expected!r}, found {token[1]!r}")
        self.at += 1
        return token

    def parse(self) -> float:
        value = self.disjunction()
        if self.at != len(self.tokens):
            raise ExpressionError(f"unexpected {self.tokens[self.at][1]!r}")
        return value

    def disjunction(self) -> float:
        value = self.conjunction()
        while self.peek() == "or":
            self.take()
            right = self.conjunction()
            value = float(bool(value) or bool(right))
        return value

    def conjunction(self) -> float:
        value = self.negation()
        while self.peek() == "and":
            self.take()
            right = self.negation()
            value = float(bool(value) and bool(right))
        return value

    def negation(self) -> float:
        flips = 0
        while self.peek() == "not":  # a loop, not recursion: any number of them
            self.take()
            flips += 1
        value = self.comparison()
        return value if not flips else float(bool(value) != (flips % 2 == 1))

    def comparison(self) -> float:
        value = self.sum()
        while self.peek() in _COMPARISONS:
            test = _COMPARISONS[self.take()[1]]
            value = float(test(value, self.sum()))
        return value

    def sum(self) -> float:
        value = self.product()
        while self.peek() in ("+", "-"):
            sign = self.take()[1]
            right = self.product()
            value = _finite(value + right if sign == "+" else value - right)
        return value

    def product(self) -> float:
        value = self.unary()
        while self.peek() in ("*", "/", "%"):
            op = self.take()[1]
            right = self.unary()
            if op != "*" and right == 0:
                raise ExpressionError("division by zero")
            value = _finite(
                value * right if op == "*" else value / right if op == "/" else value % right
            )
        return value

    def unary(self) -> float:
        signs = 0
        while self.peek() == "-":  # a loop, not recursion: any number of them
            self.take()
            signs += 1
        value = self.atom()
        return -value if signs % 2 else value

    def atom(self) -> float:
        kind, text = self.take()
        if kind == "number":
            return _finite(float(text))
        if kind == "parameter":
            return number(self.values, text[1:])
        if text == "(":
            self.nest()
            value = self.disjunction()
            self.take(")")
            self.depth -= 1
            return value
        if kind == "name" and text in _CONSTANTS:
            return _CONSTANTS[text]
        if kind == "name" and text in ("true", "false"):
            return 1.0 if text == "true" else 0.0
        if kind == "name" and text in _FUNCTIONS:
            return self.call(text)
        raise ExpressionError(f"unexpected {text!r}")

    def nest(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ExpressionError(f"parentheses and calls are nested more than {MAX_DEPTH} deep")

    def call(self, name: str) -> float:
        self.take("(")
        self.nest()
        arguments = [self.disjunction()]
        while self.peek() == ",":
            self.take()
            arguments.append(self.disjunction())
        self.take(")")
        self.depth -= 1
        try:
            return _finite(float(_FUNCTIONS[name](*arguments)))
        except (TypeError, ValueError, OverflowError) as error:
            shown = ", ".join(f"{a:g}" for a in arguments)
            raise ExpressionError(f"{name}({shown}) cannot be computed: {error}") from None


def number(values: Mapping[str, str], name: str) -> float:
    """A declared parameter's value as a number."""
    if name not in values:
        raise ExpressionError(f"parameter ${name} is not declared")
    try:
        return float(values[name])
    except ValueError:
        raise ExpressionError(f"parameter ${name} = {values[name]!r} is not a number") from None


def evaluate(expression: str, values: Mapping[str, str]) -> float:
    """The value of the text between `${` and `}`."""
    return _Parser(expression, values).parse()


def text_of(value: float) -> str:
    """A computed number as OpenSCENARIO text: integers without a fraction."""
    if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return repr(value)
