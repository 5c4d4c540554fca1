#!/usr/bin/env bash
# The main job: builds the package and runs the whole simulated mission headless on the paper's 43.5 m
# corridor, at 5x real time, then writes a report to results/demo/:
#   1. mapping (launch/mapping.launch): the robot sweeps the corridor (out along one wall, turn, back) while
#      the RBPF SLAM maps it and the text extractor reads the plates; the maps are saved (map_server PGM +
#      YAML and the text-landmark map) into results/demo/maps/;
#   2. localization (launch/localization.launch): the robot is put somewhere else, unknown to the localizer;
#      Text AMCL starts with global localization on the saved maps while the robot patrols until it has
#      read plates and converged; then the patrol stops and the robot is sent to a room by number
#      (go_to_room) and drives there;
#   3. report (doorplate_mission_report): report.md with the plates read, the map's length / width
#      accuracy and plate errors, the localization and go-to-room errors beside the paper's figures, the
#      pictures (map.png: the map folded into segments with plates, paths and magnified plate errors;
#      plate_errors.png; localization.png: the particles' spread against travel), and the commands that
#      reproduce the full tables.
# It builds only the demo's targets (scripts/build.sh --demo) and shows each phase's progress
# (scripts/mission_progress.py: metres driven and plates read, the particles' spread, the distance left).
# A world that lists more than one corridor (`corridors:`, e.g. worlds/hospital_floor_ring.yaml) runs the
# floor mode: mapping explores the whole floor (FloorExplorer), localization searches by following one wall
# wherever it leads (roam) and go-to-room plans a path over the saved map round corners (route grid), at 2x
# real time; the default start is the middle of the corridor farthest from the world's start.
# Usage: scripts/demo.sh [--world FILE] [--seed N] [--room TEXT] [--start "X Y THETA_DEG"] [--timeout-s S]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
world="$repo/worlds/paper_real_corridor.yaml"; seed=1; room=207; start=""; timeout_s=""
usage() { echo "usage: scripts/demo.sh [--world FILE] [--seed N] [--room TEXT] [--start \"X Y THETA_DEG\"] [--timeout-s S]" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --world) world="$2"; shift 2;;
    --seed) seed="$2"; shift 2;;
    --room) room="$2"; shift 2;;
    --start) start="$2"; shift 2;;
    --timeout-s) timeout_s="$2"; shift 2;;
    *) usage;;
  esac
done
[ -f "$world" ] || { echo "demo: --world $world: no such file" >&2; exit 2; }
world="$(cd "$(dirname "$world")" && pwd)/$(basename "$world")"  # roslaunch's nodes run in ROS_HOME
# Floor mode: how many corridors the world lists, and a start pose in the one farthest from the world's start.
floor_info=$(/usr/bin/python3 - "$world" <<'PY'
import math, sys, yaml
w = yaml.safe_load(open(sys.argv[1]))
cs = w.get("corridors") or []
s = w["robot"]["start"]
def mid(c): return [(a + b) / 2 for a, b in zip(c["from"], c["to"])]
far = max(cs, key=lambda c: math.dist(mid(c), [s["x_m"], s["y_m"]]), default=None)
start = "" if far is None else "%.2f %.2f %.0f" % (*mid(far), math.degrees(math.atan2(far["to"][1] - far["from"][1], far["to"][0] - far["from"][0])))
print(len(cs), start)
PY
) || { echo "cannot read $world" >&2; exit 2; }
read -r n_corridors floor_start <<< "$floor_info"
floor=false; [ "$n_corridors" -gt 1 ] && floor=true
if $floor; then
  rtf=2; [ -n "$start" ] || start="$floor_start"; [ -n "$timeout_s" ] || timeout_s=2400
  mapping_drive="explore:=true"
else
  rtf=5; [ -n "$start" ] || start="30.0 1.25 180"; [ -n "$timeout_s" ] || timeout_s=900
  mapping_drive="sweep:=true"
fi
read -r start_x start_y start_theta <<< "$start"
[ -n "${start_theta:-}" ] || usage
build="${DOORPLATE_BUILD:-$repo/build}"   # where scripts/build.sh builds
echo "== 0/3 build (only the demo's targets; scripts/test.sh builds everything)"
bash "$repo/scripts/build.sh" --demo "$build"
source "$repo/scripts/env.sh" "$build"
out="$repo/results/demo"; maps="$out/maps"
rm -rf "$out"; mkdir -p "$maps"

launch_pid=""
stop_launch() {
  [ -n "$launch_pid" ] || return 0
  kill -INT "$launch_pid" 2>/dev/null || true; wait "$launch_pid" 2>/dev/null || true; launch_pid=""
}
trap stop_launch EXIT

