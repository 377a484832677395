#!/bin/bash
# Holds every C++ file of the tree (src/, include/, test/, bench/, fuzz/) to
# .clang-format: lists every file that clang-format would change and exits
# non-zero if there is one. Run by the test command; `clang-format -i <file>`
# fixes a file.
#
#   bash scripts/format_check.sh             # every C++ file of the tree
#   bash scripts/format_check.sh --changed   # those changed since main
#   bash scripts/format_check.sh FILE...     # these files
#
# --changed takes the files that differ from the merge-base of HEAD and
# origin/main (else main), committed or not, and new untracked ones.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$repo"
files=()
if [ "${1:-}" = "--changed" ]; then
  mapfile -t files < <(rbs_changed_cxx "$(rbs_main_base)")
  if [ ${#files[@]} -eq 0 ]; then
    echo "format_check: OK (no C++ changed since main)"
    exit 0
  fi
elif [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(find src include test bench fuzz \( -name '*.cpp' -o -name '*.h' \) | sort)
fi
unformatted=()
for file in "${files[@]}"; do
  clang-format --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "format_check: not as .clang-format says (clang-format -i fixes them):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "format_check: OK (${#files[@]} files)"
