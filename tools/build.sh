#!/usr/bin/env bash
# @brief Installs the missing Debian packages, then configures and builds beamimpact into build/:
# every target (tests and benchmarks included), or only the targets named.
# Usage: tools/build.sh [TARGET...]   (env BEAMIMPACT_BUILD_DIR to build elsewhere; BEAMIMPACT_JOBS for -j)
#   tools/build.sh              everything: what tools/run-tests.sh needs
#   tools/build.sh beamimpact   the program only: what tools/run-verification.sh needs
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
build=${BEAMIMPACT_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j"${BEAMIMPACT_JOBS:-$(nproc)}" "${targets[@]}"
