#!/usr/bin/env bash
# Set up everything SceML and its test suite need on a fresh Debian/Ubuntu machine:
# system packages (Graphviz, a JDK with Eclipse EMF, Chromium, Node.js), a virtualenv in .venv, SceML
# installed into it in editable mode with its development extras, and the editor's browser bundle.
# Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

APT_PACKAGES=(graphviz default-jdk-headless libeclipse-emf-ecore-xmi-java chromium fonts-dejavu-core)
missing=()
for package in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The editor's browser page is built from web/ with Node and npm; machines that already have a
# Node (for example from NodeSource, which bundles npm) keep it.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing nodejs npm"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq nodejs npm >/dev/null
fi

python=${PYTHON:-python3}
"$python" -c 'import sys; sys.exit(sys.version_info < (3, 11))' \
  || { echo "setup: SceML needs Python >= 3.11 (set PYTHON=...)" >&2; exit 2; }
[ -x .venv/bin/python ] || "$python" -m venv .venv
.venv/bin/python -m pip install -q --disable-pip-version-check -e '.[dev]'
# ASAM's OpenDRIVE checker, for the tests of our map (tests/maps/test_opendrive_checker.py). Its
# 1.0.0 release pins pyclothoids < 0.2, numpy < 2 and xmlschema < 4, older than ours, so pip
# cannot resolve it with SceML; it runs fine on ours, so it is installed without its pins.
.venv/bin/python -m pip install -q --disable-pip-version-check --no-deps \
  asam-qc-opendrive==1.0.0 transforms3d==0.4.2 semver==3.1.1
bash scripts/build-web.sh
echo "setup: ready (.venv/bin/sceml)"
