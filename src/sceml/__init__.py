"""SceML: graph-based, modular driving scenarios, validated and exported to OpenSCENARIO."""

from __future__ import annotations

from functools import cache


@cache
def package_version() -> str:
    """The installed version; read on demand (importlib.metadata costs ~30 ms at start-up)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("sceml")
    except PackageNotFoundError:  # running from a source tree without an install
        return "0.0.0+unknown"


def __getattr__(name: str) -> str:
    if name == "__version__":
        return package_version()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
