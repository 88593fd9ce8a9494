"""The one Jinja environment for every template in `sceml.templates` (export and report alike)."""

from __future__ import annotations

import contextlib
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
        bytecode_cache=bytecode_cache(),
    )


def template(name: str) -> jinja2.Template:
    """A template of `sceml.templates` by file name, e.g. `report.html.j2`."""
    return environment().get_template(name)


def bytecode_cache(directory: str | None = None) -> jinja2.BytecodeCache | None:
    """Compiled templates kept between processes, or None where no cache folder can be had.

    Compiling the export template costs every process (each sampling worker, each `simulate`)
    30-80 ms; loading it compiled costs under 1 ms. Jinja's own file cache keys each entry by
    the template's name and checks the source's checksum and the Python version, so a changed
    template is compiled again. Without `directory` it is Jinja's default folder, which Jinja
    makes for the user alone (mode 0700, owner checked) in the temporary folder, as Python
    keeps its own bytecode beside the sources.
    """
    try:
        return _Cache(directory)
    except (OSError, RuntimeError):  # no temporary folder, or one another user owns
        return None


class _Cache(jinja2.FileSystemBytecodeCache):
    """Jinja's file cache, except that a cache entry that cannot be written fails nothing."""

    def dump_bytecode(self, bucket: jinja2.bccache.Bucket) -> None:
        # A full or read-only disk: the template was compiled, only not kept.
        with contextlib.suppress(OSError):
            super().dump_bytecode(bucket)
