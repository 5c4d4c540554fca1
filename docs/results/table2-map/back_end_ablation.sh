#!/usr/bin/env bash
# What each part of the pose-graph back end does on paper_real_corridor (docs/slam.md "Back end"): the
# laser filter with the degeneracy-aware proposal (the rbpf_text filter), without and with the back end
# and its parts, 10 seeds each. The camera is left out (--method rbpf + the text filter's options): in this
# sweep every plate is read once, so the plates do not move the trajectory and these runs take seconds.
# Usage: docs/results/table2-map/back_end_ablation.sh [BUILD_DIR] > docs/results/table2-map/back_end_ablation.txt
set -u
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
base="degenerate_min_points=10"
declare -A variants=(
  [1_filter_only]="$base,back_end.enabled=0"
  [2_back_end_without_scale]="$base,back_end.enabled=1,back_end.graph.estimate_odometry_scale=0"
  [3_back_end_normals_from_2_neighbours]="$base,back_end.enabled=1,back_end.icp.normal_neighbours=2"
  [4_back_end_without_loop_closures]="$base,back_end.enabled=1,back_end.loop_closure_radius_m=0"
  [5_back_end_full]="$base,back_end.enabled=1"
)
tmp=$(mktemp -d)
for name in $(printf '%s\n' "${!variants[@]}" | sort); do
  for seed in 1 2 3 4 5 6 7 8 9 10; do
    "$E" map --world worlds/paper_real_corridor.yaml --method rbpf --seed $seed --set "${variants[$name]}" \
      --json "$tmp/$name.$seed.json" > /dev/null
  done
  python3 - "$tmp" "$name" <<'PY'
import json, sys, glob
tmp, name = sys.argv[1], sys.argv[2]
runs = [json.load(open(f)) for f in sorted(glob.glob(f"{tmp}/{name}.*.json"))]
acc = [100 * r["length_accuracy"] for r in runs]
fin = [r["final_position_error_m"] for r in runs]
traj = [r["trajectory_max_error_m"] for r in runs]
build = [r["map_build_seconds"] for r in runs]
scale = [r["back_end_odometry_scale"] for r in runs]
print(f"{name}: length accuracy min {min(acc):.2f} mean {sum(acc)/len(acc):.2f} max {max(acc):.2f} % "
      f"({sum(a >= 99.5 for a in acc)}/{len(acc)} >= 99.5 %); trajectory max error {min(traj):.2f}-{max(traj):.2f} m; "
      f"final pose error max {max(fin):.3f} m; "
      f"odometry scale {min(scale):.4f}-{max(scale):.4f} (true 1/1.02 = 0.9804); "
      f"final maps built in {min(build):.2f}-{max(build):.2f} s CPU")
PY
done
rm -rf "$tmp"
