#!/bin/bash
# Lints the Python and the shell of the tree and exits non-zero on any
# finding: pyflakes checks every Python file (*.py, the dynamic_reconfigure
# files cfg/*.cfg, and any other file whose first line names python), and
# ShellCheck every shell script (*.sh, and any other file whose first line
# names bash or sh, e.g. .ci/run) with the files they source; catkin_lint
# -W2 checks package.xml against CMakeLists.txt and cmake/.
# The files are those git tracks plus new untracked ones. Run by the test
# command before the build.
#
#   bash scripts/lint_check.sh
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$repo"
for tool in pyflakes3 shellcheck catkin_lint; do
  command -v "$tool" >/dev/null || {
    echo "lint_check: $tool not found (bash scripts/install_deps.sh)" >&2
    exit 1
  }
done

python_files=()
shell_files=()
while IFS= read -r f; do
  [ -f "$f" ] || continue
  case "$f" in
  *.py | cfg/*.cfg) python_files+=("$f") ;;
  *.sh) shell_files+=("$f") ;;
  *)
    first_line=""
    IFS= read -r first_line <"$f" 2>/dev/null || true
    case "$first_line" in
    '#!'*python*) python_files+=("$f") ;;
    '#!'*/bash* | '#!'*/sh | '#!'*'env bash'* | '#!'*'env sh') shell_files+=("$f") ;;
    esac
    ;;
  esac
done < <(git ls-files --cached --others --exclude-standard | sort -u)

failed=0
pyflakes3 "${python_files[@]}" || failed=1
# -x: the scripts' `source` lines are followed (their `# shellcheck source=`
# paths are relative to the checkout).
shellcheck -x "${shell_files[@]}" || failed=1
# The checkout's directory is named by whoever cloned it, not the package.
# Without rosdep's database (rosdep update needs the network) catkin_lint
# says it cannot check that every dependency resolves; that notice is dropped.
# rviz is optional (the launch files start it only with rviz:=true): where it
# is installed catkin_lint asks for an exec_depend on it, which is dropped too.
lint_status=0
lint_out=$(catkin_lint -W2 --strict --quiet --ignore package_path_name "$repo" 2>&1) || lint_status=$?
findings=$(grep -v -e 'cannot load rosdep database' -e 'unknown dependencies will be ignored' \
  -e "launch configuration needs exec_depend on 'rviz'" -e '^$' <<<"$lint_out" || true)
if [ -n "$findings" ] || { [ "$lint_status" -ne 0 ] && [ -z "$lint_out" ]; }; then
  echo "$findings"
  failed=1
fi
if [ "$failed" -ne 0 ]; then
  echo "lint_check: findings above (pyflakes, shellcheck, catkin_lint)" >&2
  exit 1
fi
echo "lint_check: OK (${#python_files[@]} Python files, ${#shell_files[@]} shell scripts)"
