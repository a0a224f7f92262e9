#!/usr/bin/env bash
# The benchmark of docs/performance.md: builds what is missing (into build/, override with
# BUILD_DIR), runs stepcom-bench at 9600, 19200 and 38400 baud against the simulator's
# wire-time model, prints the table and writes it into docs/performance.md. Exits non-zero
# when a target is missed. Arguments go to stepcom-bench (e.g. --baud 9600, --no-window);
# with arguments the document is left as it is.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo} >/dev/null
fi
cmake --build "$build" --parallel "$(nproc)" --target stepcom-bench stepcom
if [ $# -eq 0 ]; then
    exec "$build/app/stepcom-bench" --update-doc docs/performance.md
fi
exec "$build/app/stepcom-bench" "$@"
