"""Parameter declarations and `$name` / `${expression}` values, resolved in place, by scope.

A ParameterDeclarations element declares for its parent and everything below it; a declaration
may use the ones declared before it. Every attribute that starts with `$` is replaced by its
value, so later stages only see literals (the import report lists the parameters used).

When a distribution varies some top-level parameters (`traced`), each attribute that is exactly
`$name` of one of them is marked (`traced.mark`) and recorded as a `Use`, so that the values it
becomes can be found in the model; a declaration whose value is exactly `$name` (a catalog
entry's assigned parameter, an inner alias) passes the distribution on to its own name, and an
inner declaration of the same name hides it. A use inside `${...}` is recorded as an expression:
SceML cannot carry a distribution through arithmetic.
"""

from __future__ import annotations

import math
import re
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field

from lxml import etree

from ..xosc.expressions import ExpressionError, evaluate, text_of
from . import traced as tracing
from .reading import Source

_REFERENCE = re.compile(r"\$([A-Za-z_][A-Za-z0-9_]*)")


@dataclass(frozen=True)
class Use:
    """One place the file uses a distributed parameter."""

    parameter: str
    element: str
    attribute: str
    file: str
    line: int | None
    #: Inside a `${...}` expression (the value is computed, so it keeps its declared value).
    expression: bool = False

    def place(self) -> tuple[str, int | None, str]:
        """(parameter, line, attribute), as `traced.Traced.place` gives it."""
        return self.parameter, self.line, self.attribute


@dataclass
class Resolved:
    """The top-level declarations and the uses of the traced parameters."""

    top: dict[str, str] = field(default_factory=dict)
    uses: list[Use] = field(default_factory=list)


@dataclass(frozen=True)
class _Scope:
    values: Mapping[str, str]
    #: Name -> the traced top-level parameter it stands for, and how.
    origins: Mapping[str, tracing.Link]


def resolve(source: Source, traced: Collection[str] = ()) -> Resolved:
    """Replace every parameter reference in the tree; `traced` names the distributed ones."""
    resolved = Resolved()
    _resolve(source, source.root, _Scope({}, {}), resolved, frozenset(traced))
    return resolved


def _resolve(
    source: Source,
    element: etree._Element,
    scope: _Scope,
    resolved: Resolved,
    traced: frozenset[str],
) -> None:
    declarations = element.find("ParameterDeclarations")
    if declarations is not None:
        scope = _declare(source, element, declarations, scope, resolved, traced)
    _substitute(source, element, scope, resolved)
    for child in element:
        if isinstance(child.tag, str) and child is not declarations:
            _resolve(source, child, scope, resolved, traced)


def _declare(
    source: Source,
    element: etree._Element,
    declarations: etree._Element,
    scope: _Scope,
    resolved: Resolved,
    traced: frozenset[str],
) -> _Scope:
    values, origins = dict(scope.values), dict(scope.origins)
    top = element is source.root
    for declaration in declarations.iterchildren("ParameterDeclaration"):
        name, text = declared_name(declaration), str(declaration.get("value", ""))
        declaration.set("name", name)  # the name is no reference, even with its `$`
        origin = _link(text, values, origins)
        _substitute(source, declaration, _Scope(values, origins), None)
        values[name] = str(declaration.get("value", ""))
        origins.pop(name, None)
        if top and name in traced:
            origins[name] = tracing.Link(name)
        elif origin is not None:
            origins[name] = origin
    if top:
        resolved.top.update(values)
    return _Scope(values, origins)


def _substitute(
    source: Source, element: etree._Element, scope: _Scope, resolved: Resolved | None
) -> None:
    for key, value in element.attrib.items():
        if not value.startswith("$"):
            continue
        if resolved is not None:
            _trace(source, element, str(key), value, scope, resolved)
        element.set(key, _value(source, element, key, value, scope.values))


def _trace(
    source: Source,
    element: etree._Element,
    key: str,
    text: str,
    scope: _Scope,
    resolved: Resolved,
) -> None:
    expression = text.startswith("${")
    names = _REFERENCE.findall(text) if expression else [text[1:]]
    file, line = source.where(element)
    for name in names:
        origin = scope.origins.get(name)
        if origin is None:
            continue
        resolved.uses.append(Use(origin.origin, str(element.tag), key, file, line, expression))
    link = _link(text, scope.values, scope.origins)
    if link is not None:
        tracing.mark(element, key, link)


