#!/usr/bin/env bash
# Fuzzing that runs (issue 37), for .ci/run: every fuzz target of fuzz/ built as cargo-fuzz
# builds it with `--sanitizer none` (libFuzzer from libfuzzer-sys, the SanitizerCoverage
# instrumentation by -Cpasses=sancov-module), which needs no nightly toolchain and no
# cargo-fuzz install, then each run for FUZZ_SECONDS (default 10) from a copy of its seed
# corpus. A crash, a failed assertion or a timeout of one input fails the script and leaves the
# input in fuzz/artifacts/TARGET/.
#
# Locally, with cargo-fuzz and nightly: `cargo fuzz run TARGET` does the same with ASan.
set -euo pipefail
cd "$(dirname "$0")"
seconds=${FUZZ_SECONDS:-10}
host=$(rustc -vV | sed -n 's/^host: //p')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# cargo-fuzz's flags for --sanitizer none; `--target` keeps them off the build scripts and
# proc macros, which run on the host without libFuzzer.
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
export CARGO_TARGET_DIR="$PWD/target"
cargo build -q --release --bins --target "$host"

targets=$(sed -n 's/^name = "\(.*\)"$/\1/p' Cargo.toml | grep -v '^plc-timers-fuzz$')
for t in $targets; do
    mkdir -p "$work/$t" "artifacts/$t"
    if [ -d "corpus/$t" ]; then cp corpus/"$t"/* "$work/$t/"; fi
    echo "== fuzz/$t for ${seconds}s"
    "target/$host/release/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=1024 \
        -artifact_prefix="artifacts/$t/" -print_final_stats=1 "$work/$t" 2>"$work/$t.log" ||
        { tail -n 40 "$work/$t.log" >&2; exit 1; }
    grep -E '^stat::number_of_executed_units|^Done' "$work/$t.log" | tr '\n' ' '
    echo
done
