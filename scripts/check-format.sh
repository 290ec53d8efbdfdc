#!/usr/bin/env bash
# The formatter check of the test command: every C++ file of src/, tests/ and bench/ must be as
# clang-format (the repo's .clang-format, Debian's clang-format 14) writes it, except the files in
# scripts/format-legacy.txt, written before the check and not yet reformatted (the list only
# shrinks: reformat a file, remove its line). A new file is checked from its first commit.
set -euo pipefail
cd "$(dirname "$0")/.."
legacy=scripts/format-legacy.txt
bad=()
while IFS= read -r f; do
  grep -qxF "$f" "$legacy" && continue
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' 'bench/*.cpp' 'bench/*.hpp')
stale=()
while IFS= read -r f; do
  [ -f "$f" ] && clang-format --dry-run --Werror "$f" >/dev/null 2>&1 && stale+=("$f")
done < "$legacy"
if [ ${#bad[@]} -gt 0 ]; then
  echo "not formatted (run clang-format -i on them):"; printf '  %s\n' "${bad[@]}"; exit 1
fi
if [ ${#stale[@]} -gt 0 ]; then
  echo "formatted now, remove them from $legacy:"; printf '  %s\n' "${stale[@]}"; exit 1
fi
echo "format: $(git ls-files 'src/*.[ch]pp' 'tests/*.[ch]pp' 'bench/*.[ch]pp' | wc -l) files, $(wc -l < "$legacy") legacy files not yet reformatted"
