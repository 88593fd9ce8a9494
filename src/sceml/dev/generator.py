"""pyecoregen's generator with SceML's one change: features made by `_static_features`.

The generated module is pyecoregen's, but for how a class's EAttributes and EReferences are
made: `_attribute(...)` and `_reference(...)` from `_static_features.py` (a copy of
sceml.dev.static_features written beside it), the same objects at a quarter of the cost of
pyecore's constructors (that module says why and how). Everything else is pyecoregen's own
templates, read from the installed, pinned pyecoregen: the loader below changes only the two
constructor calls and adds the import, and refuses to generate if those texts are not where
it expects them (a new pyecoregen), rather than generate something else.
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import jinja2
from pyecoregen.ecore import EcoreGenerator

#: The helper module, as the generated package names it.
HELPER = "_static_features.py"

#: Template -> (text in pyecoregen's template, what it becomes).
_CHANGES = {
    "module_utilities.tpl": (
        ("= EAttribute(", "= _attribute("),
        ("= EReference(", "= _reference("),
    ),
    "module.py.tpl": (
        (
            "from pyecore.ecore import *\n",
            "from pyecore.ecore import *\n"
            "from ._static_features import attribute as _attribute, reference as _reference\n",
        ),
    ),
}


class _ChangingLoader(jinja2.FileSystemLoader):
    """pyecoregen's templates, with the changes of _CHANGES made to their text."""

    def get_source(self, environment: jinja2.Environment, template: str) -> Any:
        source, filename, uptodate = super().get_source(environment, template)
        for old, new in _CHANGES.get(template, ()):
            if source.count(old) != 1:
                raise RuntimeError(f"pyecoregen's {template} has changed: {old!r} not found once")
            source = source.replace(old, new)
        return source, filename, uptodate


class StaticFeaturesGenerator(EcoreGenerator):  # type: ignore[misc]
    """EcoreGenerator whose modules make their features with `_static_features`."""

    def create_environment(self, **kwargs: Any) -> jinja2.Environment:
        environment: jinja2.Environment = super().create_environment(**kwargs)
        environment.loader = _ChangingLoader(self.templates_path)
        return environment

    def generate(self, model: Any, outfolder: str, **kwargs: Any) -> None:
        super().generate(model, outfolder, **kwargs)
        helper = Path(__file__).with_name("static_features.py")
        shutil.copyfile(helper, Path(outfolder) / str(model.name) / HELPER)
