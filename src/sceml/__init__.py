"""SceML: graph-based, modular driving scenarios, validated and exported to OpenSCENARIO."""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("sceml")
except PackageNotFoundError:  # running from a source tree without an install
    __version__ = "0.0.0+unknown"
