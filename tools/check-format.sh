#!/usr/bin/env bash
# @brief The format check: every C++ file of the repository (*.cc, *.hpp, *.h) as clang-format 14
# writes it with the repository's .clang-format (`clang-format --dry-run -Werror`). Fix a failure
# with `clang-format -i FILE`.
# Usage: tools/check-format.sh [ROOT]   Exit 1 (one warning per drifting line) when a file drifts.
set -euo pipefail
source "$(dirname "$0")/cpp-files.sh"
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
cpp_files check-format
clang-format --dry-run -Werror "${files[@]}"
echo "check-format: ${#files[@]} files formatted"
