#!/usr/bin/env bash
# The simulated laser fitted to real laser logs (issue 20, docs/results/laser-model.md): doorplate_laser_fit on
# the four shared CARMEN logs (statistics, fitted parameters, real vs simulated distances) into this folder,
# then the simulator's laser real-time factor with the gaussian and the fitted error model, three runs.
# Usage: docs/results/laser-model/run.sh [BUILD_DIR]   (about 10 s for the fit, 3 x 1 min for the bench)
set -eu
cd "$(dirname "$0")/../../.."
BIN="${1:-build}/devel/lib/doorplate_localization"
LOGS=/work/shared/data/carmen
OUT=docs/results/laser-model
"$BIN/doorplate_laser_fit" --log "$LOGS/intel-corrected.log.gz" --log "$LOGS/aces-corrected.log.gz" \
  --log "$LOGS/freiburg-079-corrected.log.gz" --log "$LOGS/csail-corrected.log.gz" --seed 1 \
  --json "$OUT/laser_fit.json" --plot "$OUT/laser_fit.png" | tee "$OUT/laser_fit.txt"
for run in 1 2 3; do
  "$BIN/doorplate_sim_bench" --seconds 300 --seed 1 | tee "$OUT/sim_bench_run$run.txt"
done
