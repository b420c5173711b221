#!/usr/bin/env bash
# @brief The main job: installs what is missing, builds the program (tests and benchmarks are
# the test command's), runs the verification matrix on the shipped scenes and writes its results
# under out/verify/ (norms.json, report.md, junit.xml), then out/verify/report.html
# (reports/render.py): the verdict, where it fails and what it costs on the first screen, then
# every gate and the figure sets, each figure marked with the build that made it; the figures are
# files in out/verify/figures/, loaded lazily.
# Usage: tools/run-verification.sh [--tier quick|full] [--score] [--figures]   (default: quick)
#   --score    also scores every method that runs here (`beamimpact methods`) on the benchmark set:
#              out/score/NAME/scorecard.html with its runs on the work-precision diagrams
#   --figures  also remakes, with this build, the committed figure sets that take minutes, into
#              out/figures/NAME (the committed reports/NAME are left as they are), and the report
#              shows those instead: paper_figures, classical_benchmarks, beam_theories and
#              work_precision at the paper scenes' own sizes. Each step prints its time and the total.
#              Measured with beamimpact 0.1.0+048044f on 2 cores at load 11-13 (wall, each script
#              as run below): paper_figures 142 s, classical_benchmarks 37 s, beam_theories 269 s,
#              work_precision 2222 s; 2670 s for the four, 46 min with verify (docs/user-guide.md,
#              "Reading the report").
#              The sets that take hours keep their committed figures and say which build made them:
#              the S4 study (1050 runs, 15 min on 2 MPI ranks), the scorecards (every method on the benchmark set) and the
#              work-precision sets at x22..x5000 (hours of IDA and Siconos).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BEAMIMPACT_BUILD_DIR:-build}
args=()
score=0
figures=0
for a in "$@"; do
  case $a in
    --score) score=1 ;;
    --figures) figures=1 ;;
    *) args+=("$a") ;;
  esac
done
((${#args[@]})) || args=(--tier quick)
# The report needs only the program and /usr/bin/python3 with matplotlib and jinja2; --figures also
# the Python module (work_precision.py times in process through it).
if ((figures)); then bash tools/build.sh beamimpact beamimpact_python; else bash tools/build.sh beamimpact; fi
status=0
rm -rf out/verify/norms.json out/verify/report.html out/verify/figures  # never a stale report from an earlier run
"$build"/beamimpact verify verification/matrix.toml --out out/verify --jobs "$(nproc)" "${args[@]}" || status=$?

fresh=()
if ((figures)); then
  # NAME | command (run from the repository, output into out/figures/NAME)
  remake=(
    "paper_figures|/usr/bin/python3 reports/paper_figures.py --build $build --out out/figures/paper_figures --runs out/figures/runs/paper_figures"
    "classical_benchmarks|/usr/bin/python3 reports/classical_benchmarks.py --build $build --out out/figures/classical_benchmarks --runs out/figures/runs/classical_benchmarks"
    "beam_theories|/usr/bin/python3 reports/beam_theories.py --build $build --out out/figures/beam_theories --runs out/figures/runs/beam_theories"
    "work_precision|/usr/bin/python3 reports/work_precision.py --build $build --out out/figures/work_precision --runs out/figures/runs/work_precision"
  )
  all=$SECONDS
  for r in "${remake[@]}"; do
    IFS='|' read -r name cmd <<< "$r"
    rm -rf "out/figures/$name" && mkdir -p "out/figures/$name"
    start=$SECONDS
    echo "figures: $name: $cmd"
    # shellcheck disable=SC2086
    if $cmd >"out/figures/$name.log" 2>&1; then
      fresh+=(--figures "out/figures/$name")
      echo "figures: $name remade in $((SECONDS - start)) s (log: out/figures/$name.log)"
    else
      echo "figures: $name FAILED after $((SECONDS - start)) s; the report keeps the committed set (log: out/figures/$name.log)" >&2
      status=1
    fi
  done
  echo "figures: $((${#fresh[@]} / 2)) set(s) remade, $((SECONDS - all)) s in all; the S4 study, the scorecards and the sized work-precision sets keep their committed figures"
fi

# The report shows a failing run too (its verdicts say so); an interrupted or refused run wrote no norms.json.
if [[ -f out/verify/norms.json ]]; then
  /usr/bin/python3 reports/render.py report --verify out/verify "${fresh[@]}" --committed --out out/verify/report.html
fi
if ((score)); then
  # Every method that runs here (but exact: it is the reference where it applies) in one command,
  # so that a reference several methods meet is run once.
  mapfile -t found < <("$build"/beamimpact methods | awk '/ runs here/ && $1 != "exact" {print $1}')
  echo "score: ${found[*]} -> out/score/NAME/scorecard.html (log: out/score.log)"
  # Exit 1 is a scorecard whose verdict failed (still drawn); 2 and above wrote none.
  rc=0
  "$build"/beamimpact score "${found[@]}" --out out/score --jobs "$(nproc)" >out/score.log 2>&1 || rc=$?
  if ((rc <= 1)); then
    for m in "${found[@]}"; do
      dir=out/score; ((${#found[@]} > 1)) && dir=out/score/$m
      # score made the page (reports/render.py); this adds the work-precision diagrams and renders it again.
      /usr/bin/python3 reports/scorecard_figures.py "$dir"
    done
  fi
  if ((rc != 0)); then
    echo "score exited $rc (1: a verdict failed; the verdict lines end out/score.log)" >&2
    status=1
  fi
fi
exit "$status"
