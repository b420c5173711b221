#!/usr/bin/env bash
# @brief The test command: installs what is missing, builds, runs every test (ctest).
# Usage: tools/run-tests.sh [--full]   --full adds the slow tier (ctest label "full").
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
build=${BEAMIMPACT_BUILD_DIR:-build}
label=(-LE full)
[[ "${1:-}" == "--full" ]] && label=()
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "${label[@]}"
