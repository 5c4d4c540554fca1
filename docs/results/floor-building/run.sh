#!/usr/bin/env bash
# Several floors (issue 17 item 5, docs/results/floor-building.md): global localization on the two-floor
# hospital from an unknown floor (text_amcl and laser-only amcl), kidnaps that are lift rides the filter is
# not told of, and go to a room on the other floor by lift. JSON and printed summaries into this folder.
# Usage: docs/results/floor-building/run.sh [BUILD_DIR]   (about 20 + 25 + 3 + 60 minutes on one core)
set -eu
cd "$(dirname "$0")/../../.."
E="${1:-build}/devel/lib/doorplate_localization/doorplate_eval"
OUT=docs/results/floor-building
B=worlds/hospital_two_floors.building.yaml
export OMP_THREAD_LIMIT=1
"$E" localize --building $B --trials 30 --seed 1 --json $OUT/two_floors_text_amcl.json | tee $OUT/two_floors_text_amcl.log
"$E" localize --building $B --trials 30 --seed 2 --kidnap --json $OUT/two_floors_text_amcl_kidnap.json \
  | tee $OUT/two_floors_text_amcl_kidnap.log
"$E" localize --building $B --method amcl --trials 30 --seed 1 --json $OUT/two_floors_amcl.json | tee $OUT/two_floors_amcl.log
"$E" goto --building $B --trials 30 --seed 1 --camera-hz 10 --json $OUT/two_floors_goto.json | tee $OUT/two_floors_goto.log
