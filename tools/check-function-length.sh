#!/usr/bin/env bash
# @brief The function-length check: every C++ function of the repository (free, member, constructor
# with its initializer list, lambda at namespace scope, test body) at most 80 lines from its name to
# its closing brace, as universal-ctags finds them (its `end` field). Split a longer one along its
# own comments.
# Usage: tools/check-function-length.sh [ROOT] [MAX_LINES]   Exit 1, listing each longer function.
set -euo pipefail
source "$(dirname "$0")/cpp-files.sh"
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
max=${2:-80}
cd "$root"
cpp_files check-function-length
# One line per function definition: end line, start line, file, name (names may hold spaces).
tags=$(ctags --languages=C++ --kinds-C++=f --fields=+ne -x --_xformat='%{end} %{line} %F %N' "${files[@]}")
count=$(wc -l <<< "$tags")
((count > 100)) || { echo "check-function-length: ctags found only $count functions" >&2; exit 1; }
long=$(awk -v max="$max" '$1 - $2 + 1 > max {
  name = $0; sub(/^[^ ]+ [^ ]+ [^ ]+ /, "", name); print $1 - $2 + 1 " lines: " $3 ":" $2 " " name }' <<< "$tags" | sort -rn)
if [[ -n "$long" ]]; then
  echo "check-function-length: functions over $max lines (split them along their own comments):"
  echo "$long"
  exit 1
fi
echo "check-function-length: $count functions in ${#files[@]} files, none over $max lines"
