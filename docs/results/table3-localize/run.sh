#!/usr/bin/env bash
# Table III runs (docs/results/table3-localize.md): per world, amcl (laser only) and text_amcl with kidnaps,
# 30 trials, seed 1, JSON and printed summary (.log) into this folder. Both methods run the filter through
# TextAmclSession, the loop the Text AMCL nodelet runs.
# Usage: docs/results/table3-localize/run.sh [BUILD_DIR] [WORLD...]
#   (default: build; paper_real_corridor paper_sim_closed_doors hospital_ward). TRIALS=n runs the first n
#   trials only (trial i has the same seed whatever n is, so they are the first n rows of a 30-trial run).
# text_amcl renders and reads every camera frame (15 Hz): 4-18 minutes per world on a loaded 2-core machine.
set -eu
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
shift || true
WORLDS="${*:-paper_real_corridor paper_sim_closed_doors hospital_ward}"
TRIALS="${TRIALS:-30}"
OUT=docs/results/table3-localize
export OMP_THREAD_LIMIT=1
for world in $WORLDS; do
  "$E" localize --world worlds/$world.yaml --method amcl --trials "$TRIALS" --seed 1 \
    --json $OUT/${world}_amcl.json | tee $OUT/${world}_amcl.log
  "$E" localize --world worlds/$world.yaml --method text_amcl --kidnap --trials "$TRIALS" --seed 1 \
    --camera-hz 15 --json $OUT/${world}_text_amcl_kidnap.json | tee $OUT/${world}_text_amcl_kidnap.log
done
