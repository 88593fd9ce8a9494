"""Every open page of one server hears of every change: a Server-Sent Events stream.

A page subscribes to `/api/events`; after each change the server sends one `change` event with
the new view version and the tab that made it. A page that did not make the change fetches the
view again (with its own undo and redo labels). Events are tiny and the view is fetched once per
change per page, so a page that was asleep catches up with one request.
"""

from __future__ import annotations

import asyncio
import json
from collections.abc import AsyncIterator
from typing import Any

#: Seconds between comments on an idle stream, so proxies and the browser keep it open.
KEEP_ALIVE = 15.0


class Broadcaster:
    """Fans change events out to the streams of all open pages (used on the event loop only)."""

    def __init__(self) -> None:
        self._queues: set[asyncio.Queue[str | None]] = set()
        self.closed = False

    @property
    def listeners(self) -> int:
        """How many pages are subscribed."""
        return len(self._queues)

    def publish(self, event: dict[str, Any]) -> None:
        """Send `event` to every subscribed page."""
        text = json.dumps(event)
        for queue in self._queues:
            queue.put_nowait(text)

    def close(self) -> None:
        """End every stream (the server is stopping; streams would hold the shutdown up)."""
        self.closed = True
        for queue in self._queues:
            queue.put_nowait(None)

    async def stream(self, first: dict[str, Any]) -> AsyncIterator[str]:
        """One page's stream: `first` as a `hello` event, then every change until closed."""
        queue: asyncio.Queue[str | None] = asyncio.Queue()
        self._queues.add(queue)
        try:
            # retry: how soon the browser reconnects after a restart of the server.
            yield f"retry: 1000\nevent: hello\ndata: {json.dumps(first)}\n\n"
            while not self.closed:
                try:
                    item = await asyncio.wait_for(queue.get(), timeout=KEEP_ALIVE)
                except TimeoutError:
                    yield ": still here\n\n"
                    continue
                if item is None:
                    return
                yield f"event: change\ndata: {item}\n\n"
        finally:
            self._queues.discard(queue)
