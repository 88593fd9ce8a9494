#!/usr/bin/env bash
# Set up, then run SceML's main job on the built-in example UIS1: summarise it, validate it,
# export it to OpenSCENARIO 1.3 (XSD-checked), check the file with ASAM's Quality Checker, draw
# it (graph, behavior tree, map), play it in the preview and write its review report. Results go
# to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p out
run() { echo "\$ $*"; "$@"; echo; }
run .venv/bin/sceml info examples/uis1-concrete.xmi
run .venv/bin/sceml validate examples/uis1-concrete.xmi
run .venv/bin/sceml export examples/uis1-concrete.xmi -o out/uis1.xosc --osc-version 1.3
run .venv/bin/sceml check-xosc out/uis1.xosc
run .venv/bin/sceml render examples/uis1-concrete.xmi -o out/uis1.svg
run .venv/bin/sceml render examples/uis1-concrete.xmi -o out/uis1-bt.png --view bt
run .venv/bin/sceml render examples/uis1-concrete.xmi -o out/uis1-map.png --view map
run .venv/bin/sceml simulate examples/uis1-concrete.xmi -o out/uis1-preview.html
run .venv/bin/sceml report examples/uis1-concrete.xmi -o out/uis1-report.html
echo "done: see out/ (uis1.xosc, uis1.svg, uis1-bt.png, uis1-map.png, uis1-preview.html, uis1-report.html)"
echo "draw and edit it in the browser: .venv/bin/sceml edit examples/uis1-concrete.xmi"
