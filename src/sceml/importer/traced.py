"""Numbers that came from a distributed `$parameter`, followed into the model's values.

`parameters.py` marks each attribute that was exactly `$name` of a parameter a distribution
varies; `number()` then reads it as a `Traced` float that remembers the parameter and the line.
A Traced number that ends up unchanged in a `scm.Value` is a place the parameter fills, so
`logical.py` can put the distribution there; arithmetic on it gives a plain float, so a derived
number (a rate computed from a time, a distance from a speed) is never mistaken for one.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

#: Attribute set on an element whose attributes use distributed parameters:
#: `attribute=parameter` pairs, space separated (namespaced; removed before any XML is kept).
TRACE = "{urn:sceml:import}traced"


class Traced(float):
    """A number read from a `$parameter` reference: which parameter, and where."""

    parameter: str
    line: int | None
    attribute: str

    def __new__(cls, number: float, parameter: str, line: int | None, attribute: str) -> Traced:
        made = super().__new__(cls, number)
        made.parameter, made.line, made.attribute = parameter, line, attribute
        return made

    def place(self) -> tuple[str, int | None, str]:
        """(parameter, line, attribute): one use of the parameter in the file."""
        return self.parameter, self.line, self.attribute


def mark(element: etree._Element, attribute: str, parameter: str) -> None:
    """Note that `attribute` of `element` was `$parameter` (before it is replaced)."""
    pairs = dict(_pairs(element))
    pairs[attribute] = parameter
    element.set(TRACE, " ".join(f"{k}={v}" for k, v in sorted(pairs.items())))


def _pairs(element: etree._Element) -> list[tuple[str, str]]:
    text = element.get(TRACE)
    if not text:
        return []
    return [(k, v) for k, _, v in (pair.partition("=") for pair in text.split())]


def read(element: etree._Element, attribute: str, number: float) -> float:
    """`number` (the attribute's value), Traced when the attribute was a distributed parameter."""
    parameter = dict(_pairs(element)).get(attribute)
    if parameter is None:
        return number
    return Traced(number, parameter, element.sourceline, attribute)


def value(number: float) -> scm.Value:
    """A Value holding `number`; a Traced number keeps its trace until `logical.py` reads it."""
    return scm.Value(value=number if isinstance(number, float) else float(number))
