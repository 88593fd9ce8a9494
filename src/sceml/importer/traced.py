"""Numbers that came from a distributed `$parameter`, followed into the model's values.

`parameters.py` marks each attribute that was exactly `$name` of a parameter a distribution
varies; `number()` then reads it as a `Traced` float that remembers the parameter and the line.
A Traced number that ends up unchanged in a `scm.Value` is a place the parameter fills, so
`logical.py` can put the distribution there; arithmetic on it gives a plain float, so a derived
number (a rate computed from a time, a distance from a speed) is never mistaken for one.

An attribute written as an affine expression of one distributed parameter (`${$Speed / 3.6}`)
is traced too, with its scale and shift (a `Link`): the distribution is carried through the
same line, so `sceml sample` draws what the file would have computed.
"""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree

import scemlmodel as scm

#: Attribute set on an element whose attributes use distributed parameters:
#: `attribute=parameter` pairs, space separated (namespaced; removed before any XML is kept).
TRACE = "{urn:sceml:import}traced"


@dataclass(frozen=True)
class Link:
    """A value that is `origin`'s value * scale + shift (a plain `$origin`: 1 and 0)."""

    origin: str
    scale: float = 1.0
    shift: float = 0.0

    def then(self, scale: float, shift: float) -> Link:
        """This link followed by `scale * x + shift`."""
        return Link(self.origin, scale * self.scale, scale * self.shift + shift)

    @property
    def is_plain(self) -> bool:
        return self.scale == 1.0 and self.shift == 0.0

    def text(self) -> str:
        """`$Speed`, or the line for a derived value: `$Speed * 0.277778`, `$Gap + 110`."""
        words = f"${self.origin}"
        if self.scale != 1.0:
            words += f" * {self.scale:.6g}"
        if self.shift:
            words += f" + {self.shift:.6g}" if self.shift > 0 else f" - {-self.shift:.6g}"
        return words


class Traced(float):
    """A number read from a `$parameter` reference: which parameter (and how), and where."""

    parameter: str
    line: int | None
    attribute: str
    link: Link

    def __new__(
        cls,
        number: float,
        parameter: str,
        line: int | None,
        attribute: str,
        link: Link | None = None,
    ) -> Traced:
        made = super().__new__(cls, number)
        made.parameter, made.line, made.attribute = parameter, line, attribute
        made.link = link if link is not None else Link(parameter)
        return made

    def place(self) -> tuple[str, int | None, str]:
        """(parameter, line, attribute): one use of the parameter in the file."""
        return self.parameter, self.line, self.attribute


def mark(element: etree._Element, attribute: str, link: Link) -> None:
    """Note that `attribute` of `element` was `link` of a parameter (before it is replaced)."""
    pairs = dict(_pairs(element))
    pairs[attribute] = link
    element.set(
        TRACE,
        " ".join(f"{k}={v.origin};{v.scale!r};{v.shift!r}" for k, v in sorted(pairs.items())),
    )


def _pairs(element: etree._Element) -> list[tuple[str, Link]]:
    text = element.get(TRACE)
    if not text:
        return []
    pairs = []
    for pair in text.split():
        key, _, held = pair.partition("=")
        origin, scale, shift = held.split(";")
        pairs.append((key, Link(origin, float(scale), float(shift))))
    return pairs


def read(element: etree._Element, attribute: str, number: float) -> float:
    """`number` (the attribute's value), Traced when the attribute was a distributed parameter."""
    link = dict(_pairs(element)).get(attribute)
    if link is None:
        return number
    return Traced(number, link.origin, element.sourceline, attribute, link)


def value(number: float) -> scm.Value:
    """A Value holding `number`; a Traced number keeps its trace until `logical.py` reads it."""
    return scm.Value(value=number if isinstance(number, float) else float(number))
