#!/usr/bin/env bash
# Table II runs (docs/results/table2-map.md): 10 seeds x {rbpf, rbpf_text} on the three corridors, JSON per
# run into this folder, the maps of rbpf_text seed 1 into <world>_rbpf_text_seed1/.
# Usage: docs/results/table2-map/run.sh [BUILD_DIR]; then python3 docs/results/table2-map/summarize.py
# (rbpf_text runs render and read every camera frame: 2-8 minutes each on the 43.5 m corridor.)
set -u
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
OUT=docs/results/table2-map
for world in paper_real_corridor paper_sim_closed_doors paper_sim_open_doors; do
  for seed in 1 2 3 4 5 6 7 8 9 10; do
    "$E" map --world worlds/$world.yaml --method rbpf --seed $seed --json $OUT/${world}_rbpf_seed$seed.json
    extra=""
    [ $seed = 1 ] && extra="--out-dir $OUT/${world}_rbpf_text_seed1"
    "$E" map --world worlds/$world.yaml --method rbpf_text --seed $seed \
      --json $OUT/${world}_rbpf_text_seed$seed.json $extra
  done
done
