#!/usr/bin/env bash
# @brief The main job: installs what is missing, builds the program (tests and benchmarks are
# the test command's), runs the verification matrix on the
# shipped scenes and writes its report under out/verify/, then one self-contained
# out/verify/report.html: this run's verdicts plus the committed work-precision sets, paper
# figures and benchmark plots (reports/html_report.py).
# Usage: tools/run-verification.sh [--tier quick|full] [--score]   (default: quick)
#   --score  also scores every method that runs here (`beamimpact methods`) on the benchmark set:
#            out/score/NAME/scorecard.html with its runs on the work-precision diagrams
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh beamimpact   # the report needs only the program and /usr/bin/python3 + matplotlib
build=${BEAMIMPACT_BUILD_DIR:-build}
args=()
score=0
for a in "$@"; do
  if [[ $a == --score ]]; then score=1; else args+=("$a"); fi
done
((${#args[@]})) || args=(--tier quick)
status=0
rm -f out/verify/norms.json out/verify/report.html  # never a stale report from an earlier run
"$build"/beamimpact verify verification/matrix.toml --out out/verify --jobs "$(nproc)" "${args[@]}" || status=$?
# The report shows a failing run too (its verdicts say so); an interrupted or refused run wrote no norms.json.
if [[ -f out/verify/norms.json ]]; then
  /usr/bin/python3 reports/html_report.py --verify out/verify --committed --out out/verify/report.html
fi
if ((score)); then
  # Every method that runs here (but exact: it is the reference where it applies) in one command,
  # so that a reference several methods meet is run once.
  mapfile -t found < <("$build"/beamimpact methods | awk '/ runs here/ && $1 != "exact" {print $1}')
  echo "score: ${found[*]} -> out/score/NAME/scorecard.html (log: out/score.log)"
  if "$build"/beamimpact score "${found[@]}" --out out/score --jobs "$(nproc)" >out/score.log 2>&1; then
    for m in "${found[@]}"; do
      dir=out/score; ((${#found[@]} > 1)) && dir=out/score/$m
      /usr/bin/python3 reports/scorecard_figures.py "$dir"
    done
  else
    echo "score failed: out/score.log" >&2
    status=1
  fi
fi
exit "$status"
