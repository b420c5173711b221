#!/usr/bin/env bash
# @brief The layering check, read from the module table cmake/modules.txt: every
# #include <FOLDER/...> of a module's file names a module listed before it (lower layers never
# see higher ones) and never one the row forbids ("!paper": the references never see the paper's
# code); every include of a module names a file that exists at that path; every namespace a
# module's file opens is the module's (or nested in it). Tests (*_test.cc) may compare methods
# and are exempt from the layer rules, not from the path and namespace rules. A module's file spells
# a project include one way only: <FOLDER/...> from the repository root (no "quoted" include, no
# <beamimpact/...> but the generated <beamimpact/version.hpp>: that prefix is the installed layout's).
# Usage: tools/check-layers.sh [ROOT]   Exit 1 with one line per violation.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
declare -A rank folder forbidden space
modules=()
add() {  # add MODULE FOLDER NAMESPACE FORBIDDEN RANK
  modules+=("$1"); folder[$1]=$2; space[$1]=$3; forbidden[$1]=" ${4//!/} "; rank[$1]=$5
}
i=0
while read -r module dir library ns rest; do
  [[ -z "$module" || "$module" == \#* ]] && continue
  if [[ "$dir" == */\* ]]; then  # every subfolder with C++ headers, named after it
    for sub in ${dir%/\*}/*/; do
      sub=${sub%/}
      compgen -G "$sub/*.hpp" > /dev/null || continue
      m=${sub##*/}
      add "$m" "$sub" "beamimpact::$m" "$rest" "$i"
    done
  else
    add "$module" "$dir" "$ns" "$rest" "$i"
  fi
  i=$((i + 1))
done < cmake/modules.txt
owner_of() {  # the module whose folder holds the path
  local best=""
  for m in "${modules[@]}"; do
    [[ "$1" == "${folder[$m]}/"* ]] || continue
    [[ -z "$best" || ${#folder[$m]} -gt ${#folder[$best]} ]] && best=$m
  done
  echo "$best"
}
bad=0
for module in "${modules[@]}"; do
  while IFS= read -r hit; do
    file=${hit%%:*}
    path=$(sed -E 's|.*#include <([^>]+)>.*|\1|' <<<"$hit")
    [[ -f "$path" ]] || { echo "$file: includes <$path>, which is no file of the repository"; bad=1; continue; }
    used=$(owner_of "$path")
    [[ -n "$used" ]] || { echo "$file: includes <$path>, outside every module of cmake/modules.txt"; bad=1; continue; }
    if [[ "$file" != *_test.cc && ${rank[$used]} -gt ${rank[$module]} ]]; then
      echo "$file: module '$module' includes higher module '$used' (cmake/modules.txt)"; bad=1
    fi
    if [[ "$file" != *_test.cc && "${forbidden[$module]}" == *" $used "* ]]; then
      echo "$file: module '$module' must not include '$used' (forbidden in cmake/modules.txt)"; bad=1
    fi
  done < <(grep -HE '#include <(solver|references|api|verification)/' "${folder[$module]}"/*.cc "${folder[$module]}"/*.hpp 2>/dev/null || true)
  while IFS= read -r hit; do
    echo "${hit%%:*}: $(sed -E 's|^[^:]*:[0-9]+:||' <<<"$hit") does not name a module folder from the repository root (#include <FOLDER/...>)"; bad=1
  done < <(grep -HnE '^[[:space:]]*#include ("|<beamimpact/)' "${folder[$module]}"/*.cc "${folder[$module]}"/*.hpp 2>/dev/null \
             | grep -v '#include <beamimpact/version.hpp>' || true)
  while IFS= read -r hit; do
    file=${hit%%:*}
    ns=$(sed -E 's|^[^:]*:namespace ([A-Za-z_:]+).*|\1|' <<<"$hit")
    [[ "$ns" == "${space[$module]}" || "$ns" == "${space[$module]}::"* ]] && continue
    [[ ( "$file" == *_test.cc || "${file##*/}" == test_* ) && "$ns" == beamimpact* ]] && continue  # test code may reopen another
    echo "$file: opens namespace $ns; module '$module' declares ${space[$module]} (cmake/modules.txt)"; bad=1
  done < <(grep -HE '^namespace beamimpact' "${folder[$module]}"/*.cc "${folder[$module]}"/*.hpp 2>/dev/null || true)
done
# Nothing below tools/ includes the CLI's private headers.
if grep -rlE '#include "(command_|CommandExit)' solver references api verification 2>/dev/null; then
  echo "a module includes a tools/ header"; bad=1
fi
if ((bad)); then echo "check-layers: FAILED"; exit 1; fi
echo "check-layers: ${#modules[@]} modules, every include a file, no upward or forbidden include, namespaces as listed"
