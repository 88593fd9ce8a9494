"""Parameter declarations and `$name` / `${expression}` values, resolved in place, by scope.

A ParameterDeclarations element declares for its parent and everything below it; a declaration
may use the ones declared before it. Every attribute that starts with `$` is replaced by its
value, so later stages only see literals (the import report lists the parameters used).
"""

from __future__ import annotations

from collections.abc import Mapping

from lxml import etree

from .expressions import ExpressionError, evaluate, text_of
from .reading import Source


def resolve(source: Source) -> dict[str, str]:
    """Replace every parameter reference in the tree; returns the top-level declarations."""
    top: dict[str, str] = {}
    _resolve(source, source.root, {}, top)
    return top


def _resolve(
    source: Source, element: etree._Element, scope: Mapping[str, str], top: dict[str, str]
) -> None:
    declarations = element.find("ParameterDeclarations")
    if declarations is not None:
        inner = dict(scope)
        for declaration in declarations.iterchildren("ParameterDeclaration"):
            _substitute(source, declaration, inner)
            inner[str(declaration.get("name"))] = str(declaration.get("value", ""))
        if element is source.root:
            top.update(inner)
        scope = inner
    _substitute(source, element, scope)
    for child in element:
        if isinstance(child.tag, str) and child is not declarations:
            _resolve(source, child, scope, top)


def _substitute(source: Source, element: etree._Element, scope: Mapping[str, str]) -> None:
    for key, value in element.attrib.items():
        if value.startswith("$"):
            element.set(key, _value(source, element, key, value, scope))


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
        raise source.error(f"<{element.tag} {key}={text!r}>: {error}", element) from None
