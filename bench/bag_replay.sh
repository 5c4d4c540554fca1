#!/bin/bash
# The recorded-bag check of issue 16: one mapping bag through the mapping nodelet (rosbag play --clock,
# ROS time, the nodelet as users run it) and through the offline tool doorplate_map_bag (the same
# MappingSession), same filter seed; prints how far each plate of the two text maps and each pose of the two
# trajectories lie apart and exits 1 when one is farther than --tolerance-m (default 0.01 m) or
# --tolerance-deg (0.5), or the plate sets or processed scans differ.
# Usage: bench/bag_replay.sh BUILD BAG [--seed N] [--tolerance-m M] [--tolerance-deg D] [--out DIR]
#   BAG: a mapping bag as scripts/demo.sh records it (results/demo/mapping.bag: scan, tf, tf_static,
#   text_detections, ...). Needs a free ROS master port 11411.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
build="$(cd "$1" && pwd)"; bag="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2
seed=1; tol=0.01; tol_deg=0.5; out="$(mktemp -d /tmp/bag_replay.XXXXXX)"
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2;;
    --tolerance-m) tol="$2"; shift 2;;
    --tolerance-deg) tol_deg="$2"; shift 2;;
    --out) out="$2"; shift 2;;
    *) echo "bag_replay: unknown argument $1" >&2; exit 2;;
  esac
done
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../scripts/env.sh" "$build" >/dev/null
mkdir -p "$out"
echo "== offline: doorplate_map_bag (seed $seed)"
"$build/devel/lib/doorplate_localization/doorplate_map_bag" "$bag" --out-dir "$out/offline" --seed "$seed" \
  --progress-s 0 2> "$out/offline.log"
echo "== nodelet: rosbag play --clock at 1x (log: $out/replay.log)"
ROS_HOME="$out/ros_home" roslaunch -p 11411 "$here/bag_replay.launch" bag:="$bag" out:="$out/replay" \
  seed:="$seed" > "$out/replay.log" 2>&1
/usr/bin/python3 - "$out/offline" "$out/replay" "$tol" "$tol_deg" <<'PY'
import math, sys, yaml
off, rep, tol, tol_deg = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
a = {l["text"]: l for l in yaml.safe_load(open(off + "/map.text_map.yaml"))["landmarks"]}
b = {l["text"]: l for l in yaml.safe_load(open(rep + "/map.text_map.yaml"))["landmarks"]}
common = sorted(set(a) & set(b))
d = {t: math.hypot(a[t]["x_m"] - b[t]["x_m"], a[t]["y_m"] - b[t]["y_m"]) for t in common}
print(f"plates: offline {len(a)}, nodelet {len(b)}, both {len(common)}")
for t in common: print(f"  {t}: {d[t]:.4f} m")
worst = max(d.values(), default=0.0)
print(f"plates: max {worst:.4f} m, median {sorted(d.values())[len(d)//2] if d else 0:.4f} m (tolerance {tol} m)")
def traj(path):
    return {int(f[0]): tuple(map(float, f[1:4])) for f in (l.split() for l in open(path)) if f}
ta, tb = traj(off + "/trajectory.txt"), traj(rep + "/map.trajectory.txt")
both = sorted(set(ta) & set(tb))
dp = max((math.hypot(ta[k][0] - tb[k][0], ta[k][1] - tb[k][1]) for k in both), default=0.0)
da = max((abs(math.degrees(math.remainder(ta[k][2] - tb[k][2], 2 * math.pi))) for k in both), default=0.0)
print(f"trajectory: offline {len(ta)} poses, nodelet {len(tb)}, both {len(both)}; max {dp:.4f} m, {da:.3f} deg "
      f"(tolerance {tol} m, {tol_deg} deg)")
ok = set(a) == set(b) and worst <= tol and set(ta) == set(tb) and dp <= tol and da <= tol_deg
sys.exit(0 if ok else 1)
PY