def _link(
    text: str, values: Mapping[str, str], origins: Mapping[str, tracing.Link]
) -> tracing.Link | None:
    """What a value written as `text` is of a traced parameter: `$name` is the name's own link;
    `${expression}` of one traced name is its link when the expression is affine in it (a
    speed in km/h divided by 3.6, an offset plus a lane width), so the distribution can be
    carried through (`tracing.Link.applied`); anything else is None (the value is computed)."""
    if not text.startswith("$"):
        return None
    if not text.startswith("${"):
        return origins.get(text[1:])
    expression = text[2:-1] if text.endswith("}") else ""
    names = {name for name in _REFERENCE.findall(expression) if name in origins}
    if len(names) != 1:
        return None
    (name,) = names
    affine = _affine(expression, name, values)
    return None if affine is None else origins[name].then(*affine)


#: Where an expression is probed around the declared value, off any integer grid so that a
#: step function (floor, round) is not taken for a line.
_PROBES = (0.0, 0.37, 1.29, -0.73, 3.11)


def _affine(expression: str, name: str, values: Mapping[str, str]) -> tuple[float, float] | None:
    """(scale, shift) when `expression` is scale * name + shift near the name's value."""
    try:
        here = float(values[name])
    except (KeyError, ValueError):
        return None
    points = []
    for probe in _PROBES:
        at = here + probe * max(1.0, abs(here))
        try:
            points.append((at, evaluate(expression, {**values, name: repr(at)})))
        except (ExpressionError, ArithmeticError):
            return None
    (x0, y0), (x1, y1) = points[0], points[1]
    # Twelve significant digits: the probes' rounding noise (0.4 + 4e-16) is not the file's.
    scale = float(f"{(y1 - y0) / (x1 - x0):.12g}")
    shift = y0 - scale * x0
    shift = 0.0 if abs(shift) <= 1e-9 * max(1.0, abs(y0)) else float(f"{shift:.12g}")
    if scale == 0 or not all(
        math.isclose(y, scale * x + shift, rel_tol=1e-9, abs_tol=1e-9) for x, y in points
    ):
        return None
    return scale, shift


def declared_name(declaration: etree._Element) -> str:
    """A ParameterDeclaration's name; scenariogeneration writes it with a leading `$`, which
    esmini accepts, so the `$` is dropped."""
    return str(declaration.get("name", "")).removeprefix("$")


def values_at(source: Source, element: etree._Element) -> dict[str, str]:
    """The parameter values visible at `element`, before the tree is resolved (catalog step).

    Declarations are evaluated from the root down, as `resolve` will do later; an attribute
    here is only read, never changed.
    """
    values: dict[str, str] = {}
    for holder in [*reversed(list(element.iterancestors())), element]:
        declarations = holder.find("ParameterDeclarations")
        for declaration in [] if declarations is None else declarations:
            if declaration.tag != "ParameterDeclaration":
                continue
            text = str(declaration.get("value", ""))
            if text.startswith("$"):
                text = _value(source, declaration, "value", text, values)
            values[declared_name(declaration)] = text
    return values


def value_of(source: Source, element: etree._Element, key: str, values: Mapping[str, str]) -> str:
    """One attribute's value with `$name` / `${expression}` resolved in `values`."""
    text = str(element.get(key, ""))
    return _value(source, element, key, text, values) if text.startswith("$") else text


def _value(
    source: Source, element: etree._Element, key: str, text: str, scope: Mapping[str, str]
) -> str:
    try:
        if text.startswith("${") and text.endswith("}"):
            return text_of(evaluate(text[2:-1], scope))
        name = text[1:]
        if name not in scope:
            raise ExpressionError(f"parameter ${name} is not declared")
        return scope[name]
    except ExpressionError as error:
        if key == "name" and text.startswith("${"):
            # A name is only a label: esmini keeps an expression it cannot compute as text.
            return text
        raise source.error(f"<{element.tag} {key}={text!r}>: {error}", element) from None
