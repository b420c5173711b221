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
sets=paper  # the paper's scenes: the set this solver is held to (add hard,exact as it grows)
beamimpact conform mysolver --methods "$here/methods.toml" --out "$out/conform"
if [[ ${1:-} == --update ]]; then
  beamimpact score mysolver --methods "$here/methods.toml" --sets "$sets" --out "$out/score"
  cp "$out/score/scorecard.json" "$here/scorecard.json"
  echo "gate: wrote $here/scorecard.json"
else
  beamimpact score mysolver --methods "$here/methods.toml" --sets "$sets" --out "$out/score" \
    --baseline "$here/scorecard.json"
fi
