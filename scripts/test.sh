#!/usr/bin/env bash
# Second command of the README (and CI): install what is missing, build, run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh --test
scripts/check-format.sh # the tree as .clang-format says, before anything is built
scripts/build.sh
build=${BUILD_DIR:-build}
# The suites mostly wait (for the simulator, timers, ptys; the whole suite uses under a minute
# of CPU), so three per core run side by side: on 2 cores 6 at once, 2.5 minutes instead of 6
# with -j 2 (docs/testing.md). CTEST_JOBS=2 runs them as before.
ctest --test-dir "$build" --output-on-failure --timeout 300 -j "${CTEST_JOBS:-$((2 * $(nproc)))}" "$@"
[[ $# -gt 0 ]] && exit 0 # a chosen subset of the tests: nothing more

# The fuzz targets, 10 s each here (docs/testing.md): the suite replays their corpus and
# regressions already; this keeps the libFuzzer build working and explores a little on every
# run. Longer runs: scripts/fuzz.sh (60 s a target) or FUZZ_SECONDS=600 scripts/fuzz.sh.
# STEPCOM_TEST_FUZZ=0 leaves them out.
if [[ ${STEPCOM_TEST_FUZZ:-1} != 0 ]]; then
    FUZZ_SECONDS=${FUZZ_SECONDS:-10} scripts/fuzz.sh
fi
# The whole suite again under ASan + UBSan: a second full build, so only on request.
if [[ ${STEPCOM_TEST_SANITIZE:-0} != 0 ]]; then
    scripts/sanitize.sh
fi
