"""Reading a request's JSON body within bounds: size, nesting depth, and text that files can hold.

A page on the user's machine (or a buggy one) may post anything to 127.0.0.1. Every body is read
under a byte limit while it arrives (not by the length the request claims), parsed by the
standard json module, and then walked once, without recursion, for its depth and its strings, so
that no later step meets a RecursionError, a 200 MB document or a lone surrogate.
"""

from __future__ import annotations

import json
from collections.abc import AsyncIterator
from typing import Any

from .errors import EditorError

#: The largest body accepted. The largest real request, a move of every node of a 5,000-node
#: scenario, is about 0.3 MB.
MAX_BODY_BYTES = 4 * 1024 * 1024
#: The deepest nesting accepted. The deepest real request (a waypoint's world position in an
#: op list) is 7 levels deep.
MAX_DEPTH = 32


class BodyTooLarge(EditorError):
    """A body over MAX_BODY_BYTES."""

    status = 413


class BadBody(EditorError):
    """A body that is not a JSON object the protocol can use."""

    status = 400


async def read_limited(chunks: AsyncIterator[bytes], declared: str | None) -> bytes:
    """The body's bytes, refused as soon as it is known to exceed MAX_BODY_BYTES."""
    if declared is not None and declared.isdigit() and int(declared) > MAX_BODY_BYTES:
        raise BodyTooLarge(_too_large())
    received = bytearray()
    async for chunk in chunks:
        received += chunk
        if len(received) > MAX_BODY_BYTES:
            raise BodyTooLarge(_too_large())
    return bytes(received)


def _too_large() -> str:
    return f"the request body is larger than {MAX_BODY_BYTES // (1024 * 1024)} MiB"


def parse_object(raw: bytes) -> dict[str, Any]:
    """The JSON object in `raw` (empty: {}), checked by `check_nesting_and_text`."""
    if not raw.strip():
        return {}
    try:
        body = json.loads(raw)
    except RecursionError:
        raise BadBody(_too_deep()) from None
    except ValueError as error:
        raise BadBody(f"the request body is not JSON ({error})") from None
    check_nesting_and_text(body)
    if not isinstance(body, dict):
        raise BadBody("the request body must be a JSON object")
    return body


def _too_deep() -> str:
    return f"the request body is nested more than {MAX_DEPTH} levels deep"


def check_nesting_and_text(body: object) -> None:
    """BadBody if `body` nests deeper than MAX_DEPTH or holds a string no file could hold."""
    pending: list[tuple[object, int]] = [(body, 1)]
    while pending:
        value, depth = pending.pop()
        if isinstance(value, str):
            _check_text(value)
            continue
        if not isinstance(value, dict | list):
            continue
        if depth > MAX_DEPTH:
            raise BadBody(_too_deep())
        items = list(value.items()) if isinstance(value, dict) else [(None, v) for v in value]
        for key, item in items:
            if key is not None:
                _check_text(key)
            pending.append((item, depth + 1))


def _check_text(text: str) -> None:
    # JSON may carry "\ud800", a half of a UTF-16 pair that UTF-8 (and so XMI) cannot encode.
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as error:
        bad = text[error.start]
        raise BadBody(
            f"the text {_excerpt(text)!r} holds a lone surrogate (U+{ord(bad):04X}), "
            "which no file can store"
        ) from None
    if "\x00" in text:
        raise BadBody(f"the text {_excerpt(text)!r} holds a NUL character")


def _excerpt(text: str) -> str:
    shown = text.encode("utf-8", "backslashreplace").decode("ascii", "backslashreplace")
    return shown if len(shown) <= 40 else shown[:37] + "..."
