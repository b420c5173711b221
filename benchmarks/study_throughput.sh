#!/usr/bin/env bash
# @brief Throughput of `beamimpact study` (cases per second) at 1 and N MPI ranks in one run, the
# ratio between them, and the load average of the machine before and after (a shared machine
# slows the parallel run: read the ratio with the load). Also checks that both tables agree.
# Usage: benchmarks/study_throughput.sh [STUDY] [N] [BUILD_DIR]
#   default STUDY verification/studies/s4_throughput.toml, N 2, BUILD_DIR build
# As root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 (set here).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
study=${1:-$root/verification/studies/s4_throughput.toml}
n=${2:-2}
build=${3:-$root/build}
exe=$build/beamimpact
[[ -x "$exe" ]] || { echo "study_throughput: $exe not built" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "beamimpact $("$exe" --version), study $study, $(nproc) cores"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$exe" study "$study" --out "$out/r1" 2> "$out/r1.log" | head -1
mpirun --oversubscribe -n "$n" "$exe" study "$study" --out "$out/r$n" 2> "$out/rn.log" | head -1
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
cmp -s "$out/r1/study.csv" "$out/r$n/study.csv" && echo "study.csv identical at 1 and $n ranks" \
  || { echo "study_throughput: study.csv differs between 1 and $n ranks" >&2; exit 1; }
/usr/bin/python3 - "$out/r1/timing.json" "$out/r$n/timing.json" "$n" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
print(f"1 rank: {a['cases']} cases in {a['wall_seconds']:.1f} s = {a['cases_per_second']:.3f} cases/s")
print(f"{sys.argv[3]} ranks: {b['cases']} cases in {b['wall_seconds']:.1f} s = {b['cases_per_second']:.3f} cases/s")
print(f"speed-up {b['cases_per_second'] / a['cases_per_second']:.2f}x")
PY
