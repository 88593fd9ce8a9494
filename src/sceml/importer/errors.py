"""The one error type of `sceml import`: input that cannot be used, with file and line."""

from __future__ import annotations

from lxml import etree

from ..errors import SceMLError


class XoscImportError(SceMLError):
    """An OpenSCENARIO file cannot be imported (malformed, wrong version, dangling or circular
    reference, missing catalog); nothing is written. Exit code 2: the input is unusable."""

    exit_code = 2


class BadValue(Exception):  # noqa: N818 - not a ValueError on purpose: never read as "absent"
    """A number in the input that no model can hold (NaN, infinite, a lane id beyond 32 bits).

    Raised where the value is read, which knows the element but not the file; `import_file`
    turns it into an XoscImportError with the file and line. It is no ValueError, so the
    readers that take a ValueError to mean "not this kind of position" do not swallow it.
    """

    def __init__(self, message: str, element: etree._Element) -> None:
        super().__init__(message)
        self.element = element
