"""Reading small configuration files (limits, ranges) safely: size, encoding, depth and aliases."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import LoadError
from .safefiles import read_input

if TYPE_CHECKING:
    import yaml

#: Configuration files (limits, ranges) are small; anything bigger is a mistake or an attack.
CONFIG_MAX_BYTES = 1024 * 1024


def read_config_text(path: str | Path, what: str, max_bytes: int = CONFIG_MAX_BYTES) -> str:
    """The UTF-8 text of a small configuration file; LoadError names the file and the problem."""
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > max_bytes:
            raise LoadError(f"{what} is {size} bytes, above the {max_bytes} byte limit", file=path)
        # The reading rule of every input: a regular file, the limit counted while reading.
        data = read_input(path, max_bytes=max_bytes, what=what)
    except OSError as error:
        raise LoadError(f"cannot read {what}: {error.strerror}", file=path) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data[: error.start].count(b"\n") + 1
        raise LoadError(f"{what} is not UTF-8 (byte {error.start})", file=path, line=line) from None


_TOML_LINE = re.compile(r"at line (\d+)")


def load_config(path: str | Path, what: str, max_bytes: int = CONFIG_MAX_BYTES) -> object:
    """Parse a small configuration file: TOML (.toml), JSON (.json), else YAML's safe subset.

    Whatever the parsers raise becomes a LoadError `malformed WHAT: reason` naming the file and,
    where the parser knows it, the line: also nesting deep enough to exhaust Python's stack (all
    three parsers recurse) and values Python refuses to build (an int of over 4300 digits, a
    YAML date such as 2026-13-01), which would otherwise escape as tracebacks.
    """
    path = Path(path)
    text = read_config_text(path, what, max_bytes)
    suffix = path.suffix.lower()
    malformed: tuple[type[Exception], ...] = (ValueError,)  # JSON's and TOML's errors
    try:
        if suffix == ".toml":
            import tomllib  # here, not with the module: every `sceml validate` imports it

            return tomllib.loads(text)
        if suffix == ".json":
            return json.loads(text)
        # PyYAML is imported here, not with the module: every `sceml validate` imports this
        # module and few read a YAML file (about 10 ms).
        import yaml

        malformed = (yaml.YAMLError, ValueError)
        return _safe_yaml(text)
    except RecursionError:
        raise LoadError(f"malformed {what}: nested too deeply", file=path) from None
    except malformed as error:
        raise LoadError(
            f"malformed {what}: {_config_error_reason(error)}",
            file=path,
            line=_config_error_line(error),
        ) from None


#: How many values YAML aliases may add to a configuration file once expanded.
ALIAS_EXPANSION_LIMIT = 100_000


def _safe_yaml(text: str) -> object:
    """yaml.safe_load, refusing documents whose aliases expand to a huge tree (alias bombs).

    PyYAML shares aliased objects instead of copying them, so loading is cheap; but whatever
    walks the result afterwards (checks, error messages that show a value) pays the expanded size.
    """
    import yaml

    loader = yaml.SafeLoader(text)
    try:
        node = loader.get_single_node()
        if node is None:
            return None
        distinct, expanded = _node_counts(node)
        if expanded - distinct > ALIAS_EXPANSION_LIMIT:
            raise ValueError(
                f"aliases expand {distinct} values to {expanded}, more than "
                f"{ALIAS_EXPANSION_LIMIT} extra (an alias bomb?)"
            )
        return loader.construct_document(node)
    finally:
        loader.dispose()


def _node_counts(root: yaml.Node) -> tuple[int, int]:
    """Distinct nodes of a composed YAML graph, and nodes of the tree it stands for.

    Iterative with memoised subtree sizes, so neither depth nor expansion costs more than the
    distinct nodes do.
    """
    import yaml

    sizes: dict[int, int] = {}
    entered: set[int] = set()
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    while stack:
        node, children_done = stack.pop()
        if isinstance(node, yaml.MappingNode):
            children = [item for pair in node.value for item in pair]
        elif isinstance(node, yaml.SequenceNode):
            children = list(node.value)
        else:
            children = []
        if children_done:
            sizes[id(node)] = 1 + sum(sizes.get(id(child), 0) for child in children)
        elif id(node) not in entered:
            entered.add(id(node))
            stack.append((node, True))
            stack.extend((child, False) for child in children if id(child) not in entered)
    return len(entered), sizes[id(root)]


def _config_error_reason(error: Exception) -> str:
    # PyYAML's str() spans several lines with a source excerpt; its `problem` is the gist.
    problem = getattr(error, "problem", None)
    if isinstance(error, json.JSONDecodeError):
        return error.msg
    text = str(problem) if problem else str(error).strip()
    return (text.splitlines() or [type(error).__name__])[0]


def _config_error_line(error: Exception) -> int | None:
    if isinstance(error, json.JSONDecodeError):
        return error.lineno
    mark = getattr(error, "problem_mark", None) or getattr(error, "context_mark", None)
    if mark is not None:
        return int(mark.line) + 1
    tomllib = sys.modules.get("tomllib")  # imported if a TOML file was read
    from_toml = tomllib is not None and isinstance(error, tomllib.TOMLDecodeError)
    found = _TOML_LINE.search(str(error)) if from_toml else None
    return int(found.group(1)) if found else None
