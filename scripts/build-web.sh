#!/usr/bin/env bash
# Build the editor's browser page (web/) into src/sceml/editor/static/, which the Python package
# ships, so that `sceml edit` needs no Node at run time. Installs the npm packages exactly as the
# committed lock file says. Skips what is already up to date; FORCE=1 rebuilds.
set -euo pipefail
cd "$(dirname "$0")/../web"

node_major=$(node -p 'process.versions.node.split(".")[0]')
if ((node_major < 20)); then
  echo "build-web: the editor needs Node.js >= 20 to build (found $(node --version))" >&2
  exit 2
fi

newest() { find "$@" -type f -printf '%T@\n' 2>/dev/null | sort -n | tail -1; }
# stale OUTPUT INPUT...: OUTPUT is missing or older than the newest INPUT (or FORCE=1).
stale() {
  local output=$1 built
  shift
  built=$(newest "$output")
  [ "${FORCE:-}" = 1 ] || [ -z "$built" ] ||
    awk -v a="$(newest "$@")" -v b="$built" 'BEGIN { exit !(a > b) }'
}

if stale node_modules/.package-lock.json package-lock.json; then
  echo "build-web: npm ci"
  npm ci --no-audit --no-fund --loglevel=error
fi
if stale ../src/sceml/editor/static src public index.html package.json package-lock.json \
  vite.config.ts tsconfig.json; then
  echo "build-web: npm run build"
  npm run --silent build
fi
