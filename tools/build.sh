#!/usr/bin/env bash
# @brief Installs the missing Debian packages, then configures and builds beamimpact into build/.
# Usage: tools/build.sh   (env BEAMIMPACT_BUILD_DIR to build elsewhere; BEAMIMPACT_JOBS for -j)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
build=${BEAMIMPACT_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"${BEAMIMPACT_JOBS:-$(nproc)}"
