#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer + UBSan) in build-fuzz/ (override
# with FUZZ_BUILD_DIR) from only the core files they need, and runs each for a bounded time
# on its committed seed corpus (tests/fuzz/corpus/<target>/) plus its regression inputs.
#   scripts/fuzz.sh                   every target, 60 s each (FUZZ_SECONDS)
#   FUZZ_SECONDS=600 scripts/fuzz.sh registermap
# New corpus entries go to build-fuzz/corpus/<target>/ (the committed corpus is not touched);
# a crash leaves build-fuzz/crash-<target>-* and fails the script. Add that input to
# tests/fuzz/regressions/<target>/ with the fix: the normal test suite replays it from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh --test
build=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${FUZZ_SECONDS:-60}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S tests/fuzz -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="${FUZZ_CXX:-clang++}" \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" >/dev/null
cmake --build "$build" --parallel "${JOBS:-$(nproc)}"

targets=("$@")
if [[ ${#targets[@]} -eq 0 ]]; then
    for dir in tests/fuzz/corpus/*/; do targets+=("$(basename "$dir")"); done
fi
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
# fuzz_one TARGET: run one target for its time; fails with the crashing input's name.
fuzz_one() {
    local t=$1 exe="$build/fuzz_$1" work="$build/corpus/$1" seeds
    mkdir -p "$work"
    seeds=(tests/fuzz/corpus/"$t")
    [[ -d tests/fuzz/regressions/$t ]] && seeds+=(tests/fuzz/regressions/"$t")
    # -timeout: an input that takes over 10 s is a hang; -rss_limit_mb: a runaway allocation.
    if ! "$exe" "$work" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
            -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/$t-" \
            -dict=tests/fuzz/json.dict 2>"$build/fuzz-$t.log"; then
        tail -n 60 "$build/fuzz-$t.log" >&2
        echo "fuzz: $t FAILED, input saved as $(ls -t "$build/$t"-* 2>/dev/null | head -1)" >&2
        return 1
    fi
    grep -E '^stat::number_of_executed_units|^stat::new_units_added|Done ' "$build/fuzz-$t.log" |
        sed "s/^/fuzz: $t: /" || true
}
for t in "${targets[@]}"; do
    [[ -x $build/fuzz_$t ]] || { echo "fuzz: no target $t ($build/fuzz_$t)" >&2; exit 2; }
done
# The targets run side by side, one per core: each is one process, so on 2 cores two take the
# time of one.
status=0
pids=()
for t in "${targets[@]}"; do
    echo "fuzz: $t for ${seconds} s"
    fuzz_one "$t" &
    pids+=($!)
    if [[ ${#pids[@]} -ge ${JOBS:-$(nproc)} ]]; then
        wait "${pids[0]}" || status=1
        pids=("${pids[@]:1}")
    fi
done
for pid in "${pids[@]}"; do
    wait "$pid" || status=1
done
exit $status
