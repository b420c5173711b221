#!/usr/bin/env bash
# @brief The format check: every C++ file of the repository (*.cc, *.hpp, *.h) as clang-format 14
# writes it with the repository's .clang-format (`clang-format --dry-run -Werror`). Fix a failure
# with `clang-format -i FILE`.
# Usage: tools/check-format.sh [ROOT]   Exit 1 (one warning per drifting line) when a file drifts.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cc' '*.hpp' '*.h')
else
  mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cc' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
((${#files[@]})) || { echo "check-format: no C++ files under $root" >&2; exit 1; }
clang-format --dry-run -Werror "${files[@]}"
echo "check-format: ${#files[@]} files formatted"
