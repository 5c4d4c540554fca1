#!/usr/bin/env bash
# Table II on the realistic corridor (issue 20; docs/results/table2-map.md, "Realistic corridor"): 10 seeds x
# {rbpf, rbpf_text} on worlds/paper_real_corridor_realistic.yaml, two runs at a time, JSON per run into this
# folder, the maps of both methods' seed 1 into paper_real_corridor_realistic_<method>_seed1/.
# Usage: docs/results/table2-map/run_realistic.sh [BUILD_DIR]; then python3 docs/results/table2-map/summarize.py
set -u
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
OUT=docs/results/table2-map
world=paper_real_corridor_realistic
run() {  # run METHOD SEED
  local extra=""
  [ "$2" = 1 ] && extra="--out-dir $OUT/${world}_$1_seed1"
  "$E" map --world worlds/$world.yaml --method "$1" --seed "$2" --json "$OUT/${world}_$1_seed$2.json" $extra > /dev/null
}
for seed in 1 2 3 4 5 6 7 8 9 10; do run rbpf $seed; done
for pair in "1 2" "3 4" "5 6" "7 8" "9 10"; do
  set -- $pair
  run rbpf_text "$1" & run rbpf_text "$2" & wait
done
