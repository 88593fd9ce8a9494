"""`sceml info FILE`: summarise a scenario or module library."""

from __future__ import annotations

import json
from dataclasses import asdict
from pathlib import Path

import click

from ..model.graph import NO_LEVEL_TEXT
from ..model.info import Summary, summarize
from ..model.loading import broken_references, load
from .common import SceMLCommand, allow_option, exit_if_broken, input_file


@click.command(cls=SceMLCommand)
@input_file()
@click.option("--json", "as_json", is_flag=True, help="Print the summary as JSON.")
@allow_option
def info(file: Path, as_json: bool, allow: tuple[Path, ...]) -> None:
    """Summarise FILE: its level, map, actors, node counts and module uses.

    FILE is a scenario or a module library (.xmi). Exits 1 when a cross-file reference (a module
    use's definition) cannot be resolved, after printing the summary.
    """
    document = load(file, allow=allow)
    summary = summarize(document.root)
    if as_json:
        click.echo(json.dumps(asdict(summary), indent=2))
    else:
        for text in _text(summary, file):
            click.echo(text)
    exit_if_broken(list(broken_references(document)))


def _text(summary: Summary, file: Path) -> list[str]:
    if summary.kind == "library":
        lines = [f"{file}: module library {summary.name!r}"]
        lines.append(f"  modules ({len(summary.modules)}): {', '.join(summary.modules)}")
        lines.append(f"  nodes: {_counts(summary.node_counts)}; flows: {summary.flows}")
        return lines
    lines = [f"{file}: scenario {summary.name!r}"]
    lines.append(f"  level: {summary.level or NO_LEVEL_TEXT}")
    lines.append(f"  map: {summary.map or '(none)'}")
    lines.append(f"  actors ({len(summary.actors)}):")
    for actor in summary.actors:
        lines.append(f"    {actor.name}: {actor.kind}{' (ego)' if actor.ego else ''}")
    lines.append(f"  nodes: {_counts(summary.node_counts)}; flows: {summary.flows}")
    lines.append(f"  module uses ({len(summary.uses)}):")
    for use in summary.uses:
        bound = ", ".join(f"{role}={actor}" for role, actor in use.bindings.items())
        lines.append(f"    {use.name}: {use.definition} from {use.source} [{bound}]")
    return lines


def _counts(counts: dict[str, int]) -> str:
    return ", ".join(f"{count} {kind}" for kind, count in counts.items())
