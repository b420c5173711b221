# @brief The C++ files the checks read (sourced by tools/check-format.sh and
# tools/check-function-length.sh): in a git checkout the files git tracks (*.cc, *.hpp, *.h),
# elsewhere (an unpacked source archive) every such file outside build/.
# Usage: source tools/cpp-files.sh; cpp_files NAME   (in the root: the array `files`, or exit 1
# with "NAME: no C++ files under ROOT" when there are none)
cpp_files() {
  if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    mapfile -t files < <(git ls-files '*.cc' '*.hpp' '*.h')
  else
    mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cc' -o -name '*.hpp' -o -name '*.h' \) -print)
  fi
  ((${#files[@]})) || { echo "$1: no C++ files under $PWD" >&2; exit 1; }
}
