#!/usr/bin/env bash
# Fails when a C++ file is not formatted as the repository's .clang-format says, and shows the
# difference. `scripts/check-format.sh --fix` formats them in place instead.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (scripts/deps.sh --test)" >&2; exit 2; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files -- '*.cpp' '*.h')
else
    mapfile -t files < <(find app core ui tests -name '*.cpp' -o -name '*.h' | sort)
fi
if [[ "${1:-}" == "--fix" ]]; then
    clang-format -i "${files[@]}"
    exit 0
fi
bad=0
for f in "${files[@]}"; do
    if ! out=$(clang-format --style=file "$f" | diff -u --label "$f" --label "$f (clang-format)" "$f" -); then
        printf '%s\n' "$out"
        bad=$((bad + 1))
    fi
done
if [[ $bad -gt 0 ]]; then
    echo "check-format: $bad of ${#files[@]} files are not formatted ($(clang-format --version | head -n1)); run scripts/check-format.sh --fix" >&2
    exit 1
fi
echo "check-format: ${#files[@]} files formatted"
