#!/usr/bin/env bash
# Set up, then run SceML's main job on the built-in example UIS1; results go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p out
run() { echo "\$ $*"; "$@"; }
run .venv/bin/sceml info examples/uis1-concrete.xmi
run .venv/bin/sceml render examples/uis1-concrete.xmi -o out/uis1.svg
run .venv/bin/sceml report examples/uis1-concrete.xmi -o out/uis1-report.html
