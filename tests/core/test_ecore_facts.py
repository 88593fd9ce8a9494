"""The catalog's facts come from a generated module; it must say what the .ecore says."""

from __future__ import annotations

from pathlib import Path

from sceml.model import catalog
from sceml.model.ecore_facts import facts_module, read_facts
from scemlmodel._catalog_facts import CLASSES

ECORE = Path(__file__).resolve().parents[2] / "metamodel" / "scemlmodel.ecore"


def test_the_generated_facts_are_a_fresh_reading_of_the_ecore() -> None:
    assert read_facts(ECORE.read_bytes()) == CLASSES
    assert list(CLASSES) == list(read_facts(ECORE.read_bytes()))  # file order too


def test_the_module_text_reads_back_as_the_same_facts() -> None:
    facts = read_facts(ECORE.read_bytes())
    namespace: dict[str, object] = {}
    exec(compile(facts_module(facts), "facts", "exec"), namespace)
    assert namespace["CLASSES"] == facts


def test_facts_name_classes_features_and_annotations_as_written() -> None:
    # Checked by hand against metamodel/scemlmodel.ecore.
    facts = read_facts(ECORE.read_bytes())
    abstract, supertypes, annotations, features = facts["Scenario"]
    assert (abstract, supertypes) == (False, ("Graph",))
    assert facts["Graph"][0] is True
    assert ("nodes", "GraphElement", {}) in facts["Graph"][3]
    assert facts["NamedElement"][3] == (("name", "", {}),)


def test_the_catalog_reads_every_class_of_the_generated_facts() -> None:
    classes = catalog._ecore_classes()
    assert list(classes) == list(CLASSES)
    assert classes["Scenario"].supertypes == ("Graph",)
    assert [f.name for f in classes["Graph"].features] == ["nodes", "flows"]
