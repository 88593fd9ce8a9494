"""The one Jinja environment for every template in `sceml.templates` (export and report alike)."""

from __future__ import annotations

from functools import cache

import jinja2


@cache
def environment() -> jinja2.Environment:
    """Jinja with StrictUndefined and autoescaping, compiled once per process.

    Templates stay declarative: callers hand them a view model in which every decision is
    already made, so the environment carries no filters or globals of its own.
    """
    return jinja2.Environment(
        loader=jinja2.PackageLoader("sceml.templates", "."),
        undefined=jinja2.StrictUndefined,
        autoescape=True,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=False,
    )


def template(name: str) -> jinja2.Template:
    """A template of `sceml.templates` by file name, e.g. `report.html.j2`."""
    return environment().get_template(name)
