"""`sceml edit`: its help, its usage errors, and the run that writes a recovery copy."""

from __future__ import annotations

import re
import socket
from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.editor import EditorSession
from sceml.editor import server as server_module


def test_help_names_the_options() -> None:
    result = CliRunner().invoke(cli, ["edit", "--help"])
    assert result.exit_code == 0
    for option in ("--port", "--no-browser", "--read-only", "--level", "--library"):
        assert option in result.output


def test_usage_errors_exit_2(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["edit", str(tmp_path / "a.xmi"), "--level", "vague"])
    assert result.exit_code == 2
    result = CliRunner().invoke(cli, ["edit", str(tmp_path / "a.xmi"), "--port", "0"])
    assert result.exit_code == 2


def test_unreadable_file_exits_2(tmp_path: Path) -> None:
    broken = tmp_path / "broken.xmi"
    broken.write_text("<nope", encoding="utf-8")
    result = CliRunner().invoke(cli, ["edit", str(broken), "--no-browser"])
    assert result.exit_code == 2 and "malformed" in result.output


def test_a_run_prints_the_url_and_keeps_unsaved_work(
    examples_copy: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    sessions: list[EditorSession] = []
    original_init = EditorSession.__init__

    def remember(self: EditorSession, *args: object, **kwargs: object) -> None:
        original_init(self, *args, **kwargs)  # type: ignore[arg-type]
        sessions.append(self)

    def run(self: object, sockets: object = None) -> None:
        # Stands for a user who edits and then presses Ctrl-C without saving.
        sessions[0].apply([{"op": "add_node", "kind": "Stop"}])

    monkeypatch.setattr(EditorSession, "__init__", remember)
    monkeypatch.setattr(server_module.uvicorn.Server, "run", run)
    target = examples_copy / "uis1-concrete.xmi"
    result = CliRunner().invoke(cli, ["edit", str(target), "--no-browser"])
    assert result.exit_code == 0, result.output
    assert re.search(r"http://127\.0\.0\.1:\d+/", result.output)
    recovered = examples_copy / ".uis1-concrete.recovered.xmi"
    assert recovered.exists() and str(recovered) in result.output
    assert b"Stop_1" in recovered.read_bytes() and b"Stop_1" not in target.read_bytes()


def test_a_new_file_in_a_missing_folder_is_refused_before_any_drawing(tmp_path: Path) -> None:
    result = CliRunner().invoke(cli, ["edit", str(tmp_path / "nowhere" / "a.xmi"), "--no-browser"])
    assert result.exit_code == 2 and "does not exist" in result.output
    result = CliRunner().invoke(cli, ["edit", str(tmp_path / "a.xmi"), "--read-only"])
    assert result.exit_code == 2 and "nothing to review" in result.output
    assert list(tmp_path.iterdir()) == []


def test_a_busy_port_is_a_usage_error(examples_copy: Path) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        target = examples_copy / "uis1-concrete.xmi"
        args = ["edit", str(target), "--no-browser", "--port", str(port)]
        result = CliRunner().invoke(cli, args)
    assert result.exit_code == 2
    assert f"port {port} on 127.0.0.1 is in use" in result.output
    assert "http://" not in result.output  # nothing announced that would not answer
