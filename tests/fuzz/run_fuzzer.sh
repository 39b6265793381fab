#!/usr/bin/env bash
# usage: run_fuzzer.sh FUZZER WORKDIR SECONDS SEED_DIR...
# Runs a libFuzzer target for SECONDS with a fixed seed, from its seed corpus (read only:
# new inputs go to WORKDIR/corpus). A finding fails the test and leaves the input in
# WORKDIR/crash-* : add it to tests/fuzz/regressions/<target>/ with the fix.
set -euo pipefail
fuzzer=$1 work=$2 seconds=$3
shift 3
rm -rf "$work" && mkdir -p "$work/corpus"
seeds=()
for d in "$@"; do [ -d "$d" ] && seeds+=("$d"); done
# ASan: report leaks too, but the HDF5 library keeps its free lists until exit by design.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
exec "$fuzzer" -seed=1 -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}"
