#!/usr/bin/env bash
# @brief Fuzzing (issue 16): builds the libFuzzer targets of fuzz/ with clang + ASan + UBSan (the
# build of tools/sanitize.sh, build-asan/) and runs each from its seed corpus (the shipped scenes, matrix and fuzz/corpus/).
# Usage: tools/fuzz.sh            each target for 20 s (CI)
#        tools/fuzz.sh --long     a campaign: each target for BEAMIMPACT_FUZZ_SECONDS (default 1800)
# Prints the executions reached per target; exits non-zero on a finding (crash, sanitizer report,
# an exception other than SceneError, a timeout or an out-of-memory), saved in build-asan/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BEAMIMPACT_ASAN_DIR:-build-asan}
seconds=20
[[ "${1:-}" == "--long" ]] && seconds=${BEAMIMPACT_FUZZ_SECONDS:-1800}
bash tools/sanitize.sh --build-only   # the fuzz targets live in the sanitizer build

# Seeds: the shipped files. The working corpus grows in build-asan/corpus/TARGET.
declare -A seeds=(
  [scene_fuzz]="$(find verification/scenes fuzz/corpus/scene -name '*.toml' | tr '\n' ' ')"
  [run_reader_fuzz]="$(find fuzz/corpus/run -type f | tr '\n' ' ')"
  [matrix_fuzz]="verification/matrix.toml"
)
mkdir -p "$build/findings"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
status=0
for t in scene_fuzz run_reader_fuzz matrix_fuzz; do
  corpus="$build/corpus/$t"
  mkdir -p "$corpus"
  # shellcheck disable=SC2086
  cp ${seeds[$t]} "$corpus/" 2>/dev/null || true
  log="$build/findings/$t.log"
  if "$build/fuzz/$t" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
       -print_final_stats=1 -artifact_prefix="$build/findings/$t-" >"$log" 2>&1; then
    echo "$t: $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') executions in ${seconds} s, no finding"
  else
    status=1
    echo "$t: FINDING, see $log and $build/findings/$t-*"
    grep -m1 -E 'ERROR|terminate|runtime error' "$log" || tail -5 "$log"
  fi
done
exit $status
