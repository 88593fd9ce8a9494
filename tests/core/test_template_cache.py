"""Compiled templates are kept between processes, and the cache can never fail a command."""

from __future__ import annotations

import os
from pathlib import Path

import jinja2
import pytest

from sceml.templating import bytecode_cache, environment

SOURCE = "{% for x in items %}<li>{{ x }}</li>{% endfor %}"


def _environment(cache: jinja2.BytecodeCache | None, source: str = SOURCE) -> jinja2.Environment:
    """A fresh environment (as a new process has) over one template, `t.html`."""
    return jinja2.Environment(
        loader=jinja2.DictLoader({"t.html": source}), autoescape=True, bytecode_cache=cache
    )


def test_a_second_environment_loads_the_compiled_template_instead_of_compiling(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    first = _environment(bytecode_cache(str(tmp_path))).get_template("t.html")
    assert len(list(tmp_path.iterdir())) == 1
    monkeypatch.setattr(jinja2.Environment, "compile", _refuse)
    again = _environment(bytecode_cache(str(tmp_path))).get_template("t.html")
    assert again is not first
    assert again.render(items=["a", "<b>"]) == "<li>a</li><li>&lt;b&gt;</li>"


def test_a_changed_template_is_compiled_again(tmp_path: Path) -> None:
    _environment(bytecode_cache(str(tmp_path))).get_template("t.html")
    # Same name, so the same cache entry, whose checksum no longer matches the source.
    changed = _environment(bytecode_cache(str(tmp_path)), SOURCE + "!").get_template("t.html")
    assert changed.render(items=["a"]) == "<li>a</li>!"


def test_a_cache_that_cannot_be_written_fails_nothing(tmp_path: Path) -> None:
    missing = tmp_path / "gone"  # the folder went away after the cache was set up
    template = _environment(bytecode_cache(str(missing))).get_template("t.html")
    assert template.render(items=["a"]) == "<li>a</li>"
    assert not missing.exists()


def test_the_project_environment_keeps_its_templates_in_the_users_own_folder() -> None:
    cache = environment().bytecode_cache
    assert isinstance(cache, jinja2.FileSystemBytecodeCache)
    status = os.stat(cache.directory)
    assert status.st_uid == os.getuid()
    assert status.st_mode & 0o777 == 0o700


def _refuse(*args: object, **kwargs: object) -> None:
    raise AssertionError("compiled although the cache holds it")
