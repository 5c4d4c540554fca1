#!/usr/bin/env bash
# Whole-floor mapping runs (issue 17, docs/results/floor-map.md): the ring world explored by FloorExplorer,
# rbpf_text for seeds 1-10 and the laser-only filter (same drive: the extractor still runs for the explorer)
# for seeds 1-3; JSON per run into this folder, the maps of rbpf_text seed 1 into ring_rbpf_text_seed1/.
# Usage: docs/results/floor-map/run.sh [BUILD_DIR] [SEEDS...]; then python3 docs/results/floor-map/summarize.py
# (each run drives ~325 m and reads every camera frame: 5-10 minutes on one core of the 2-core machine).
set -u
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
shift || true
SEEDS="${*:-1 2 3 4 5 6 7 8 9 10}"
OUT=docs/results/floor-map
export OMP_THREAD_LIMIT=1
for seed in $SEEDS; do
  extra=""
  [ "$seed" = 1 ] && extra="--out-dir $OUT/ring_rbpf_text_seed1"
  "$E" map --world worlds/hospital_floor_ring.yaml --method rbpf_text --seed "$seed" --progress-s 0 \
    --json "$OUT/ring_rbpf_text_seed$seed.json" $extra
done
for seed in $SEEDS; do
  [ "$seed" -le 3 ] || continue
  "$E" map --world worlds/hospital_floor_ring.yaml --method rbpf --seed "$seed" --progress-s 0 \
    --json "$OUT/ring_rbpf_seed$seed.json"
done
