#!/usr/bin/env bash
# @brief No tracked file names a path outside the repository, which a clone does not have:
# the folder of shared material beside a developer's clone, anywhere (what users need is copied into
# docs/: the scene format is docs/scene-format.md), nor an absolute path of the machine that
# made it (/tmp/..., /work/..., /home/..., /root/...) in a committed report (reports/: JSON and
# Markdown write paths relative to the repository), nor a home or work folder of one machine in any
# tracked file. Also: README.md stays under 10 KB (a
# newcomer's five minutes; measured figures belong in docs/performance.md and docs/accuracy-cost.md).
# Usage: tools/check-paths.sh [ROOT]   Exit 1 with one line per hit; 77 (skipped) outside a git checkout.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
git rev-parse --git-dir > /dev/null 2>&1 || { echo "check-paths: not a git checkout: nothing to check"; exit 77; }
status=0
# This file names the patterns it looks for; so does the description of them below.
if git grep -nE '\.\./shared|shared/(spec|notes|paper)' -- . ':!*.png' ':!tools/check-paths.sh'; then
  echo "check-paths: the lines above name a folder outside the repository; point to docs/ instead"
  status=1
fi
if git grep -nE '(^|[^A-Za-z0-9_.~/}-])/(tmp|work|home|root)/' -- 'reports/*.json' 'reports/*.md'; then
  echo "check-paths: the committed reports above carry absolute paths of the machine that made them"
  status=1
fi
if git grep -nE '(^|[^A-Za-z0-9_.~/}-])/(work|home|root)/' -- . ':!*.png' ':!tools/check-paths.sh'; then
  echo "check-paths: the lines above name a folder of one machine; derive it from the repository or the environment"
  status=1
fi
size=$(wc -c < README.md)
if ((size >= 10240)); then
  echo "check-paths: README.md is $size bytes; keep it under 10240 (move figures to docs/)"
  status=1
fi
((status == 0)) && echo "check-paths: no path outside the repository; README.md $size bytes"
exit "$status"
