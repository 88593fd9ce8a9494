"""`sceml module ...`: list and show the modules of a library, and extract new ones from scenarios."""

from __future__ import annotations

import json
from dataclasses import asdict
from pathlib import Path

import click

from ..model.loading import load_library
from ..modules import extract_file, list_definitions, parse_role, show
from ..modules.library import DefinitionDetail, DefinitionSummary, ParameterInfo, Size
from .common import SceMLGroup, allow_option, output_file

_EXISTING_FILE = click.Path(exists=True, dir_okay=False, path_type=Path)


@click.group(cls=SceMLGroup)
def module() -> None:
    """Work with module libraries: list, show and extract reusable sub-scenarios."""


@module.command("list")
@click.argument("library", type=_EXISTING_FILE)
@click.option("--json", "as_json", is_flag=True, help="Print the definitions as JSON.")
@allow_option
def list_command(library: Path, as_json: bool, allow: tuple[Path, ...]) -> None:
    """List the module definitions of LIBRARY with their roles, parameters and size.

    Size counts the nodes inside a module (ports not counted), its flows, its sub-module uses and
    its nesting depth (1 for a module without sub-modules).
    """
    summaries = list_definitions(load_library(library, allow=allow).root)
    if as_json:
        click.echo(json.dumps([asdict(s) for s in summaries], indent=2))
        return
    click.echo(f"{library}: {_count(len(summaries), 'module')}")
    for summary in summaries:
        click.echo("")
        for line in _summary_lines(summary):
            click.echo(line)


@module.command("show")
@click.argument("library", type=_EXISTING_FILE)
@click.argument("name")
@click.option("--json", "as_json", is_flag=True, help="Print the definition as JSON.")
@allow_option
def show_command(library: Path, name: str, as_json: bool, allow: tuple[Path, ...]) -> None:
    """Show module NAME of LIBRARY: roles, parameters, nodes in flow order, flows and uses."""
    detail = show(load_library(library, allow=allow).root, name)
    if as_json:
        click.echo(json.dumps(asdict(detail), indent=2))
        return
    for line in _detail_lines(detail, library):
        click.echo(line)


@module.command("extract")
@click.argument("file", type=_EXISTING_FILE)
@click.option(
    "--nodes",
    "node_list",
    required=True,
    metavar="A,B,C",
    help="Comma-separated names of the scenario nodes to move into the module. They must form "
    "a part with one entry and one exit (see docs/modules.md).",
)
@click.option("--name", required=True, help="Name of the new module; must be new in LIB.")
@click.option(
    "--into",
    "library",
    required=True,
    type=click.Path(dir_okay=False, path_type=Path),
    metavar="LIB",
    help="Library file to add the module to; created if it does not exist.",
)
@output_file("Write the changed scenario here instead of over FILE.", required=False)
@click.option(
    "--role",
    "role_options",
    multiple=True,
    metavar="ACTOR=ROLE:KIND|KIND",
    help="Name the role an actor becomes and the actor kinds it accepts, e.g. "
    "'bike=crosser:TwoWheeler|Pedestrian'; ROLE or :KINDS may be left out. Default: a role "
    "named after the actor that accepts the actor's own kind. Repeat for several actors.",
)
@click.option(
    "--parametrize",
    is_flag=True,
    help="Turn every value the nodes hold into a module parameter (default: that value); the "
    "new use overrides each with the same value, so the scenario does not change.",
)
@allow_option
def extract_command(
    file: Path,
    node_list: str,
    name: str,
    library: Path,
    output: Path | None,
    role_options: tuple[str, ...],
    parametrize: bool,
    allow: tuple[Path, ...],
) -> None:
    """Move nodes of scenario FILE into a new module of LIB and use the module in their place.

    Each actor the nodes refer to becomes a role of the module; the new use binds it back to the
    actor. Both files are written only if both can be.
    """
    nodes = [n.strip() for n in node_list.split(",") if n.strip()]
    roles = dict(parse_role(option) for option in role_options)
    report = extract_file(
        file,
        nodes,
        name,
        library,
        output=output,
        roles=roles,
        parametrize=parametrize,
        allowed_roots=allow,
    )
    verb = "created" if report.created_library else "added to"
    click.echo(f"module {report.module!r} {verb} {report.library}")
    bound = ", ".join(f"{role}={actor}" for role, actor in report.roles.items())
    click.echo(f"  roles: {bound or 'none'}; parameters: {report.parameters}")
    click.echo(f"scenario {report.scenario}: nodes {', '.join(nodes)} replaced by {report.use}")


def _summary_lines(summary: DefinitionSummary) -> list[str]:
    lines = [summary.name + (f": {summary.description}" if summary.description else "")]
    roles = ", ".join(f"{r.name} ({'|'.join(r.kinds) or 'any kind'})" for r in summary.roles)
    lines.append(f"  roles: {roles or 'none'}")
    parameters = ", ".join(_parameter_text(p) for p in summary.parameters)
    lines.append(f"  parameters: {parameters or 'none'}")
    lines.append(f"  size: {_size_text(summary.size)}")
    return lines


def _parameter_text(parameter: ParameterInfo) -> str:
    if parameter.default is not None:
        return f"{parameter.name} = {parameter.default}"
    unit = f" [{parameter.unit}]" if parameter.unit else ""
    return f"{parameter.name}{unit} (no default)"


def _size_text(size: Size) -> str:
    depth = f"depth {size.depth}" if size.depth is not None else f"depth unknown: {size.problem}"
    counts = [_count(size.nodes, "node"), _count(size.flows, "flow"), _count(size.uses, "use")]
    return ", ".join([*counts, depth])


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}{'' if number == 1 else 's'}"


def _detail_lines(detail: DefinitionDetail, library: Path) -> list[str]:
    lines = [f"{detail.name} ({library})"]
    if detail.description:
        lines.append(f"  {detail.description}")
    lines.append("roles:")
    lines += [f"  {r.name}: {' | '.join(r.kinds) or 'any kind'}" for r in detail.roles] or [
        "  none"
    ]
    lines.append("parameters:")
    lines += [f"  {_parameter_text(p)}" for p in detail.parameters] or ["  none"]
    lines.append(f"size: {_size_text(detail.size)}")
    lines.append("nodes (in flow order):")
    width = max((len(node.name) for node in detail.nodes), default=0)
    for node in detail.nodes:
        kind = node.kind + (f" ({node.category})" if node.category else "")
        who = (node.actor or "") + (f" -> {node.target}" if node.target else "")
        settings = ", ".join(f"{key}={text}" for key, text in node.parameters.items())
        text = f"  {node.name.ljust(width)}  {kind}"
        text += f"  [{who}]" if who else ""
        text += f"  {settings}" if settings else ""
        lines.append(text)
    lines.append("flows:")
    lines += [f"  {source} -> {target}" for source, target in detail.flows] or ["  none"]
    lines.append("uses:")
    for use in detail.uses:
        bound = ", ".join(f"{role}={actor}" for role, actor in use.bindings.items())
        lines.append(f"  {use.name}: {use.definition} [{bound}]")
        for parameter, value in use.overrides.items():
            lines.append(f"    {parameter} = {value}")
    if not detail.uses:
        lines.append("  none")
    return lines
