"""Writes the corpus of hostile and broken input files, and its MANIFEST, into tests/hostile/corpus.

Most cases are small edits of the shipped examples, so each one differs from a good file in
exactly one way. Run it after changing a case; `--check` exits 1 when the committed corpus is
stale. The 100 MB case is not here: the tests make it in a temporary folder.

MANIFEST: one case per line, `FILE<TAB>COMMAND<TAB>EXIT<TAB>TEXT`; the command (`info` or
`check-xosc`) run on FILE must exit with EXIT and print TEXT.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
EXAMPLES = HERE.parents[1] / "examples"

XML_HEAD = '<?xml version="1.0" encoding="UTF-8"?>\n'
NS = (
    'xmlns:xmi="http://www.omg.org/XMI" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
    'xmlns:scemlmodel="https://sceml.org/metamodel/1.0" xmi:version="2.0"'
)


@dataclass(frozen=True)
class Case:
    """One hostile file and what the CLI must answer."""

    name: str
    content: bytes
    command: str
    exit_code: int
    expected: str


def _example(name: str) -> str:
    return (EXAMPLES / name).read_text(encoding="utf-8")


def _replace_once(text: str, old: str, new: str) -> str:
    if text.count(old) < 1:
        raise ValueError(f"{old!r} not found")
    return text.replace(old, new, 1)


def _uis1(old: str, new: str) -> bytes:
    return _replace_once(_example("uis1-concrete.xmi"), old, new).encode()


def _uis2(old: str, new: str) -> bytes:
    return _replace_once(_example("uis2-concrete.xmi"), old, new).encode()


def _library(old: str, new: str) -> bytes:
    return _replace_once(_example("library/sceml-library.xmi"), old, new).encode()


def _billion_laughs(root: str) -> bytes:
    entities = "".join(f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10}">\n' for i in range(1, 10))
    return (
        f'{XML_HEAD}<!DOCTYPE {root} [\n<!ENTITY lol0 "lol">\n{entities}]>\n'
        f"<{root}>&lol9;</{root}>\n"
    ).encode()


def _external_entity(root: str, system_id: str) -> bytes:
    return (
        f'{XML_HEAD}<!DOCTYPE {root} [\n<!ENTITY xxe SYSTEM "{system_id}">\n]>\n'
        f"<{root}>&xxe;</{root}>\n"
    ).encode()


def _scenario_with_nodes(body: str) -> bytes:
    return f"{XML_HEAD}<scemlmodel:Scenario {NS}>\n{body}</scemlmodel:Scenario>\n".encode()


def _self_using_library(name: str, href: str) -> bytes:
    return (
        f'{XML_HEAD}<scemlmodel:Library {NS} name="{name}">\n'
        f'  <modules xsi:type="scemlmodel:ModuleDefinition" name="{name}Module">\n'
        '    <nodes xsi:type="scemlmodel:InPort" name="In"/>\n'
        '    <nodes xsi:type="scemlmodel:OutPort" name="Out"/>\n'
        '    <nodes xsi:type="scemlmodel:ModuleUse" name="Again">\n'
        f'      <definition href="{href}"/>\n'
        "    </nodes>\n"
        '    <flows source="//@modules.0/@nodes.0" target="//@modules.0/@nodes.2"/>\n'
        '    <flows source="//@modules.0/@nodes.2" target="//@modules.0/@nodes.1"/>\n'
        "  </modules>\n"
        "</scemlmodel:Library>\n"
    ).encode()


def _scenario_using(href: str) -> bytes:
    return _scenario_with_nodes(
        '  <nodes xsi:type="scemlmodel:RootNode" name="Root" scenarioName="Loop"/>\n'
        '  <nodes xsi:type="scemlmodel:EndNode" name="End"/>\n'
        '  <nodes xsi:type="scemlmodel:ModuleUse" name="Use">\n'
        f'    <definition href="{href}"/>\n'
        "  </nodes>\n"
        '  <flows source="//@nodes.0" target="//@nodes.2"/>\n'
        '  <flows source="//@nodes.2" target="//@nodes.1"/>\n'
    )


def _deep(depth: int) -> bytes:
    return _scenario_with_nodes("<nodes>" * depth + "</nodes>" * depth + "\n")


def _truncated() -> bytes:
    data = (EXAMPLES / "uis1-concrete.xmi").read_bytes()
    return data[: len(data) // 2]


def _xml_cases() -> list[Case]:
    use_href = 'href="library/sceml-library.xmi#CrossingManeuver"'
    return [
        Case("billion_laughs.xmi", _billion_laughs("x"), "info", 2, "DTDs and entity"),
        Case("xxe_file.xmi", _external_entity("x", "file:///etc/passwd"), "info", 2, "DTDs"),
        Case("xxe_network.xmi", _external_entity("x", "http://192.0.2.1/x"), "info", 2, "DTDs"),
        Case("truncated.xmi", _truncated(), "info", 2, "malformed XML"),
        Case(
            "invalid_utf8.xmi",
            _uis1('name="ego"', 'name="eg\xff"').replace(b"\xc3\xbf", b"\xff"),
            "info",
            2,
            "malformed XML",
        ),
        Case("empty.xmi", b"", "info", 2, "malformed XML"),
        Case("not_xml.xmi", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "info", 2, "malformed XML"),
        Case(
            "wrong_root_flow.xmi",
            f"{XML_HEAD}<scemlmodel:Flow {NS}/>\n".encode(),
            "info",
            2,
            "found Flow",
        ),
        Case(
            "wrong_root_foreign.xmi",
            b'<?xml version="1.0"?>\n<html><body/></html>\n',
            "info",
            2,
            "not a SceML model",
        ),
        Case(
            "two_roots.xmi",
            f"{XML_HEAD}<xmi:XMI {NS}>\n<scemlmodel:Scenario/>\n<scemlmodel:Scenario/>\n"
            "</xmi:XMI>\n".encode(),
            "info",
            2,
            "one model per file",
        ),
        Case(
            "unknown_xsi_type.xmi",
            _uis1("scemlmodel:TurnRight", "scemlmodel:Teleport"),
            "info",
            2,
            "Teleport",
        ),
        Case(
            "abstract_xsi_type.xmi",
            _uis1("scemlmodel:TurnRight", "scemlmodel:Maneuver"),
            "info",
            2,
            "abstract",
        ),
        Case(
            "wrong_type_for_feature.xmi",
            _uis1('<rate xsi:type="scemlmodel:Value"', '<rate xsi:type="scemlmodel:Flow"'),
            "info",
            2,
            "Flow",
        ),
        Case(
            "unknown_feature.xmi", _uis1('name="ego"', 'name="ego" wings="2"'), "info", 2, "wings"
        ),
        Case("string_for_number.xmi", _uis1('value="8.0"', 'value="fast"'), "info", 2, "fast"),
        Case("string_for_int.xmi", _uis1('laneId="1"', 'laneId="left"'), "info", 2, "left"),
        Case("int_too_large.xmi", _uis1('laneId="1"', 'laneId="2147483648"'), "info", 2, "32-bit"),
        Case("infinite_number.xmi", _uis1('value="8.0"', 'value="inf"'), "info", 2, "finite"),
        Case("nan_number.xmi", _uis1('value="8.0"', 'value="NaN"'), "info", 2, "finite"),
        Case(
            "bad_enum_literal.xmi",
            _uis1('level="concrete"', 'level="abstract"'),
            "info",
            2,
            "abstract",
        ),
        Case(
            "duplicate_module_names.xmi",
            _library(
                "</scemlmodel:Library>",
                '  <modules xsi:type="scemlmodel:ModuleDefinition" name="CrossingManeuver"/>\n'
                "</scemlmodel:Library>",
            ),
            "info",
            2,
            "duplicate",
        ),
        Case(
            "duplicate_xmi_ids.xmi",
            _uis1('name="ego"', 'xmi:id="a1" name="ego"').replace(
                b'name="bike"', b'xmi:id="a1" name="bike"'
            ),
            "info",
            2,
            "duplicate xmi:id",
        ),
        Case(
            "dangling_fragment.xmi",
            _uis1('referenceActor="//@nodes.0/@actors.0"', 'referenceActor="//@nodes.0/@actors.7"'),
            "info",
            2,
            "//@nodes.0/@actors.7",
        ),
        Case(
            "reference_to_wrong_type.xmi",
            _uis1('referenceActor="//@nodes.0/@actors.0"', 'referenceActor="//@flows.0"'),
            "info",
            2,
            "Flow",
        ),
        Case(
            "missing_library.xmi",
            _uis2(use_href, 'href="library/absent.xmi#CrossingManeuver"'),
            "info",
            1,
            "no such file",
        ),
        Case(
            "missing_module.xmi",
            _uis2(use_href, 'href="library/sceml-library.xmi#Absent"'),
            "info",
            1,
            "Absent",
        ),
        Case(
            "network_href.xmi",
            _uis2(use_href, 'href="http://192.0.2.1/lib.xmi#CrossingManeuver"'),
            "info",
            1,
            "only local files",
        ),
        Case(
            "outside_href.xmi",
            _uis2(use_href, 'href="../../../../../../etc/passwd#x"'),
            "info",
            1,
            "allowed folders",
        ),
        Case(
            "absolute_href.xmi",
            _uis2(use_href, 'href="/etc/hosts#x"'),
            "info",
            1,
            "allowed folders",
        ),
        Case(
            "containment_href_to_self.xmi",
            _scenario_with_nodes(
                '  <nodes xsi:type="scemlmodel:RootNode" name="Root">\n'
                '    <actors href="#/"/>\n  </nodes>\n'
            ),
            "info",
            2,
            "containment",
        ),
        Case(
            "self_use_direct.xmi",
            _self_using_library("SelfDirect", "#SelfDirectModule"),
            "info",
            0,
            "SelfDirectModule",
        ),
        Case(
            "self_use_a.xmi",
            _self_using_library("SelfA", "self_use_b.xmi#SelfBModule"),
            "info",
            0,
            "SelfAModule",
        ),
        Case(
            "self_use_b.xmi",
            _self_using_library("SelfB", "self_use_a.xmi#SelfAModule"),
            "info",
            0,
            "SelfBModule",
        ),
        Case(
            "self_use_direct_scenario.xmi",
            _scenario_using("self_use_direct.xmi#SelfDirectModule"),
            "info",
            0,
            "SelfDirectModule from self_use_direct.xmi",
        ),
        Case(
            "self_use_transitive_scenario.xmi",
            _scenario_using("self_use_a.xmi#SelfAModule"),
            "info",
            0,
            "SelfAModule from self_use_a.xmi",
        ),
        Case("deep_nesting.xmi", _deep(300), "info", 2, "depth"),
        Case(
            "xosc_billion_laughs.xosc", _billion_laughs("OpenSCENARIO"), "check-xosc", 2, "DOCTYPE"
        ),
        Case(
            "xosc_xxe.xosc",
            _external_entity("OpenSCENARIO", "file:///etc/passwd"),
            "check-xosc",
            2,
            "DOCTYPE",
        ),
        Case(
            "xosc_truncated.xosc",
            b'<?xml version="1.0"?>\n<OpenSCENARIO>\n  <FileHeader',
            "check-xosc",
            2,
            "not well-formed",
        ),
        Case(
            "xosc_invalid_utf8.xosc",
            b'<?xml version="1.0" encoding="UTF-8"?>\n<Open\xffSCENARIO/>',
            "check-xosc",
            2,
            "not well-formed",
        ),
        Case(
            "xosc_deep_nesting.xosc",
            b"<OpenSCENARIO>" + b"<a>" * 300 + b"</a>" * 300 + b"</OpenSCENARIO>",
            "check-xosc",
            2,
            "depth",
        ),
    ]


def cases() -> list[Case]:
    """Every case of the corpus, in MANIFEST order."""
    return _xml_cases()


def manifest(all_cases: list[Case]) -> str:
    """The MANIFEST text for these cases."""
    lines = [f"{c.name}\t{c.command}\t{c.exit_code}\t{c.expected}" for c in all_cases]
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    """Write the corpus, or with `--check` report whether the committed one is stale."""
    all_cases = cases()
    wanted = {c.name: c.content for c in all_cases} | {"MANIFEST": manifest(all_cases).encode()}
    # The library the scenario cases refer to, so that only the broken part is broken.
    wanted["library/sceml-library.xmi"] = (EXAMPLES / "library" / "sceml-library.xmi").read_bytes()
    if "--check" in argv:
        stale = [n for n, data in wanted.items() if not _same(CORPUS / n, data)]
        for name in stale:
            print(f"corpus/{name} is stale: run tests/hostile/make_corpus.py")
        return 1 if stale else 0
    for name, data in wanted.items():
        (CORPUS / name).parent.mkdir(parents=True, exist_ok=True)
        (CORPUS / name).write_bytes(data)
    return 0


def _same(path: Path, data: bytes) -> bool:
    return path.is_file() and path.read_bytes() == data


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
