#!/usr/bin/env bash
# First command of the README: install what is missing, build, and start StepCom on the
# built-in simulated controller.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
build=${BUILD_DIR:-build}
if [[ -x "$build/app/stepcom" ]]; then
    exec "$build/app/stepcom" --sim "$@"
fi
echo "The window is not built yet; reading every parameter of the built-in simulator instead:"
exec "$build/app/stepcomctl" --sim read "$@"
