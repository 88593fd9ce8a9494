"""Standard-library modules that a library imports at its top for a path SceML never takes, loaded
on first use instead of at every command's start.

pyecore's `pyecore.resources.resource` imports `urllib.request` at its top for one line: opening
an `http://` URI (`HttpURI.getreadstream`). SceML reads and writes local files only, yet every
command that loads a model paid for `urllib.request` with `http.client`, `email`, `ssl`,
`hashlib` and `socket`: about 29 ms CPU, as much as `python -c pass` (benchmarks/startup.py).

A deferred module is put in `sys.modules` with its spec, name and file but without its code run;
the first look-up of anything else in it (`urllib.request.urlopen`, `from urllib.request import
x`) runs the code in that same module object, so whoever holds it sees the ordinary module.
pyecore itself is not changed. The standard library's `importlib.util.LazyLoader` cannot do
this on Python 3.11: the `import urllib.request` statement itself reads the module's `__spec__`
(`_find_and_load`), which makes LazyLoader run the code at once. Only the console script defers
(`sceml.cli.main`, before any command is imported): a program that imports `sceml` as a library
gets the ordinary imports.
"""

from __future__ import annotations

import importlib.util
import sys
import threading
import types
from typing import Any

#: The modules deferred, each imported at the top of a library for a path SceML does not take.
DEFERRED = ("urllib.request",)

_LOADING = threading.Lock()


def defer_unused_imports() -> None:
    """Make each of DEFERRED load on first use, unless it is already imported."""
    for name in DEFERRED:
        defer(name)


def defer(name: str) -> None:
    """Put `name` in sys.modules (and on its parent package) as a module that loads when used."""
    if name in sys.modules:
        return
    spec = importlib.util.find_spec(name)
    if spec is None or spec.loader is None:
        return  # not there: the ordinary import will say so where it is needed
    module = importlib.util.module_from_spec(spec)
    module.__class__ = _Deferred
    sys.modules[name] = module
    parent, _, child = name.rpartition(".")
    if parent:
        setattr(sys.modules[parent], child, module)


class _Deferred(types.ModuleType):
    """A module whose code runs when something not yet in it is looked up.

    Python calls `__getattr__` only for a name the module does not have: its spec, name, loader
    and file are there from the start, so the import machinery's own look-ups do not load it.
    Names with double underscores that are missing (`__path__`: this is not a package) stay
    missing rather than loading it.
    """

    def __getattr__(self, attribute: str) -> Any:
        if attribute.startswith("__") and attribute.endswith("__"):
            raise AttributeError(attribute)
        with _LOADING:  # two threads' first look-ups run the code once
            if type(self) is _Deferred:
                self.__spec__.loader.exec_module(self)  # type: ignore[union-attr]
                self.__class__ = types.ModuleType  # type: ignore[assignment]
        return getattr(self, attribute)
