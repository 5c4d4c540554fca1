#!/usr/bin/env bash
# Table II runs (docs/results/table2-map.md): 10 seeds x {rbpf, rbpf_text} on paper_real_corridor, JSON per
# run into this folder, the maps of rbpf_text seed 1 into paper_real_corridor_rbpf_text_seed1/.
# Usage: docs/results/table2-map/run.sh [BUILD_DIR]; then python3 docs/results/table2-map/summarize.py
set -u
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
OUT=docs/results/table2-map
for seed in 1 2 3 4 5 6 7 8 9 10; do
  "$E" map --world worlds/paper_real_corridor.yaml --method rbpf --seed $seed \
    --json $OUT/paper_real_corridor_rbpf_seed$seed.json
  extra=""
  [ $seed = 1 ] && extra="--out-dir $OUT/paper_real_corridor_rbpf_text_seed1"
  "$E" map --world worlds/paper_real_corridor.yaml --method rbpf_text --seed $seed \
    --json $OUT/paper_real_corridor_rbpf_text_seed$seed.json $extra
done
