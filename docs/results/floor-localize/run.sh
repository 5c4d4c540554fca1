#!/usr/bin/env bash
# Floor localization runs (docs/results/floor-localize.md): global localization from random poses in any
# corridor of worlds/hospital_floor_ring.yaml (start poses over its `corridors`, contour drive), Text AMCL
# and the laser-only baseline, JSON and printed summary (.log) into this folder.
# Usage: docs/results/floor-localize/run.sh [BUILD_DIR]   (TRIALS=n: the first n trials only)
set -eu
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
TRIALS="${TRIALS:-30}"
OUT=docs/results/floor-localize
W=worlds/hospital_floor_ring.yaml
export OMP_THREAD_LIMIT=1
"$E" localize --world $W --trials "$TRIALS" --seed 1 --json $OUT/ring_text_amcl.json | tee $OUT/ring_text_amcl.log
"$E" localize --world $W --method amcl --trials "$TRIALS" --seed 1 --json $OUT/ring_amcl.json | tee $OUT/ring_amcl.log
"$E" localize --world $W --trials "$TRIALS" --seed 1 --camera-hz 15 \
  --json $OUT/ring_text_amcl_15hz.json | tee $OUT/ring_text_amcl_15hz.log
"$E" localize --world $W --kidnap --trials "$TRIALS" --seed 1 \
  --json $OUT/ring_text_amcl_kidnap.json | tee $OUT/ring_text_amcl_kidnap.log
"$E" localize --world $W --trials 60 --seed 2 --camera-hz 15 \
  --json $OUT/ring_text_amcl_seed2_15hz.json | tee $OUT/ring_text_amcl_seed2_15hz.log
