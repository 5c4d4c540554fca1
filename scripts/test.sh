#!/usr/bin/env bash
# Builds the package and runs every test: the ROS-free core gtests, the message-conversion gtests and the
# rostests (each starts its own ROS master), the rviz screenshot test (test/viz; needs install_deps.sh
# --with-viz), the offline tools' bad-input corpus (test/bad_input) and the install space
# (scripts/check_install.sh). With --sanitize, also builds the core under ASan+UBSan in
# <repo>/build-asan and runs the core tests there, then fuzzes every file parser for a bounded time
# (scripts/fuzz.sh: clang-14, <repo>/build-fuzz; DOORPLATE_FUZZ_SECONDS per target, default 30).
# Prints "N passed, N failed" and exits non-zero on any failure.
# Usage: scripts/test.sh [--sanitize]
set -uo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
sanitize=0
[ "${1:-}" = "--sanitize" ] && sanitize=1
build="${DOORPLATE_BUILD:-$repo/build}"
status=0

bash "$repo/scripts/build.sh" "$build" || { echo "build failed"; exit 1; }
source "$repo/scripts/env.sh" "$build"
rm -rf "$build/test_results"
cmake --build "$build" --target run_tests -- -j1 2>&1 | tee "$build/run_tests.log" \
  | grep -E "^\[ *(RUN|OK|FAILED|PASSED) |^\[ROSTEST\]|^SUMMARY|^ \* RESULT|^-- run_tests|FAILURE|ERROR|FATAL|RLException|Traceback|rror:" || true

passed=0; failed=0
summary=$(/usr/bin/python3 "$repo/scripts/count_test_results.py" "$build/test_results")
echo "$summary" | sed '$d'
read -r passed failed <<< "$(echo "$summary" | tail -n1)"

echo "== rviz screenshot test (Xvfb, software GL): particles and text landmarks drawn"
# (Not `tee /dev/stderr`: when stderr is a file, opening /dev/stderr truncates it and the log above is lost.)
viz_output=$(bash "$repo/test/viz/rviz_screenshot_test.sh" "$build" 2>&1); echo "$viz_output"
viz_summary=$(tail -n1 <<< "$viz_output")
if [[ "$viz_summary" =~ ^viz:\ ([0-9]+)\ passed,\ ([0-9]+)\ failed$ ]]; then
  passed=$((passed + BASH_REMATCH[1])); failed=$((failed + BASH_REMATCH[2]))
else
  failed=$((failed + 1)); echo "[viz] did not run: $viz_summary"
fi

echo "== bad-input corpus: every offline tool on broken and absurd files (test/bad_input/run_bad_input.sh)"
bad_output=$(bash "$repo/test/bad_input/run_bad_input.sh" "$build" 2>&1); echo "$bad_output"
bad_summary=$(tail -n1 <<< "$bad_output")
if [[ "$bad_summary" =~ ^bad_input:\ ([0-9]+)\ passed,\ ([0-9]+)\ failed$ ]]; then
  passed=$((passed + BASH_REMATCH[1])); failed=$((failed + BASH_REMATCH[2]))
else
  failed=$((failed + 1)); echo "[bad_input] did not run: $bad_summary"
fi

echo "== install space: every tool and demo.launch from an install of this build (scripts/check_install.sh)"
if bash "$repo/scripts/check_install.sh" "$build"; then
  passed=$((passed + 1))
else
  failed=$((failed + 1)); echo "[install] FAILED"
fi

if [ "$sanitize" = 1 ]; then
  echo "== sanitizer run (ASan + UBSan) of the ROS-free core tests"
  asan="$repo/build-asan"
  source "$repo/scripts/env.sh" "$asan"
  cmake -S "$repo" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DDOORPLATE_SANITIZE=ON -DCATKIN_ENABLE_TESTING=ON \
    -DPYTHON_EXECUTABLE=/usr/bin/python3 > "$asan.cmake.log" 2>&1 || { cat "$asan.cmake.log"; exit 1; }
  cmake --build "$asan" --target core_tests -- -j2 || { echo "sanitizer build failed"; exit 1; }
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  while read -r bin; do
    [ -n "$bin" ] || continue
    if "$bin" --gtest_brief=1 > "$asan/$(basename "$bin").log" 2>&1; then
      passed=$((passed + 1)); echo "[sanitize] $(basename "$bin"): ok"
    else
      failed=$((failed + 1)); echo "[sanitize] $(basename "$bin"): FAILED"; tail -n 40 "$asan/$(basename "$bin").log"
    fi
  done < "$asan/core_tests.txt"
  echo "== fuzzing the file parsers (libFuzzer + ASan/UBSan/LeakSanitizer, ${DOORPLATE_FUZZ_SECONDS:-30} s each)"
  fuzz_output=$(bash "$repo/scripts/fuzz.sh" --seconds "${DOORPLATE_FUZZ_SECONDS:-30}" 2>&1); echo "$fuzz_output"
  fuzz_summary=$(tail -n1 <<< "$fuzz_output")
  if [[ "$fuzz_summary" =~ ^fuzz:\ ([0-9]+)\ passed,\ ([0-9]+)\ failed$ ]]; then
    passed=$((passed + BASH_REMATCH[1])); failed=$((failed + BASH_REMATCH[2]))
  else
    failed=$((failed + 1)); echo "[fuzz] did not run: $fuzz_summary"
  fi
fi

echo "tests: $passed passed, $failed failed"
[ "$failed" = 0 ] && [ "$passed" -gt 0 ] || status=1
exit $status
