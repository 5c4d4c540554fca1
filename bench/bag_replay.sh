#!/bin/bash
# The recorded-bag check of issue 16: one mapping bag through the mapping nodelet (rosbag play --clock,
# ROS time, the nodelet as users run it) and through the offline tool doorplate_map_bag (the same
# MappingSession), same filter seed; prints how far each plate of the two text maps lies apart and exits 1
# when one is farther than --tolerance-m (default 0.01 m) or the plate sets differ.
# Usage: bench/bag_replay.sh BUILD BAG [--seed N] [--tolerance-m M] [--out DIR]
#   BAG: a mapping bag as scripts/demo.sh records it (results/demo/mapping.bag: scan, tf, tf_static,
#   text_detections, ...). Needs a free ROS master port 11411.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
build="$(cd "$1" && pwd)"; bag="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2
seed=1; tol=0.01; out="$(mktemp -d /tmp/bag_replay.XXXXXX)"
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2;;
    --tolerance-m) tol="$2"; shift 2;;
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
/usr/bin/python3 - "$out/offline/map.text_map.yaml" "$out/replay/map.text_map.yaml" "$tol" <<'PY'
import math, sys, yaml
a = {l["text"]: l for l in yaml.safe_load(open(sys.argv[1]))["landmarks"]}
b = {l["text"]: l for l in yaml.safe_load(open(sys.argv[2]))["landmarks"]}
tol = float(sys.argv[3])
common = sorted(set(a) & set(b))
d = {t: math.hypot(a[t]["x_m"] - b[t]["x_m"], a[t]["y_m"] - b[t]["y_m"]) for t in common}
print(f"plates: offline {len(a)}, nodelet {len(b)}, both {len(common)}")
for t in common: print(f"  {t}: {d[t]:.4f} m")
worst = max(d.values(), default=0.0)
print(f"max {worst:.4f} m, median {sorted(d.values())[len(d)//2] if d else 0:.4f} m (tolerance {tol} m)")
sys.exit(0 if set(a) == set(b) and worst <= tol else 1)
PY
