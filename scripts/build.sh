#!/usr/bin/env bash
# Configures and builds the package (catkin, standalone) into BUILD_DIR (default: <repo>/build).
# Usage: scripts/build.sh [--sanitize] [BUILD_DIR]
set -euo pipefail
sanitize=OFF
if [ "${1:-}" = "--sanitize" ]; then sanitize=ON; shift; fi
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$repo/build}"
source "$repo/scripts/env.sh" "$build"
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDOORPLATE_SANITIZE=$sanitize \
  -DCATKIN_ENABLE_TESTING=ON -DPYTHON_EXECUTABLE=/usr/bin/python3 > "$build.cmake.log" 2>&1 \
  || { cat "$build.cmake.log"; exit 1; }
cmake --build "$build" -- -j2
cmake --build "$build" --target tests -- -j2
