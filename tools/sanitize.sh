#!/usr/bin/env bash
# @brief The sanitizer check: builds with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (incl. float-cast-overflow) into build-asan/, then runs the unit and
# CLI tests and the quick verification tier there. Any sanitizer report fails the test.
# Built without MPI (OpenMPI's own allocations and progress threads are not ours to sanitize): the
# study runs through the serial path of the same task farm; cli_mpi_identity_test covers mpirun.
# The same build holds the fuzz targets (libFuzzer coverage on all code): tools/fuzz.sh uses it.
# Usage: tools/sanitize.sh [--build-only]
#   env BEAMIMPACT_ASAN_DIR for another folder, BEAMIMPACT_JOBS for -j
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh --sanitizers
build=${BEAMIMPACT_ASAN_DIR:-build-asan}
jobs=${BEAMIMPACT_JOBS:-$(nproc)}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1" \
  -DBEAMIMPACT_SANITIZE=ON -DBEAMIMPACT_FUZZ=ON \
  -DBEAMIMPACT_FENICSX_TESTS=OFF -DBEAMIMPACT_BENCHMARKS=OFF -DBEAMIMPACT_MPI=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$jobs"
[[ "${1:-}" == "--build-only" ]] && exit 0
# LeakSanitizer needs ptrace rights that containers often lack: leaks are not checked here.
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Everything but the slow tier, the install test (it installs and builds a consumer: no
# sanitizer value, a minute of build), the scorecard figures' test (it scores the paper
# integrator on all 21 benchmark scenes: over its 5 min under ASan; the scorer's C++ is checked
# here by the Scorecard.* tests, the figures are Python) and the documentation's build (Sphinx and
# its gallery, which runs the Python examples on the Python module this build leaves out; the test
# command builds and checks it).
ctest --test-dir "$build" --output-on-failure -j"$jobs" -LE full \
  -E '^(install_consumer|reports_scorecard_figures_test|docs_build)$'
