#!/usr/bin/env bash
# Builds the libFuzzer targets of the file parsers with clang-14 (ASan + LeakSanitizer + UBSan) in
# <repo>/build-fuzz and runs each for a bounded time on its corpus (fuzz/corpus/<target>/, read only; new
# inputs go to build-fuzz/corpus/<target>/). Fails on any crash, leak, sanitizer report, timeout or OOM;
# the input that broke a target is saved as build-fuzz/artifacts/<target>/crash-* (add it to the corpus and
# a regression test, see docs/reliability.md).
# Usage: scripts/fuzz.sh [--seconds N] [--seed S] [--build DIR] [target...]   (default 60 s each, seed 1)
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
seconds=60; seed=1; build="$repo/build-fuzz"; targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2;;
    --seed) seed="$2"; shift 2;;
    --build) build="$2"; shift 2;;
    -h|--help) sed -n '2,8p' "$0"; exit 0;;
    *) targets+=("$1"); shift;;
  esac
done
all_targets=0
[ ${#targets[@]} -gt 0 ] || { all_targets=1; targets=(world_loader text_map map_yaml map_image carmen_reader message_conversions bag_reader); }
command -v clang++-14 > /dev/null || { echo "fuzz: clang++-14 not found (scripts/install_deps.sh installs it)"; exit 1; }

source "$repo/scripts/env.sh" "$build"
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDOORPLATE_FUZZ=ON \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 -DCATKIN_ENABLE_TESTING=OFF \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 > "$build.cmake.log" 2>&1 || { cat "$build.cmake.log"; exit 1; }
cmake --build "$build" --target fuzz_targets -- -j2 > "$build/fuzz_build.log" 2>&1 \
  || { tail -n 40 "$build/fuzz_build.log"; echo "fuzz: build failed"; exit 1; }

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
passed=0; failed=0
# The rawlog reader's target exists where MRPT is found (cmake/fuzz.cmake): run with the others when built.
[ "$all_targets" = 1 ] && [ -x "$build/fuzz/rawlog_reader_fuzz" ] && targets+=(rawlog_reader)
for t in "${targets[@]}"; do
  bin="$build/fuzz/${t}_fuzz"
  rm -rf "$build/artifacts/$t"  # only this run's findings
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t"
  # -rss_limit_mb / -malloc_limit_mb: a parser must not allocate ~GBs for a small file.
  asan="$ASAN_OPTIONS"
  # MRPT's rawlog reader (not ours, not instrumented) allocates what a length prefix says; the child process
  # that reads each file first (src/tools/rawlog_reader.h) then ends with ASan's report, unsymbolized for speed.
  [ "$t" = rawlog_reader ] && asan="$asan:max_allocation_size_mb=256:symbolize=0"
  max_len=8192; [ "$t" = bag_reader ] && max_len=65536  # a bag stores each connection's message definitions
  if ASAN_OPTIONS="$asan" "$bin" -seed="$seed" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=512 \
       -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" \
       "$build/corpus/$t" "$repo/fuzz/corpus/$t" > "$build/$t.fuzz.log" 2>&1; then
    passed=$((passed + 1))
    echo "[fuzz] $t: ok ($(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$build/$t.fuzz.log" | grep -o '[0-9]*$') runs in ${seconds} s)"
  else
    failed=$((failed + 1))
    echo "[fuzz] $t: FAILED (log $build/$t.fuzz.log, input in $build/artifacts/$t/)"
    grep -E -A 25 "ERROR: |runtime error|==ERROR|deadly signal|out-of-memory|timeout" "$build/$t.fuzz.log" | head -n 40
  fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" = 0 ]