# wait_for PHASE TOPIC PATTERN WHAT LOG [CSV]: shows the phase's progress (scripts/mission_progress.py: a line
# rewritten in place on a terminal, a plain line every 15 s otherwise) until the latched std_msgs/String TOPIC
# matches the extended regex PATTERN; the matching value is left in $matched. Fails, with the log's end, if
# roslaunch exits first or nothing matches within $timeout_s.
matched=""
wait_for() {
  local phase="$1" topic="$2" pattern="$3" what="$4" log="$5" csv="${6:-}" rc=0
  matched=$(/usr/bin/python3 "$repo/scripts/mission_progress.py" --phase "$phase" --until "$topic" "$pattern" \
    --timeout-s "$timeout_s" --pid "$launch_pid" ${csv:+--csv "$csv"}) || rc=$?
  case "$rc" in
    0) echo "   $topic: $matched";;
    3) echo "roslaunch exited early:"; tail -n 30 "$log"; exit 1;;
    4) echo "$what did not happen within ${timeout_s} s ($topic: $matched)"; tail -n 30 "$log"; exit 1;;
    *) echo "the progress monitor failed (exit $rc)"; tail -n 30 "$log"; exit 1;;
  esac
}

# What the mapping drive did: the follower's states with their sim times (from the launch log) and the plates
# of the saved text map (a drive that ended early, e.g. "done" without a way back, shows here, not only as a
# missing room later). Lines of several nodelets can interleave in the log: a state without its stamp gets "?".
drive_summary() {
  /usr/bin/python3 - "$out/mapping.log" "$maps/map.text_map.yaml" <<'PY'
import re, sys, yaml
log = open(sys.argv[1], errors="replace").read()
states = re.findall(r"(?:\[ INFO\] \[[0-9.]+, ([0-9.]+)\]: )?corridor following: ([a-z_0-9]+)", log)
plates = [l["text"] for l in (yaml.safe_load(open(sys.argv[2])) or {}).get("landmarks") or []]
print("   drive: " + ", ".join("%s %s" % (name, "%.1f s" % float(t) if t else "?") for t, name in states))
print("   text map: %d plates: %s" % (len(plates), " ".join(sorted(plates))))
PY
}

echo "== 1/3 mapping $(basename "$world") with text, seed $seed (log: $out/mapping.log)"
roslaunch doorplate_localization mapping.launch world:="$world" seed:="$seed" slam_seed:="$seed" $mapping_drive \
  real_time_factor:=$rtf map_output_dir:="$maps" bag:="$out/mapping.bag" > "$out/mapping.log" 2>&1 &
launch_pid=$!
wait_for mapping /corridor_follower/state '^done$' "the mapping drive" "$out/mapping.log"
rosservice call /slam_mapping/save_maps | tee "$out/save_maps.txt"
grep -q "success: True" "$out/save_maps.txt" || { echo "saving the maps failed"; exit 1; }
stop_launch
drive_summary  # after roslaunch has ended: its output reaches the log late

echo "== 2/3 localization from an unknown pose ($start_x, $start_y, $start_theta deg), then go to room $room"
roslaunch doorplate_localization localization.launch world:="$world" seed:="$seed" filter_seed:="$seed" \
  map_file:="$maps/map.yaml" text_map_file:="$maps/map.text_map.yaml" real_time_factor:=$rtf floor:=$floor \
  start_x_m:="$start_x" start_y_m:="$start_y" start_theta_deg:="$start_theta" bag:="$out/localization.bag" \
  > "$out/localization.log" 2>&1 &
launch_pid=$!
wait_for localization /amcl/state '^converged' "global localization" "$out/localization.log" \
  "$out/particle_spread.csv"
rosservice call /corridor_follower/enable false > /dev/null
rostopic pub -1 /go_to_room std_msgs/String "data: '$room'" > /dev/null
wait_for go_to_room /go_to_room/status '^(arrived|refused|failed)' "reaching room $room" "$out/localization.log" \
  "$out/particle_spread.csv"
status="$matched"
sleep 2  # let the recorder write the last messages
stop_launch; trap - EXIT
[[ "$status" == arrived* ]] || { echo "go to room $room: $status"; exit 1; }

echo "== 3/3 report"
"$build/devel/lib/doorplate_localization/doorplate_mission_report" --world "$world" --maps "$maps" \
  --mapping-bag "$out/mapping.bag" --localization-bag "$out/localization.bag" --room "$room" --out "$out" \
  --particle-spread "$out/particle_spread.csv" --title "Simulated mission on $(basename "$world" .yaml), seed $seed"
cat "$out/report.md"
