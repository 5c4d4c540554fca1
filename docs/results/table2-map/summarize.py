#!/usr/bin/env python3
"""Prints the Table II rows (markdown) from the JSON files of doorplate_eval map in this folder."""
import glob, json, os, statistics, sys

folder = os.path.dirname(os.path.abspath(__file__))
runs = {}
for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
    with open(path) as f:
        r = json.load(f)
    runs.setdefault((r["world"], r["method"]), []).append(r)

print("| world | method | seeds | length est. (m), mean [min, max] | length accuracy, mean [min, max] | "
      "width est. (m) | width accuracy, min | plates mapped | plate RMSE (m), max over seeds | worst plate (m) | "
      "final pose error (m), mean [max] | SLAM ms / processed scan | SLAM × real time | peak RSS (MB) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for (world, method), rs in sorted(runs.items()):
    rs.sort(key=lambda r: r["seed"])
    le = [r["length_est_m"] for r in rs]
    la = [r["length_accuracy"] for r in rs]
    we = [r["width_est_m"] for r in rs]
    wa = [r["width_accuracy"] for r in rs]
    width_ok = all(w > 0 for w in wa)  # open doors: rooms behind them swamp the side-wall medians
    pm = [r["plates_mapped"] for r in rs]
    rm = [r["plate_position_rmse_m"] for r in rs if r["plate_position_rmse_m"] is not None]
    mx = [r["plate_max_error_m"] for r in rs if r["plate_max_error_m"] is not None]
    ms = [r["slam_ms_per_processed_scan"] for r in rs]
    rt = [r["slam_real_time_factor"] for r in rs]
    rss = [r["peak_rss_mb"] for r in rs]
    print(f"| {world} | {method} | {','.join(str(r['seed']) for r in rs)} | {statistics.mean(le):.2f} [{min(le):.2f}, {max(le):.2f}] "
          f"| {100*statistics.mean(la):.2f} % [{100*min(la):.2f}, {100*max(la):.2f}] | {statistics.mean(we):.3f} "
          f"| {f'{100*min(wa):.2f} %' if width_ok else 'not measured'} | {min(pm)}-{max(pm)} / {rs[0]['plates_true']} "
          f"| {max(rm):.3f} | {max(mx):.3f} | " if rm else
          f"| {world} | {method} | {','.join(str(r['seed']) for r in rs)} | {statistics.mean(le):.2f} [{min(le):.2f}, {max(le):.2f}] "
          f"| {100*statistics.mean(la):.2f} % [{100*min(la):.2f}, {100*max(la):.2f}] | {statistics.mean(we):.3f} "
          f"| {f'{100*min(wa):.2f} %' if width_ok else 'not measured'} | 0 / {rs[0]['plates_true']} | – | – | ", end="")
    fe = [r["final_position_error_m"] for r in rs]
    print(f"{statistics.mean(fe):.2f} [{max(fe):.2f}] | {statistics.mean(ms):.1f} | {min(rt):.0f}-{max(rt):.0f} | {max(rss):.0f} |")
print()
print("Per seed (length accuracy %, final pose error m):")
for (world, method), rs in sorted(runs.items()):
    print(f"- {world} {method}: " + ", ".join(f"{r['seed']}: {100*r['length_accuracy']:.2f} / {r['final_position_error_m']:.2f}" for r in rs))
