#!/usr/bin/env bash
# @brief Builds the documentation (docs/*.md, Sphinx + MyST, the C++ API through Doxygen and
# Breathe, the Python API from docstrings) into OUT/html with warnings as errors, then checks
# that every link and image inside the built pages resolves (docs/check_links.py).
# Usage: tools/build-docs.sh [OUT]   (default build/docs; env BEAMIMPACT_BUILD_DIR for the
# built Python package, default build). Packages: python3-sphinx, furo, python3-myst-parser,
# doxygen, python3-breathe (tools/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/docs}
build=${BEAMIMPACT_BUILD_DIR:-build}
for tool in sphinx-build doxygen; do
  command -v "$tool" >/dev/null || { echo "build-docs: $tool is missing (tools/install-deps.sh)" >&2; exit 2; }
done
rm -rf "$out/html" "$out/doxygen"
mkdir -p "$out/doxygen"
BEAMIMPACT_DOXYGEN_OUT="$out/doxygen" doxygen docs/Doxyfile
abs() { [[ "$1" = /* ]] && echo "$1" || echo "$PWD/$1"; }
export BEAMIMPACT_DOXYGEN_XML="$(abs "$out")/doxygen/xml"
export PYTHONPATH="$(abs "$build")/python${PYTHONPATH:+:$PYTHONPATH}" PYTHONDONTWRITEBYTECODE=1
/usr/bin/python3 -m sphinx -E -W --keep-going -n -q -b html -d "$out/doctrees" docs "$out/html"
/usr/bin/python3 docs/check_links.py "$out/html"
