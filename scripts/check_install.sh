#!/usr/bin/env bash
# Checks the install space (issue 19): installs the package built in BUILD_DIR into PREFIX, then, in an
# environment that knows only PREFIX and Debian's ROS (not the source tree, not the devel space):
#   1. rospack finds the package in PREFIX/share;
#   2. every installed tool answers --help with its usage and exit status 0;
#   3. a tool works on the installed data (doorplate_world_maps on an installed world);
#   4. roslaunch doorplate_localization demo.launch (rviz off) loads every nodelet through pluginlib from
#      PREFIX and localizes: /amcl/state says converged within the timeout.
# Usage: scripts/check_install.sh [BUILD_DIR] [PREFIX]   (defaults: <repo>/build, a temporary folder removed
# afterwards; a PREFIX given is kept and must lie outside the source tree)
# BUILD_DIR must have been configured by scripts/build.sh; this sets its CMAKE_INSTALL_PREFIX to PREFIX.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$repo/build}"
build="$(mkdir -p "$build" && cd "$build" && pwd)"
# Default: a throwaway prefix outside the source tree (rospack crawls ROS_PACKAGE_PATH, which holds the
# repo: an install space inside it would be a second doorplate_localization package for roslaunch).
if [ -n "${2:-}" ]; then prefix="$2"; keep=1; else prefix="$(mktemp -d "${TMPDIR:-/tmp}/doorplate_install.XXXXXX")"; keep=0; fi
mkdir -p "$prefix" && prefix="$(cd "$prefix" && pwd)"
case "$prefix/" in "$repo/"*) echo "check_install: PREFIX $prefix is inside the source tree; rospack would find two packages" >&2; exit 2;; esac
timeout_s="${DOORPLATE_INSTALL_CHECK_TIMEOUT_S:-300}"
[ -f "$build/CMakeCache.txt" ] || { echo "check_install: $build is not configured (run scripts/build.sh $build)" >&2; exit 2; }

echo "== install: $build -> $prefix"
source "$repo/scripts/env.sh" "$build"
cmake -DCMAKE_INSTALL_PREFIX="$prefix" "$build" > "$build.install-cmake.log" 2>&1 \
  || { cat "$build.install-cmake.log"; exit 1; }
cmake --build "$build" --target install -- -j2 > "$build.install.log" 2>&1 \
  || { tail -n 40 "$build.install.log"; exit 1; }

# The rest runs with nothing of the source tree or the devel space: only PREFIX and /usr.
work="$(mktemp -d)"
trap 'rm -rf "$work"; [ "$keep" = 1 ] || rm -rf "$prefix"' EXIT
env -i HOME="$work" TERM="${TERM:-dumb}" PATH=/usr/bin:/bin PREFIX="$prefix" WORK="$work" TIMEOUT_S="$timeout_s" \
  bash --noprofile --norc -c '
set -euo pipefail
export OMP_THREAD_LIMIT=1 ROS_PYTHON_VERSION=3 ROS_DISTRO=Debian ROS_HOME="$WORK/ros_home"
if getent hosts localhost > /dev/null 2>&1; then host=localhost; else host=127.0.0.1; fi
export ROS_MASTER_URI="http://$host:11311" ROS_HOSTNAME="$host"
set +u; source "$PREFIX/setup.bash"; set -u
export ROS_PACKAGE_PATH="$PREFIX/share:/usr/share"
fail() { echo "check_install: FAILED: $*" >&2; exit 1; }

found="$(rospack find doorplate_localization)" || fail "rospack does not find doorplate_localization"
[ "$found" = "$PREFIX/share/doorplate_localization" ] || fail "rospack finds $found, not $PREFIX/share/doorplate_localization"
echo "   rospack: $found"

bin="$PREFIX/lib/doorplate_localization"
n=0
for tool in "$bin"/doorplate_*; do
  [ -x "$tool" ] || continue
  rc=0; out="$(timeout 20 "$tool" --help 2>&1)" || rc=$?
  [ "$rc" = 0 ] || fail "$(basename "$tool") --help exited $rc: $out"
  echo "$out" | grep -qi "usage" || fail "$(basename "$tool") --help printed no usage: $out"
  n=$((n + 1))
done
[ "$n" -ge 5 ] || fail "only $n tools installed in $bin"
echo "   $n installed tools answer --help"

share="$PREFIX/share/doorplate_localization"
"$bin/doorplate_world_maps" --world "$share/worlds/paper_real_corridor.yaml" --out "$WORK/corridor" > "$WORK/maps.log" 2>&1 \
  || fail "doorplate_world_maps on the installed world: $(cat "$WORK/maps.log")"
[ -s "$WORK/corridor.pgm" ] && [ -s "$WORK/corridor.text_map.yaml" ] || fail "doorplate_world_maps wrote no maps"
echo "   doorplate_world_maps made maps of the installed world"

roslaunch doorplate_localization demo.launch rviz:=false real_time_factor:=5 > "$WORK/demo.log" 2>&1 &
launch=$!
trap "kill -INT $launch 2>/dev/null; wait $launch 2>/dev/null || true" EXIT
deadline=$((SECONDS + TIMEOUT_S)); state=""
while [ $SECONDS -lt $deadline ]; do
  kill -0 $launch 2>/dev/null || fail "roslaunch exited: $(tail -n 30 "$WORK/demo.log")"
  state="$(timeout -k 1 10 rostopic echo -n 1 -p /amcl/state 2>/dev/null | tail -n 1 | cut -d, -f2- || true)"
  [ "$state" = converged ] && break
  sleep 2
done
[ "$state" = converged ] || fail "demo.launch from the install space did not converge within $TIMEOUT_S s (state: $state): $(tail -n 30 "$WORK/demo.log")"
grep -q "Failed to load nodelet" "$WORK/demo.log" && fail "a nodelet failed to load: $(grep -A3 "Failed to load" "$WORK/demo.log")"
echo "   demo.launch from the install space: every nodelet loaded, /amcl/state converged"
'
echo "== install: OK ($prefix)"
