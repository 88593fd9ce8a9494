#!/usr/bin/env bash
# The whole test suite, as CI runs it: set-up, lint, types, generated-code check, the editor page's
# type check, lint and unit tests, then pytest (browser tests included).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "== ruff";   .venv/bin/ruff check . && .venv/bin/ruff format --check .
echo "== mypy";   .venv/bin/mypy
echo "== generated/ matches metamodel/"; .venv/bin/sceml dev generate --check
echo "== metamodel: no breaking change without its migration"; .venv/bin/sceml dev check-release
echo "== web: types, lint, unit tests"; (cd web && npm run --silent check && npm test --silent)
echo "== pytest"; .venv/bin/pytest -q "$@"
