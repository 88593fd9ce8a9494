"""Each command's one-line summary for `sceml --help`, so that listing them imports none.

`sceml --help` used to import every command's module (the exporter, the simulator, the editor's
server ...) only to read the first paragraph of each docstring: 0.34 s against 0.1 s. These are
those first paragraphs; tests/cli/test_help_summaries.py fails when one no longer matches its
command, naming the text to put here.
"""

from __future__ import annotations

#: Command name -> the first paragraph of its help, on one line.
SUMMARIES = {
    "info": "Summarise FILE: its level, map, actors, node counts and module uses.",
    "validate": "Validate scenario and library FILES (.xmi) against the SceML rules.",
    "render": "Draw FILE, a scenario or a module library (.xmi), as a diagram.",
    "report": "Write a review report of FILE: diagram, map view, validation diagnostics, actors and parameters.",
    "export": "Export the concrete scenario FILE to OpenSCENARIO.",
    "check-xosc": "Check OpenSCENARIO FILES (.xosc) against the official XSD of their declared version and, for 1.2 and later, ASAM's OpenSCENARIO XML Quality Checker bundle.",
    "import": "Import the OpenSCENARIO 1.0-1.3 FILE as a SceML scenario OUT.",
    "concretize": "Make FILE concrete: set the given parameters, then check that nothing is left open.",
    "promote": "Promote FILE to the logical level with the ranges and distributions in RANGES.",
    "sample": "Sample the logical scenario LOGICAL into concrete scenarios in DIR.",
    "simulate": "Play the concrete scenario FILE in the kinematic preview.",
    "check-run": "Check that a player's run of MODEL's export kept the scenario's meaning.",
    "explore": "Search the logical scenario LOGICAL for its most critical concrete scenarios.",
    "export-distribution": "Export the logical scenario LOGICAL as OpenSCENARIO parameters (1.1 and later).",
    "module": "Work with module libraries: list, show and extract reusable sub-scenarios.",
    "flatten": "Expand every module use in scenario FILE, recursively, and save the result as OUT.",
    "migrate": "Rewrite scenario and library FILES saved with an older release of the SceML metamodel.",
    "extract": "Extract a concrete SceML scenario from the recorded drive RECORDING.",
    "diff": "Show what changed from scenario OLD to scenario NEW, by name and path.",
    "merge": "Merge the changes from BASE to THEIRS into OURS, and write the result to OUT.",
    "git-setup": "Configure git so that `git diff` shows `sceml diff` and `git merge` uses `sceml merge` for *.xmi files.",
    "dev": "Developer commands (need a source checkout and `pip install -e .[dev]`).",
    "edit": "Edit FILE, a scenario (.xmi), in the browser; a missing FILE starts a new scenario.",
}
