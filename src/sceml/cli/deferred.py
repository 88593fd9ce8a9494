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

pyecore's `pyecore.ecore` also takes `compile_restricted` and `safe_builtins` from
RestrictedPython at its top (`from RestrictedPython import ...`), for the bodies of EOperations
added to a dynamic EClass; SceML's metamodel has none. Names taken that way are looked up at
once, so such a module is deferred with stand-ins for them (about 6 ms CPU of every command
that loads a model): a function that runs the module and then calls the module's own, and a dict
that is filled with the module's own contents before that call returns (pyecore compiles with
the one before it runs the code with the other).
"""

from __future__ import annotations

import importlib.util
import sys
import threading
import types
from collections.abc import Callable
from typing import Any

#: The modules deferred, each imported at the top of a library for a path SceML does not take,
#: with the functions and the dicts that library takes from it by name (served by stand-ins).
DEFERRED: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "urllib.request": ((), ()),
    "RestrictedPython": (("compile_restricted",), ("safe_builtins",)),
}

_LOADING = threading.Lock()


def defer_unused_imports() -> None:
    """Make each of DEFERRED load on first use, unless it is already imported."""
    for name, (functions, dicts) in DEFERRED.items():
        defer(name, functions, dicts)


def defer(name: str, functions: tuple[str, ...] = (), dicts: tuple[str, ...] = ()) -> None:
    """Put `name` in sys.modules (and on its parent package) as a module that loads when used,
    with stand-ins for `functions` and `dicts` (see the module's docstring)."""
    if name in sys.modules:
        return
    spec = importlib.util.find_spec(name)
    if spec is None or spec.loader is None:
        return  # not there: the ordinary import will say so where it is needed
    module = importlib.util.module_from_spec(spec)
    module.__class__ = _Deferred
    stand_in_dicts: dict[str, dict[Any, Any]] = {attribute: {} for attribute in dicts}
    for attribute, stand_in in stand_in_dicts.items():
        setattr(module, attribute, stand_in)
    for attribute in functions:
        setattr(module, attribute, _stand_in_function(module, attribute, stand_in_dicts))
    sys.modules[name] = module
    parent, _, child = name.rpartition(".")
    if parent:
        setattr(sys.modules[parent], child, module)


def _stand_in_function(
    module: types.ModuleType, attribute: str, dicts: dict[str, dict[Any, Any]]
) -> Callable[..., Any]:
    """A function that runs the deferred module, fills the stand-in dicts with the module's own,
    and calls the module's own function of that name."""

    def stand_in(*args: Any, **kwargs: Any) -> Any:
        _run(module)
        for name, stand_in_dict in dicts.items():
            real = getattr(module, name)
            if real is not stand_in_dict and not stand_in_dict:
                stand_in_dict.update(real)
        return getattr(module, attribute)(*args, **kwargs)

    stand_in.__name__ = stand_in.__qualname__ = attribute
    return stand_in


def _run(module: types.ModuleType) -> None:
    """Run a deferred module's code in its own module object, once."""
    with _LOADING:  # two threads' first look-ups run the code once
        if type(module) is _Deferred:
            module.__spec__.loader.exec_module(module)  # type: ignore[union-attr]
            module.__class__ = types.ModuleType  # type: ignore[assignment]


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
        _run(self)
        return getattr(self, attribute)
