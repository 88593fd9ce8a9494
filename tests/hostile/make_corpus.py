"""Writes the corpus of hostile and broken input files, and its MANIFEST, into tests/hostile/corpus.

Most cases are small edits of the shipped examples, so each one differs from a good file in
exactly one way. Run it after changing a case; `--check` exits 1 when the committed corpus is
stale. The 100 MB case is not here: the tests make it in a temporary folder.

MANIFEST: one case per line, `FILE<TAB>ENTRY POINTS<TAB>EXIT<TAB>LINE<TAB>TEXT`. Every entry
point (comma-separated; a name of READERS stands for all of its entry points) run on FILE must
exit with EXIT and print TEXT, the file's path and, unless LINE is `-`, that line number.
Entry points are named in tests/hostile/test_corpus.py (e.g. `module-list` is `sceml module
list FILE`, `limits` is `sceml validate --limits FILE`).
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

import scemlmodel

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
EXAMPLES = HERE.parents[1] / "examples"

XML_HEAD = '<?xml version="1.0" encoding="UTF-8"?>\n'
#: The current release's namespace, so that the corpus tests the files of this release.
NS = (
    'xmlns:xmi="http://www.omg.org/XMI" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
    f'xmlns:scemlmodel="{scemlmodel.nsURI}" xmi:version="2.0"'
)


#: Groups of entry points: every command that reads a model file, an OpenSCENARIO file, a
#: limits file or a ranges file.
READERS = {
    "model": (
        "info",
        "validate",
        "export",
        "render",
        "flatten",
        "module-list",
        "sample",
        "concretize",
        "report",
        "export-distribution",
        "simulate",
        "explore",
        "migrate",
        "check-run",
        "diff",
        "merge",
    ),
    "xosc": ("check-xosc", "import"),
    "config": ("limits", "ranges"),
}


@dataclass(frozen=True)
class Case:
    """One hostile file and what every entry point given must answer."""

    name: str
    content: bytes
    readers: str
    exit_code: int
    expected: str
    line: int | None = None


def _example(name: str) -> str:
    # The corpus lies two folders deeper than examples/: keep the map reachable (SCEML-R001).
    text = (EXAMPLES / name).read_text(encoding="utf-8")
    return text.replace('map="../maps/intersection.xodr"', 'map="../../../maps/intersection.xodr"')


def _replace_once(text: str, old: str, new: str) -> str:
    if text.count(old) < 1:
        raise ValueError(f"{old!r} not found")
    return text.replace(old, new, 1)


def _at(example: str, text: str) -> int:
    """The line of an example on which `text` first occurs: where an edit of it will be."""
    source = _example(example)
    return source[: source.index(text)].count("\n") + 1


def _uis1(old: str, new: str) -> bytes:
    return _replace_once(_example(UIS1), old, new).encode()


def _uis2(old: str, new: str) -> bytes:
    return _replace_once(_example(UIS2), old, new).encode()


def _logical(example: str, old: str, new: str) -> bytes:
    return _replace_once(_example(example), old, new).encode()


def _library(old: str, new: str) -> bytes:
    return _replace_once(_example(LIBRARY), old, new).encode()


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
    data = (EXAMPLES / UIS1).read_bytes()
    return data[: len(data) // 2]


def _alias_bomb() -> bytes:
    # Nine levels of nine aliases: 9**9 values for whatever walks the result, from 21 nodes.
    levels = ["&a0 [1, 1, 1, 1, 1, 1, 1, 1, 1]"]
    levels += [f"&a{n} [{', '.join([f'*a{n - 1}'] * 9)}]" for n in range(1, 9)]
    return f"ego.initialSpeed: [{', '.join(levels)}]\n".encode()


UIS1 = "uis1-concrete.xmi"
UIS2 = "uis2-concrete.xmi"
LIBRARY = "library/sceml-library.xmi"
USE_HREF = 'href="library/sceml-library.xmi#CrossingManeuver"'
#: Entry points that report a scenario's broken module reference (the others need none, or
#: refuse the scenario's level first).
REFERENCE_READERS = "info,validate,export,render,flatten,concretize"
RANGE = '<initialSpeed xsi:type="scemlmodel:Range" min="3.0" max="7.0" step="1.0"/>'


def _xml_cases() -> list[Case]:
    return [
        Case("billion_laughs.xmi", _billion_laughs("x"), "model", 2, "DTDs and entity", 2),
        Case("xxe_file.xmi", _external_entity("x", "file:///etc/passwd"), "model", 2, "DTDs", 2),
        Case("xxe_network.xmi", _external_entity("x", "http://192.0.2.1/x"), "model", 2, "DTDs", 2),
        Case(
            "truncated.xmi",
            _truncated(),
            "model",
            2,
            "malformed XML",
            _truncated().count(b"\n") + 1,
        ),
        Case(
            "invalid_utf8.xmi",
            _uis1('name="ego"', 'name="eg\xff"').replace(b"\xc3\xbf", b"\xff"),
            "model",
            2,
            "malformed XML",
            _at(UIS1, 'name="ego"'),
        ),
        Case("empty.xmi", b"", "model", 2, "malformed XML", 1),
        Case("not_xml.xmi", b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "model", 2, "malformed XML", 1),
        Case(
            "wrong_root_flow.xmi",
            f"{XML_HEAD}<scemlmodel:Flow {NS}/>\n".encode(),
            "model",
            2,
            "found Flow",
            2,
        ),
        Case(
            "wrong_root_foreign.xmi",
            b'<?xml version="1.0"?>\n<html><body/></html>\n',
            "model",
            2,
            "not a SceML model",
            2,
        ),
        Case(
            "two_roots.xmi",
            f"{XML_HEAD}<xmi:XMI {NS}>\n<scemlmodel:Scenario/>\n<scemlmodel:Scenario/>\n"
            "</xmi:XMI>\n".encode(),
            "model",
            2,
            "one model per file",
            2,
        ),
        Case(
            "unknown_xsi_type.xmi",
            _uis1("scemlmodel:TurnRight", "scemlmodel:Teleport"),
            "model",
            2,
            "Teleport",
            _at(UIS1, "scemlmodel:TurnRight"),
        ),
        Case(
            "abstract_xsi_type.xmi",
            _uis1("scemlmodel:TurnRight", "scemlmodel:Maneuver"),
            "model",
            2,
            "abstract",
            _at(UIS1, "scemlmodel:TurnRight"),
        ),
        Case(
            "xsi_type_without_prefix.xmi",
            _uis1('xsi:type="scemlmodel:Accelerate"', 'xsi:type="Accelerate"'),
            "model",
            2,
            'xsi:type "Accelerate" has no namespace prefix; expected "scemlmodel:Accelerate"',
            _at(UIS1, 'xsi:type="scemlmodel:Accelerate"'),
        ),
        Case(
            "xsi_type_undeclared_prefix.xmi",
            _uis1('xsi:type="scemlmodel:Accelerate"', 'xsi:type="sceml:Accelerate"'),
            "model",
            2,
            'xsi:type "sceml:Accelerate": prefix "sceml" is not declared; expected '
            '"scemlmodel:Accelerate"',
            _at(UIS1, 'xsi:type="scemlmodel:Accelerate"'),
        ),
        Case(
            "xsi_type_foreign_namespace.xmi",
            _uis1('xsi:type="scemlmodel:Accelerate"', 'xsi:type="xmi:Accelerate"'),
            "model",
            2,
            'xsi:type "xmi:Accelerate": prefix "xmi" is not the SceML metamodel\'s namespace',
            _at(UIS1, 'xsi:type="scemlmodel:Accelerate"'),
        ),
        Case(
            "wrong_type_for_feature.xmi",
            _uis1('<rate xsi:type="scemlmodel:Value"', '<rate xsi:type="scemlmodel:Flow"'),
            "model",
            2,
            "Flow",
            _at(UIS1, '<rate xsi:type="scemlmodel:Value"'),
        ),
        Case(
            "unknown_feature.xmi",
            _uis1('name="ego"', 'name="ego" wings="2"'),
            "model",
            2,
            "wings",
            _at(UIS1, 'name="ego"'),
        ),
        Case(
            "string_for_number.xmi",
            _uis1('value="8.0"', 'value="fast"'),
            "model",
            2,
            "fast",
            _at(UIS1, 'value="8.0"'),
        ),
        Case(
            "string_for_int.xmi",
            _uis1('laneId="1"', 'laneId="left"'),
            "model",
            2,
            "left",
            _at(UIS1, 'laneId="1"'),
        ),
        Case(
            "int_too_large.xmi",
            _uis1('laneId="1"', 'laneId="2147483648"'),
            "model",
            2,
            "32-bit",
            _at(UIS1, 'laneId="1"'),
        ),
        Case(
            "infinite_number.xmi",
            _uis1('value="8.0"', 'value="inf"'),
            "model",
            2,
            "finite",
            _at(UIS1, 'value="8.0"'),
        ),
        Case(
            "nan_number.xmi",
            _uis1('value="8.0"', 'value="NaN"'),
            "model",
            2,
            "finite",
            _at(UIS1, 'value="8.0"'),
        ),
        Case(
            "bad_enum_literal.xmi",
            _uis1('level="concrete"', 'level="abstract"'),
            "model",
            2,
            "abstract",
            _at(UIS1, 'level="concrete"'),
        ),
        Case(
            "duplicate_module_names.xmi",
            _library(
                "</scemlmodel:Library>",
                '  <modules xsi:type="scemlmodel:ModuleDefinition" name="CrossingManeuver"/>\n'
                "</scemlmodel:Library>",
            ),
            "model",
            2,
            "duplicate",
            _at(LIBRARY, "</scemlmodel:Library>"),
        ),
        Case(
            "duplicate_xmi_ids.xmi",
            _uis1('name="ego"', 'xmi:id="a1" name="ego"').replace(
                b'name="bike"', b'xmi:id="a1" name="bike"'
            ),
            "model",
            2,
            "duplicate xmi:id",
            _at(UIS1, 'name="bike"'),
        ),
        Case(
            "dangling_fragment.xmi",
            _uis1('referenceActor="//@nodes.0/@actors.0"', 'referenceActor="//@nodes.0/@actors.7"'),
            "model",
            2,
            "//@nodes.0/@actors.7",
            _at(UIS1, 'referenceActor="//@nodes.0/@actors.0"'),
        ),
        Case(
            "reference_to_wrong_type.xmi",
            _uis1('referenceActor="//@nodes.0/@actors.0"', 'referenceActor="//@flows.0"'),
            "model",
            2,
            "Flow",
            _at(UIS1, 'referenceActor="//@nodes.0/@actors.0"'),
        ),
        *_reference_cases(),
        Case(
            "containment_href_to_self.xmi",
            _scenario_with_nodes(
                '  <nodes xsi:type="scemlmodel:RootNode" name="Root">\n'
                '    <actors href="#/"/>\n  </nodes>\n'
            ),
            "model",
            2,
            "containment",
            4,
        ),
        *_self_use_cases(),
        Case("deep_nesting.xmi", _deep(300), "model", 2, "depth", 3),
        *_logical_cases(),
        *_xosc_cases(),
    ]


def _reference_cases() -> list[Case]:
    # The line is the ModuleUse's (its <definition href> child is on the next).
    use = _at(UIS2, 'name="CrossingManeuver_1"')
    broken = [
        ("missing_library.xmi", 'href="library/absent.xmi#CrossingManeuver"', "no such file"),
        ("missing_module.xmi", 'href="library/sceml-library.xmi#Absent"', "Absent"),
        (
            "network_href.xmi",
            'href="http://192.0.2.1/lib.xmi#CrossingManeuver"',
            "only local files",
        ),
        ("outside_href.xmi", 'href="../../../../../../etc/passwd#x"', "allowed folders"),
        ("absolute_href.xmi", 'href="/etc/hosts#x"', "allowed folders"),
    ]
    return [
        Case(name, _uis2(USE_HREF, href), REFERENCE_READERS, 1, text, use)
        for name, href, text in broken
    ]


def _self_use_cases() -> list[Case]:
    return [
        Case(
            "self_use_direct.xmi",
            _self_using_library("SelfDirect", "#SelfDirectModule"),
            "info,module-list",
            0,
            "SelfDirectModule",
        ),
        Case(
            "self_use_a.xmi",
            _self_using_library("SelfA", "self_use_b.xmi#SelfBModule"),
            "info,module-list",
            0,
            "SelfAModule",
        ),
        Case(
            "self_use_b.xmi",
            _self_using_library("SelfB", "self_use_a.xmi#SelfAModule"),
            "info,module-list",
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
        Case(
            "self_use_scenario_flattened.xmi",
            _scenario_using("self_use_a.xmi#SelfAModule"),
            "flatten",
            1,
            # The cycle is reported where it closes: in the library, not the scenario.
            "self_use_b.xmi:6: module uses itself: SelfAModule -> SelfBModule -> SelfAModule",
        ),
    ]


def _logical_cases() -> list[Case]:
    # Logical scenarios, for `sample`: what it would sample is broken or would never end.
    logical1, logical2 = "uis1-logical.xmi", "uis2-logical.xmi"
    return [
        Case(
            "logical_missing_library.xmi",
            _logical(logical2, USE_HREF, 'href="library/absent.xmi#CrossingManeuver"'),
            "validate,sample",
            1,
            "no such file",
            _at(logical2, 'name="CrossingManeuver_1"'),
        ),
        Case(
            "logical_zero_step.xmi",
            _logical(logical1, RANGE, RANGE.replace('step="1.0"', 'step="0"')),
            "validate,sample",
            1,
            "range step 0 must be above zero",
            _at(logical1, RANGE),
        ),
        Case(
            "logical_grid_too_large.xmi",
            _logical(logical1, RANGE, RANGE.replace('step="1.0"', 'step="1e-12"')),
            "sample",
            1,
            "levels, above",
        ),
    ]


def _xosc_cases() -> list[Case]:
    return [
        Case("xosc_billion_laughs.xosc", _billion_laughs("OpenSCENARIO"), "xosc", 2, "DOCTYPE", 2),
        Case(
            "xosc_xxe_file.xosc",
            _external_entity("OpenSCENARIO", "file:///etc/passwd"),
            "xosc",
            2,
            "DOCTYPE",
            2,
        ),
        Case(
            "xosc_xxe_network.xosc",
            _external_entity("OpenSCENARIO", "http://192.0.2.1/x"),
            "xosc",
            2,
            "DOCTYPE",
            2,
        ),
        Case(
            "xosc_truncated.xosc",
            b'<?xml version="1.0"?>\n<OpenSCENARIO>\n  <FileHeader',
            "xosc",
            2,
            "not well-formed",
            3,
        ),
        Case(
            "xosc_invalid_utf8.xosc",
            b'<?xml version="1.0" encoding="UTF-8"?>\n<Open\xffSCENARIO/>',
            "xosc",
            2,
            "not well-formed",
            2,
        ),
        Case(
            "xosc_wrong_root.xosc",
            b'<?xml version="1.0"?>\n<html><body/></html>\n',
            "xosc",
            2,
            "no FileHeader",
        ),
        Case(
            "xosc_deep_nesting.xosc",
            b"<OpenSCENARIO>" + b"<a>" * 300 + b"</a>" * 300 + b"</OpenSCENARIO>",
            "xosc",
            2,
            "depth",
            1,
        ),
    ]


def _config_cases() -> list[Case]:
    deep = "[" * 3000 + "]" * 3000
    huge = "1" + "0" * 5000
    return [
        Case(
            "config_python_tag.yaml",
            b'Car: !!python/object/apply:os.system ["echo pwned"]\n',
            "config",
            2,
            "could not determine a constructor",
            1,
        ),
        Case("config_alias_bomb.yaml", _alias_bomb(), "config", 2, "alias bomb"),
        Case("config_deep.yaml", f"Car: {deep}\n".encode(), "config", 2, "nested too deeply"),
        Case("config_deep.json", f'{{"Car": {deep}}}\n'.encode(), "config", 2, "too deeply"),
        Case("config_deep.toml", f"Car = {deep}\n".encode(), "config", 2, "nested too deeply"),
        Case("config_huge_int.yaml", f"Car: {huge}\n".encode(), "config", 2, "4300 digits"),
        Case("config_huge_int.toml", f"Car = {huge}\n".encode(), "config", 2, "4300 digits"),
        Case("config_bad_date.yaml", b"Car: 2026-13-01\n", "config", 2, "month must be in"),
        Case("config_malformed.yaml", b"Car: [1, 2\n", "config", 2, "malformed", 2),
        Case("config_malformed.json", b'{"Car": [1, 2\n', "config", 2, "malformed", 2),
        Case("config_malformed.toml", b"[Car\nx = 1\n", "config", 2, "malformed", 1),
        Case("config_invalid_utf8.yaml", b"Car:\n  maxSpeed: 3\xff\n", "config", 2, "not UTF-8", 2),
        Case("config_not_a_mapping.yaml", b"- Car\n- Truck\n", "config", 2, "file maps"),
    ]


def _recording_cases() -> list[Case]:
    """Recorded drives (`sceml extract`) that cannot be used."""
    header = b"time,actor,x,y,heading,speed\n"
    return [
        Case(
            "recording_invalid_utf8.csv",
            header + b"0,ego\xff,1,2,0,0\n",
            "extract",
            2,
            "not valid UTF-8",
        ),
        Case(
            "recording_bad_number.csv",
            header + b"0,ego,1,2,0,0\n0.1,ego,1e999,2,0,0\n",
            "extract",
            2,
            "x is not finite",
            3,
        ),
        Case(
            "recording_unknown_format.csv",
            b"when,who,where\n1,2,3\n",
            "extract",
            2,
            "cannot tell the recording's format",
            1,
        ),
    ]


def cases() -> list[Case]:
    """Every case of the corpus, in MANIFEST order."""
    return _xml_cases() + _config_cases() + _recording_cases()


def manifest(all_cases: list[Case]) -> str:
    """The MANIFEST text for these cases."""
    lines = [
        f"{c.name}\t{c.readers}\t{c.exit_code}\t{c.line or '-'}\t{c.expected}" for c in all_cases
    ]
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    """Write the corpus, or with `--check` report whether the committed one is stale."""
    all_cases = cases()
    wanted = {c.name: c.content for c in all_cases} | {"MANIFEST": manifest(all_cases).encode()}
    # The library the scenario cases refer to, so that only the broken part is broken.
    wanted[LIBRARY] = (EXAMPLES / LIBRARY).read_bytes()
    present = {p.relative_to(CORPUS).as_posix() for p in CORPUS.rglob("*") if p.is_file()}
    if "--check" in argv:
        stale = [n for n, data in wanted.items() if not _same(CORPUS / n, data)]
        stale += sorted(present - set(wanted))
        for name in stale:
            print(f"corpus/{name} is stale: run tests/hostile/make_corpus.py")
        return 1 if stale else 0
    for name in present - set(wanted):
        (CORPUS / name).unlink()
    for name, data in wanted.items():
        (CORPUS / name).parent.mkdir(parents=True, exist_ok=True)
        (CORPUS / name).write_bytes(data)
    return 0


def _same(path: Path, data: bytes) -> bool:
    return path.is_file() and path.read_bytes() == data


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
