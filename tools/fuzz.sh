#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every libFuzzer target of the fuzz preset for a while on its seed corpus (fuzz/corpus/),
# and fails on the first crash, leak of a sanitizer finding or timeout, leaving the input that
# caused it in BUILD_DIR/fuzz-artifacts/. Prints per target the runs, the edges covered and the
# seconds, for docs/fuzzing.md.
# Usage: tools/fuzz.sh [BUILD_DIR] [SECONDS_PER_TARGET]   (defaults: build/fuzz 15)
set -eu
build=${1:-build/fuzz}
seconds=${2:-15}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
artifacts="$build/fuzz-artifacts"
mkdir -p "$artifacts"
status=0
for target in fuzz_project fuzz_csv fuzz_iso286 fuzz_iso1832 fuzz_cad; do
    corpus="$build/fuzz-corpus/$target"
    mkdir -p "$corpus"
    seeds="$source_dir/fuzz/corpus/${target#fuzz_}"
    extra=""
    [ "$target" = fuzz_project ] && extra="$source_dir/resources/examples"
    log="$build/$target.log"
    # -timeout: one input may take 10 s (a STEP file through OpenCascade); -rss_limit_mb: 2 GiB.
    if QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
        "$build/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$artifacts/$target-" "$corpus" "$seeds" $extra >"$log" 2>&1; then
        runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
        edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo '?')
        echo "$target: $runs runs, $edges edges covered, $seconds s, no finding"
    else
        echo "$target: FINDING (see $log and $artifacts)"
        tail -40 "$log"
        status=1
    fi
done
exit $status
