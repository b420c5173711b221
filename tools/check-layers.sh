#!/usr/bin/env bash
# @brief The layering check: every #include <beamimpact/MODULE/...> in a module's folder names a
# module listed before it in cmake/modules.txt (lower layers never see higher ones), and never a
# module the line forbids ("!paper": the references never see the paper's code). Tests (*_test.cc)
# may compare methods and are exempt from both rules.
# Usage: tools/check-layers.sh [ROOT]   Exit 1 with one line per violation.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
declare -A rank folder
declare -A forbidden
i=0
while read -r module dir rest; do
  [[ -z "$module" || "$module" == \#* ]] && continue
  if [[ "$module" == "*" ]]; then  # every subfolder with C++ headers, named after it
    for sub in ${dir%/\*}/*/; do
      sub=${sub%/}
      compgen -G "$sub/*.hpp" > /dev/null || continue
      m=${sub##*/}; rank[$m]=$i; folder[$m]=$sub; forbidden[$m]=" ${rest//!/} "
    done
  else
    rank[$module]=$i; folder[$module]=$dir; forbidden[$module]=" ${rest//!/} "
  fi
  i=$((i + 1))
done < cmake/modules.txt
bad=0
for module in "${!folder[@]}"; do
  while IFS= read -r hit; do
    file=${hit%%:*}
    owner=$module  # a file belongs to the module with the deepest folder holding it
    for m in "${!folder[@]}"; do
      [[ "$file" == "${folder[$m]}/"* && ${#folder[$m]} -gt ${#folder[$owner]} ]] && owner=$m
    done
    [[ "$owner" == "$module" ]] || continue
    used=$(sed -E 's|.*#include <beamimpact/([a-z_]+)/.*|\1|' <<<"$hit")
    [[ -n "${rank[$used]:-}" ]] || { echo "$file: includes unknown module '$used'"; bad=1; continue; }
    if [[ "$file" != *_test.cc && ${rank[$used]} -gt ${rank[$module]} ]]; then
      echo "$file: module '$module' includes higher module '$used' (cmake/modules.txt)"; bad=1
    fi
    if [[ "$file" != *_test.cc && "${forbidden[$module]}" == *" $used "* ]]; then
      echo "$file: module '$module' must not include '$used' (forbidden in cmake/modules.txt)"; bad=1
    fi
  done < <(grep -rHE '#include <beamimpact/[a-z_]+/' "${folder[$module]}" --include=*.cc --include=*.hpp 2>/dev/null || true)
done
# Nothing below tools/ includes the CLI's private headers.
if grep -rlE '#include "(command_|CommandExit)' solver references api verification 2>/dev/null; then
  echo "a module includes a tools/ header"; bad=1
fi
if ((bad)); then echo "check-layers: FAILED"; exit 1; fi
echo "check-layers: ${#folder[@]} modules, no upward or forbidden include"
