#!/usr/bin/env bash
# The nodelet soak (issue 18): the localization and mapping nodelets run as the demo runs them
# (bench/nodelet_soak.launch: localization.launch with the localizer in its own manager, the mapping nodelet
# beside it in another) in the simulated corridor at a real-time factor > 1, while bench/nodelet_soak.py
# kidnaps the robot, sends bad messages (NaN/inf scans, a scan of 10 ranges whose angles say 360, a 1 MB
# detection text, an all-occupied map to set_map), swaps the map (set_map with the good map), samples the
# managers' resident memory, and checks recovery, the state topic, /diagnostics and memory growth.
# Writes OUT/{launch.log,driver.log,rss.csv,events.json,summary.json}; exits with the driver's status.
# Usage: bench/nodelet_soak.sh [--sim-s S (3600)] [--cycle-s S (300)] [--rtf F (2)] [--seed N (1)]
#                              [--out DIR (results/nodelet_soak)] [--build DIR]
#                              [--slam-prefix CMD (run the mapper's manager under CMD, e.g. "heaptrack -o F":
#                               the memory check then reads CMD's process, not the manager's)]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
sim_s=3600; cycle_s=300; rtf=2; seed=1; out="$repo/results/nodelet_soak"; build="${DOORPLATE_BUILD:-$repo/build}"; slam_prefix=""
while [ $# -gt 0 ]; do
  case "$1" in
    --sim-s) sim_s="$2"; shift 2;;
    --cycle-s) cycle_s="$2"; shift 2;;
    --rtf) rtf="$2"; shift 2;;
    --seed) seed="$2"; shift 2;;
    --out) out="$2"; shift 2;;
    --build) build="$2"; shift 2;;
    --slam-prefix) slam_prefix="$2"; shift 2;;
    *) sed -n '2,12p' "$0"; exit 2;;
  esac
done
source "$repo/scripts/env.sh" "$build" > /dev/null
# A master of its own on a free port, so the soak does not meet another ROS graph on this machine.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_HOSTNAME=127.0.0.1
export ROS_HOME="$out/ros_home"
rm -rf "$out"; mkdir -p "$ROS_HOME"
roslaunch -p "$port" "$repo/bench/nodelet_soak.launch" real_time_factor:="$rtf" seed:="$seed" \
  slam_manager_prefix:="$slam_prefix" > "$out/launch.log" 2>&1 &
launch_pid=$!
stop() { kill -INT "$launch_pid" 2>/dev/null || true; wait "$launch_pid" 2>/dev/null || true; }
trap stop EXIT
# The managers roslaunch started (its children), by their node names.
pids=()
for name in doorplate_manager amcl_manager slam_manager; do
  pid=""
  for _ in $(seq 120); do
    pid=$(pgrep -P "$launch_pid" -f "__name:=$name( |$)" | head -n 1 || true)
    [ -n "$pid" ] && break
    kill -0 "$launch_pid" 2>/dev/null || { tail -n 30 "$out/launch.log"; exit 1; }
    sleep 0.5
  done
  [ -n "$pid" ] || { echo "nodelet_soak: no process of $name"; tail -n 30 "$out/launch.log"; exit 1; }
  pids+=(--pid "$name=$pid")
done
echo "nodelet_soak: master on port $port, managers ${pids[*]}, ${sim_s} sim s at rtf $rtf; logs in $out"
status=0
python3 "$repo/bench/nodelet_soak.py" --duration-s "$sim_s" --cycle-s "$cycle_s" --seed "$seed" --out "$out" \
  "${pids[@]}" 2>&1 | tee "$out/driver.log" || status=$?
exit "$status"
