#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (and LeakSanitizer),
# in build-asan/ (override with ASAN_BUILD_DIR). Any report fails the test that caused it.
#   scripts/sanitize.sh              build and run every test
#   scripts/sanitize.sh -R tst_poller   extra arguments go to ctest
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh --test
build=${ASAN_BUILD_DIR:-build-asan}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# ccache caches compilations with a precompiled header (STEPCOM_PCH) only with this sloppiness.
export CCACHE_SLOPPINESS=pch_defines,time_macros${CCACHE_SLOPPINESS:+,$CCACHE_SLOPPINESS}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DSTEPCOM_SANITIZE=ON \
      "${launcher[@]}" >/dev/null
cmake --build "$build" --parallel "${JOBS:-$(nproc)}"

# halt_on_error + abort: the first report ends the test with a failure and a stack trace.
# Leaks: ours are real findings; tests/sanitizers/lsan.supp may name only third-party
# libraries whose caches live until exit on purpose (none needed so far).
supp="$PWD/tests/sanitizers"
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:detect_odr_violation=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export STEPCOM_SANITIZED=1 # tests skip what sanitizers make meaningless (RSS bounds)
ctest --test-dir "$build" --output-on-failure --timeout 900 -j "${JOBS:-2}" "$@"
