#!/bin/bash
# Holds the C++ of src/ and include/ to .clang-format: lists every file that
# clang-format would change and exits non-zero if there is one. Run by the
# test command; `clang-format -i <file>` fixes a file.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
unformatted=()
while IFS= read -r file; do
  clang-format --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done < <(find src include -name '*.cpp' -o -name '*.h' | sort)
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "format_check: not as .clang-format says (clang-format -i fixes them):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "format_check: OK"
