#!/usr/bin/env bash
# @brief The CI gate of a solver kept in its own repository: the protocol's rules (`beamimpact
# conform`), then the benchmark scenes scored against the committed scorecard (`beamimpact score
# --baseline`): exit 1 when a rule is broken or an error grew beyond its uncertainty, 2 on bad
# input. Needs the `beamimpact` program on PATH (pip install; beamimpact's docs/ci.md).
# Usage: gate.sh [OUT]   (default out/; writes OUT/conform and OUT/score)
#   gate.sh --update     writes scorecard.json from a new score (commit it with the change that moved it)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-out}
[[ $out == --update ]] && out=out
# The benchmark scenes this solver is held to: the central rod impact (S1) and its offset-gap
# variant, both with an exact answer (a ladder of three resolutions each). Add scenes and sets as
# the solver grows (`beamimpact scenes`; docs/benchmark-cards.md).
sets=paper,exact
scenes=s1_central,s1_offset_gap
score=(beamimpact score mysolver --methods "$here/methods.toml" --sets "$sets" --scenes "$scenes"
       --out "$out/score" --cache "$out/reference-cache")
beamimpact conform mysolver --methods "$here/methods.toml" --out "$out/conform" --scenes end_to_end
if [[ ${1:-} == --update ]]; then
  "${score[@]}"
  cp "$out/score/scorecard.json" "$here/scorecard.json"
  echo "gate: wrote $here/scorecard.json"
else
  "${score[@]}" --baseline "$here/scorecard.json"
fi
