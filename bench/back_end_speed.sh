#!/usr/bin/env bash
# The SLAM back end's solve time over an hour's patrol (docs/results/back-end-speed.md): `doorplate_eval map
# --drive patrol` of the paper's corridor, laser-only filter with the back end, a solve every 300 simulated
# seconds as the mapping nodelet's ~map_update_interval would (without its wall-clock share: deterministic),
# run three ways in this one script run so the ratios compare like with like:
#   reference_blas_fine_stop  Debian's reference BLAS (libblas3) and the pose graph stopping at 1e-7 steps
#                             (the back end before 2026-12-07, but with its alignment memo)
#   reference_blas            Debian's reference BLAS, the default stop (0.1 mm / 1e-5 rad)
#   installed                 the BLAS update-alternatives selects (scripts/install_deps.sh installs OpenBLAS,
#                             serial) and the default stop: what ships
# and with --before-build DIR a fourth, first: `before`, that build's doorplate_eval (the back end of another
# commit; it needs `map --drive patrol --map-update-interval-s`) on the reference BLAS.
# The reference BLAS is chosen with LD_LIBRARY_PATH (its own folder under the multiarch lib dir); without
# libblas3 installed the reference runs are skipped, saying so.
# Usage: bench/back_end_speed.sh BUILD_DIR [--sim-s 3600] [--seed 1] [--out docs/results/back-end-speed]
#        [--before-build DIR]
set -euo pipefail
build=${1:?usage: bench/back_end_speed.sh BUILD_DIR [--sim-s S] [--seed N] [--out DIR]}
shift
sim_s=3600 seed=1 out=docs/results/back-end-speed before=""
while [ $# -gt 0 ]; do
  case "$1" in
    --sim-s) sim_s=$2; shift 2;;
    --seed) seed=$2; shift 2;;
    --out) out=$2; shift 2;;
    --before-build) before=$2; shift 2;;
    *) echo "back_end_speed: unknown option $1" >&2; exit 2;;
  esac
done
here=$(cd "$(dirname "$0")/.." && pwd)
eval_bin=$build/devel/lib/doorplate_localization/doorplate_eval
[ -x "$eval_bin" ] || { echo "back_end_speed: no $eval_bin (build the package first)" >&2; exit 1; }
mkdir -p "$out"
multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
ref_blas=/usr/lib/$multiarch/blas ref_lapack=/usr/lib/$multiarch/lapack
run() {  # name, extra env (LD_LIBRARY_PATH=... or ""), --set list[, doorplate_eval]
  local name=$1 env_ld=$2 sets=$3 bin=${4:-$eval_bin}
  echo "back_end_speed: $name ($(date -u +%H:%M:%S) UTC)"
  env ${env_ld:+LD_LIBRARY_PATH=$env_ld} "$bin" map \
    --world "$here/worlds/paper_real_corridor.yaml" --method rbpf --drive patrol --max-seconds "$sim_s" \
    --map-update-interval-s 300 --seed "$seed" --progress-s 0 --set "back_end.enabled=1$sets" \
    --json "$out/$name.json" > "$out/$name.txt" 2>&1
  tail -n 2 "$out/$name.txt"
}
if [ -e "$ref_blas/libblas.so.3" ]; then
  if [ -n "$before" ]; then
    run before "$ref_blas:$ref_lapack" "" "$before/devel/lib/doorplate_localization/doorplate_eval"
  fi
  run reference_blas_fine_stop "$ref_blas:$ref_lapack" ",back_end.graph.min_step_m=1e-7,back_end.graph.min_step_rad=1e-7"
  run reference_blas "$ref_blas:$ref_lapack" ""
else
  echo "back_end_speed: no reference BLAS in $ref_blas (libblas3 not installed): its two runs skipped"
fi
run installed "" ""
echo "back_end_speed: BLAS selected: $(readlink -f "/usr/lib/$multiarch/libblas.so.3")" | tee "$out/blas.txt"
/usr/bin/python3 "$here/bench/back_end_speed_table.py" "$out" | tee "$out/table.md"
