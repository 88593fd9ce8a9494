"""What the display texts of values cost the editor's view: listing a scenario with and without them.

    python benchmarks/view_texts.py [--nodes 500] [--rounds 16]

The view sends each parameter, position and module parameter with its display text
(sceml.editor.values: `value_text`, `default_text`, `position_text`). This lists every node of a
scenario of about `--nodes` nodes (benchmarks/scale_scenarios.py), as the view does when nothing
is cached (a file opened), in alternating rounds: with the texts, and, as the anchor, with the
text functions replaced by ones that return nothing. Prints the medians and their ratio.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from scale_scenarios import write

from sceml.editor import EditorSession, fields, view

#: Where the listing looks the text functions up, and their names.
_TEXTS = {
    fields: ("value_text", "default_text", "position_text"),
    view: ("value_text", "default_text"),
}


@contextmanager
def without_texts() -> Iterator[None]:
    """The listing with every display text left out (None)."""
    saved = {
        (module, name): getattr(module, name) for module, names in _TEXTS.items() for name in names
    }

    def nothing(*_: object) -> None:
        return None

    for module, name in saved:
        setattr(module, name, nothing)
    try:
        yield
    finally:
        for (module, name), function in saved.items():
            setattr(module, name, function)


def listing_ms(session: EditorSession) -> float:
    """Milliseconds to list every node and edge of the session's graph, nothing cached."""
    assert session.document is not None
    started = time.perf_counter()
    view.Lister(session.ids, session.document.path.parent).graph(session.graph)
    return (time.perf_counter() - started) * 1000


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nodes", type=int, default=500)
    parser.add_argument("--rounds", type=int, default=16)
    arguments = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as temporary:
        session = EditorSession()
        session.open(write(arguments.nodes, Path(temporary)))
        runs: dict[str, list[float]] = {"with texts": [], "anchor: without texts": []}
        measure: dict[str, Callable[[], float]] = {
            "with texts": lambda: listing_ms(session),
            "anchor: without texts": lambda: _without(session),
        }
        for name in measure:  # warm-up
            measure[name]()
        for round_number in range(arguments.rounds):
            order = list(measure) if round_number % 2 == 0 else list(reversed(measure))
            for name in order:
                runs[name].append(measure[name]())
    medians = {name: statistics.median(times) for name, times in runs.items()}
    for name, value in medians.items():
        sys.stdout.write(f"{name:>22}: {value:7.1f} ms (median of {arguments.rounds})\n")
    ratio = medians["with texts"] / medians["anchor: without texts"]
    sys.stdout.write(f"{'ratio':>22}: {ratio:7.2f}\n")


def _without(session: EditorSession) -> float:
    with without_texts():
        return listing_ms(session)


if __name__ == "__main__":
    main()
