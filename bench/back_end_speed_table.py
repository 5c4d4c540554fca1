#!/usr/bin/env python3
"""Table of bench/back_end_speed.sh's runs: each solve's wall time per configuration, the ratios against the
shipped one, and whether the runs' results agree (they must, to well below a map cell).
Usage: back_end_speed_table.py DIR (holding installed.json and any of before.json, reference_blas_fine_stop.json,
reference_blas.json)"""
import json
import os
import sys

NAMES = ["before", "reference_blas_fine_stop", "reference_blas", "installed"]
RESULT_KEYS = ["length_est_m", "width_est_m", "trajectory_rmse_m", "trajectory_max_error_m",
               "final_position_error_m", "back_end_odometry_scale"]


def main(folder):
    runs = {}
    for name in NAMES:
        path = os.path.join(folder, name + ".json")
        if os.path.exists(path):
            with open(path) as f:
                runs[name] = json.load(f)
    if "installed" not in runs:
        sys.exit("back_end_speed_table: no installed.json in " + folder)
    names = [n for n in NAMES if n in runs]
    shipped = runs["installed"]["solves"]
    print("| sim s | nodes (without scan) | loop closures | loop alignments run / reused | " +
          " | ".join(n + " (s)" for n in names) + " |")
    print("|---" * (4 + len(names)) + "|")
    for i, solve in enumerate(shipped):
        if solve["nodes"] <= 1:
            continue
        cells = ["%.2f" % runs[n]["solves"][i]["wall_s"] for n in names]
        print("| %.0f | %d (%d) | %d | %d / %d | %s |" % (
            solve["sim_time_s"], solve["nodes"], solve["nodes_on_mapped_ground"], solve["loop_closures"],
            solve.get("loop_alignments_computed", -1), solve.get("loop_alignments_reused", -1), " | ".join(cells)))
    total = {n: sum(s["wall_s"] for s in runs[n]["solves"]) for n in names}
    last = {n: runs[n]["solves"][-1]["wall_s"] for n in names}
    print()
    for n in names:
        print("- %s: all solves %.1f s (%.2fx the shipped), the last %.2f s (%.2fx); run %.0f s wall" %
              (n, total[n], total[n] / total["installed"], last[n], last[n] / last["installed"], runs[n]["seconds"]))
    for n in names:
        if n == "installed":
            continue
        worst = max(abs(runs[n][k] - runs["installed"][k]) for k in RESULT_KEYS)
        same_closures = runs[n]["back_end_loop_closures"] == runs["installed"]["back_end_loop_closures"]
        print("- %s vs installed: results differ by at most %.2g (m or scale; %s), loop closures %s" %
              (n, worst, ", ".join(RESULT_KEYS), "the same" if same_closures else "DIFFERENT"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
