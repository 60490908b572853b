#!/bin/sh
# SPDX-License-Identifier: MIT
# Checks that the C files listed in tools/clang-format.files are exactly as
# clang-format writes them with the repository's .clang-format.
#
#   tools/format_check.sh             the check (`make test` runs it)
#   tools/format_check.sh --matching  prints every C file of the tree that
#                                     clang-format leaves unchanged, listed
#                                     or not: the candidates for the list
#
# Only the listed files are checked: .clang-format states the project's C
# style as far as clang-format can, and files written denser than it allows
# (see the comment at its top) are not reformatted. A file joins the list
# once clang-format leaves it unchanged; a listed file that is edited stays
# in the style (run `clang-format -i FILE`, or fix the lines it reports).
#
# clang-format comes with `tools/deps.sh test`; without it the check fails.
# CLANG_FORMAT names another binary (clang-format-19, ...). clang-format 14
# (Debian 12's) and 19 both leave every listed file unchanged.
#
# Prints PASS or FAIL lines (tests/support/run.sh).
set -u
cd "$(dirname "$0")/.."
cf=${CLANG_FORMAT:-clang-format}
list=tools/clang-format.files
dirs="firmware hal host_sim tools tests examples"

if ! command -v "$cf" >/dev/null 2>&1; then
  echo "FAIL format: $cf is not installed (tools/deps.sh test installs it)"
  exit 1
fi
version=$("$cf" --version | sed -n 's/.*clang-format version \([0-9][0-9.]*\).*/\1/p')

if [ "${1:-}" = "--matching" ]; then
  for d in $dirs; do [ -d "$d" ] && find "$d" -name '*.[ch]' -type f; done | sort | while read -r f; do
    "$cf" --dry-run -Werror "$f" >/dev/null 2>&1 && echo "$f"
  done
  exit 0
fi
[ $# -eq 0 ] || { echo "usage: tools/format_check.sh [--matching]" >&2; exit 2; }

# The list: one path a line; blank lines and lines starting with # ignored.
files=$(sed -e 's/#.*//' -e 's/[[:space:]]*$//' "$list" | grep -v '^$') || {
  echo "FAIL format: $list lists no files"
  exit 1
}
n=0
bad=0
for f in $files; do
  n=$((n + 1))
  if [ ! -f "$f" ]; then
    echo "FAIL format $f: listed in $list but not in the tree"
    bad=$((bad + 1))
    continue
  fi
  if ! out=$("$cf" --dry-run -Werror "$f" 2>&1); then
    echo "FAIL format $f: not as clang-format $version writes it with .clang-format (clang-format -i $f); first lines it reports:"
    printf '%s\n' "$out" | head -n 12
    bad=$((bad + 1))
  fi
done
if [ "$bad" -eq 0 ]; then
  echo "PASS format: $n files as clang-format $version writes them ($list)"
fi
[ "$bad" -eq 0 ]
