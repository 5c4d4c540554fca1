#!/usr/bin/env bash
# The main job: builds the package, then runs the simulated corridor demo headless on the paper's
# 43.5 m corridor (launch/demo.launch) at 5x real time, and writes a report of the run to
# results/demo/ (report.md, trajectory.png, camera_mid_run.png).
# Usage: scripts/demo.sh [--world FILE] [--seed N] [--timeout-s S]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
world="$repo/worlds/paper_real_corridor.yaml"; seed=1; timeout_s=600
while [ $# -gt 0 ]; do
  case "$1" in
    --world) world="$2"; shift 2;;
    --seed) seed="$2"; shift 2;;
    --timeout-s) timeout_s="$2"; shift 2;;
    *) echo "usage: scripts/demo.sh [--world FILE] [--seed N] [--timeout-s S]" >&2; exit 2;;
  esac
done
build="${DOORPLATE_BUILD:-$repo/build}"   # where scripts/build.sh builds
bash "$repo/scripts/build.sh" "$build"
source "$repo/scripts/env.sh" "$build"
out="$repo/results/demo"; mkdir -p "$out"
bag="$out/corridor_run.bag"; rm -f "$bag" "$bag.active"
log="$out/roslaunch.log"

echo "== demo: corridor following on $(basename "$world"), seed $seed (log: $log)"
# 5x real time: fast, yet the control loop's latency stays a few simulated milliseconds.
roslaunch doorplate_localization demo.launch world:="$world" seed:="$seed" real_time_factor:=5 \
  bag:="$bag" > "$log" 2>&1 &
launch_pid=$!
cleanup() { kill -INT "$launch_pid" 2>/dev/null || true; wait "$launch_pid" 2>/dev/null || true; }
trap cleanup EXIT

# Wait for the robot to reach the corridor's end (the follower latches its state), at most timeout_s.
deadline=$((SECONDS + timeout_s)); state=""
while [ $SECONDS -lt $deadline ]; do
  state=$(timeout 5 rostopic echo -n 1 -p /corridor_follower/state 2>/dev/null | tail -n 1 | cut -d, -f2 || true)
  [ "$state" = "end_reached" ] && break
  kill -0 "$launch_pid" 2>/dev/null || { echo "roslaunch exited early:"; tail -n 30 "$log"; exit 1; }
  sleep 1
done
[ "$state" = "end_reached" ] || { echo "the robot did not reach the corridor end in ${timeout_s} s (state: $state)"; tail -n 30 "$log"; exit 1; }
echo "== the robot reached the end of the corridor; stopping"
cleanup; trap - EXIT
"$build/devel/lib/doorplate_localization/doorplate_run_report" --bag "$bag" --world "$world" --out "$out" \
  --title "Corridor following on $(basename "$world" .yaml), seed $seed"
cat "$out/report.md"
