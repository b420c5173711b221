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
# Ninja and ccache (the repository as ccache's base folder): tools/mutation-test.sh builds a copy of
# the tree with the same compile lines, so every object it does not mutate comes from the cache.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
config=(-DCMAKE_BUILD_TYPE=Release)
[[ -f "$build/CMakeCache.txt" ]] || config+=(-G Ninja)
command -v ccache >/dev/null && config+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" "${config[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j"${BEAMIMPACT_JOBS:-$(nproc)}" "${targets[@]}"
