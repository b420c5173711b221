#!/usr/bin/env bash
# @brief Fuzzing: builds the libFuzzer targets of fuzz/ with clang + ASan + UBSan (the
# build of tools/sanitize.sh, build-asan/) and runs each from its seed corpus (the shipped scenes, matrix and fuzz/corpus/).
# Usage: tools/fuzz.sh            each target for 12 s, one after the other (CI: a minute in all)
#        tools/fuzz.sh --long     a campaign: the targets side by side (nice 19), each until
#                                 BEAMIMPACT_FUZZ_RUNS executions (default 1000000) or
#                                 BEAMIMPACT_FUZZ_SECONDS (default 10800), whichever comes first
# Prints the executions reached per target; exits non-zero on a finding (crash, sanitizer report,
# an exception other than InputError, a timeout or an out-of-memory), saved in build-asan/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BEAMIMPACT_ASAN_DIR:-build-asan}
seconds=12
runs=-1            # libFuzzer: no execution limit
long=false
if [[ "${1:-}" == "--long" ]]; then
  long=true
  seconds=${BEAMIMPACT_FUZZ_SECONDS:-10800}
  runs=${BEAMIMPACT_FUZZ_RUNS:-1000000}
fi
bash tools/sanitize.sh --build-only   # the fuzz targets live in the sanitizer build

# Seeds: the shipped files. The working corpus grows in build-asan/corpus/TARGET.
declare -A seeds=(
  [scene_fuzz]="$(find verification/scenes fuzz/corpus/scene -name '*.toml' | tr '\n' ' ')"
  [run_reader_fuzz]="$(find fuzz/corpus/run -type f | tr '\n' ' ')"
  [matrix_fuzz]="verification/matrix.toml $(find fuzz/corpus/matrix -type f | tr '\n' ' ')"
  [study_fuzz]="$(find verification/studies fuzz/corpus/study -name '*.toml' | tr '\n' ' ')"
  [methods_fuzz]="verification/methods.toml $(find fuzz/corpus/methods -type f | tr '\n' ' ')"
)
mkdir -p "$build/findings"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
targets=(scene_fuzz run_reader_fuzz matrix_fuzz study_fuzz methods_fuzz)

# fuzz_one TARGET: runs one target from its corpus; its log is build-asan/findings/TARGET.log.
fuzz_one() {
  local t=$1 corpus="$build/corpus/$1"
  mkdir -p "$corpus"
  # shellcheck disable=SC2086
  cp ${seeds[$t]} "$corpus/" 2>/dev/null || true
  "$build/fuzz/$t" "$corpus" -max_total_time="$seconds" -runs="$runs" -timeout=10 -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="$build/findings/$t-" >"$build/findings/$t.log" 2>&1
}

# report TARGET EXIT: one line per target: executions and time, or the finding.
report() {
  local t=$1 log="$build/findings/$1.log"
  if [[ $2 == 0 ]]; then
    local n t_s
    n=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
    t_s=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | grep -o 'in [0-9]*' | grep -o '[0-9]*')
    echo "$t: $n executions in ${t_s:-?} s, no finding"
  else
    echo "$t: FINDING, see $log and $build/findings/$t-*"
    grep -m1 -E 'ERROR|terminate|runtime error' "$log" || tail -5 "$log"
  fi
}

status=0
if $long; then
  declare -A pid
  # Side by side at the lowest priority, so a campaign can run beside other work.
  for t in "${targets[@]}"; do (renice -n 19 "$BASHPID" >/dev/null; fuzz_one "$t") & pid[$t]=$!; done
  for t in "${targets[@]}"; do rc=0; wait "${pid[$t]}" || rc=$?; report "$t" "$rc"; ((rc == 0)) || status=1; done
else
  for t in "${targets[@]}"; do rc=0; fuzz_one "$t" || rc=$?; report "$t" "$rc"; ((rc == 0)) || status=1; done
fi
exit $status
