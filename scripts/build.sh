#!/usr/bin/env bash
# Configures and builds the package (catkin, standalone) into BUILD_DIR (default: <repo>/build).
# Default: everything, then the tests (scripts/test.sh). --demo: only what scripts/demo.sh needs (the CMake
# target doorplate_demo: the nodelet libraries the launch files load, the messages, the report tool).
# Prints one line per stage (configure, each target built, the seconds taken; on a terminal also the file
# being compiled); the compiler's output goes to BUILD_DIR.build.log, whose end
# is shown if the build fails. Parallel jobs: DOORPLATE_JOBS (default 2).
# Usage: scripts/build.sh [--sanitize] [--demo] [BUILD_DIR]
set -euo pipefail
sanitize=OFF; demo=0
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize) sanitize=ON; shift;;
    --demo) demo=1; shift;;
    *) break;;
  esac
done
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$repo/build}"
jobs="${DOORPLATE_JOBS:-2}"
source "$repo/scripts/env.sh" "$build"
start=$SECONDS
log="$build.build.log"
echo "== build: configuring $build (log: $build.cmake.log)"
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDOORPLATE_SANITIZE=$sanitize \
  -DCATKIN_ENABLE_TESTING=ON -DPYTHON_EXECUTABLE=/usr/bin/python3 > "$build.cmake.log" 2>&1 \
  || { cat "$build.cmake.log"; exit 1; }
: > "$log"

# build_targets WHAT TARGET...: builds, printing "built <target>" lines (and, on a terminal, the file being
# compiled in place); on failure the log's last errors.
build_targets() {
  local what="$1"; shift
  local args=() t tty=0
  for t in "$@"; do args+=(--target "$t"); done
  [ -t 1 ] && tty=1
  echo "== build: $what ($jobs jobs; compiler output: $log)"
  set +e
  cmake --build "$build" "${args[@]}" -- -j"$jobs" 2>&1 | tee -a "$log" | awk -v tty=$tty '
    BEGIN { pct = "[  ?%]" }
    match($0, /^\[ *[0-9]+%\]/) { pct = substr($0, RSTART, RLENGTH) }
    /Building CXX object|Linking CXX/ && tty == 1 {
      n = split($NF, parts, "/"); file = parts[n]; sub(/\.o$/, "", file)
      printf "\r\033[K   %s %s", pct, ($0 ~ /Linking/ ? "linking " file : "compiling " file); fflush()
    }
    /^\[ *[0-9]+%\] Built target .*(generate_messages_|_check_deps_)/ { next }  # message steps: one line per package
    /^\[ *[0-9]+%\] Built target / {
      if (tty == 1) printf "\r\033[K"
      printf "   %s built %s\n", pct, $NF; fflush()
    }
    END { if (tty == 1) printf "\r\033[K" }'
  local rc=${PIPESTATUS[0]}
  set -e
  if [ "$rc" != 0 ]; then
    echo "== build failed ($what); the errors (all in $log):"
    grep -E -A5 "error|Error [0-9]" "$log" | head -n 60
    exit "$rc"
  fi
  echo "   done in $((SECONDS - start)) s since the start"
}

if [ "$demo" = 1 ]; then
  build_targets "the demo's targets" doorplate_demo
else
  build_targets "everything" all
  build_targets "the tests" tests
fi
