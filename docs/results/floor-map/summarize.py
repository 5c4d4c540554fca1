#!/usr/bin/env python3
"""Prints the whole-floor mapping tables (markdown) from the doorplate_eval map JSON files in this folder (or
the folder given: python3 summarize.py [FOLDER]): one row per run (drive, pass ends, closing error, plates,
worst corridor), then per corridor over the runs."""
import glob, json, os, statistics, sys

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
runs = []
for path in sorted(glob.glob(os.path.join(folder, "*.json"))):
    with open(path) as f:
        runs.append(json.load(f))
runs.sort(key=lambda r: (r["method"], r["seed"]))


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}f}"


print("| method | seed | drive ended | driven (m) | pass ends (why, trajectory error there m) | plates mapped "
      "| plate max error (m), start-aligned | after best rigid fit | worst corridor length % | worst width % "
      "| trajectory max error (m) | wall time (s) | peak RSS (MB) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    ends = "; ".join(f"{e['why']} {fmt(e.get('trajectory_error_m'))}" for e in r.get("pass_ends", []))
    cs = [c for c in r.get("corridors", []) if c["ok"]]
    worst_len = min((c["length_accuracy"] for c in cs), default=None)
    worst_wid = min((c["width_accuracy"] for c in cs), default=None)
    print(f"| {r['method']} | {r['seed']} | {'yes' if r['sweep_done'] else 'NO'} | {r['distance_m']:.0f} | {ends} "
          f"| {r['plates_mapped']} / {r['plates_true']} | {fmt(r['plate_max_error_m'])} "
          f"| {fmt(r.get('plates_fitted_max_error_m'))} "
          f"| {'–' if worst_len is None else f'{100 * worst_len:.2f}'} ({len(cs)}/{len(r.get('corridors', []))} measured) "
          f"| {'–' if worst_wid is None else f'{100 * worst_wid:.2f}'} | {r['trajectory_max_error_m']:.3f} "
          f"| {r['seconds']:.0f} | {r['peak_rss_mb']:.0f} |")

print()
print("Per corridor (length accuracy %, min / mean over the runs of each method; estimated length m, mean):")
print()
print("| method | corridor | true length (m) | length accuracy % min / mean | width accuracy % min |")
print("|---|---|---|---|---|")
by = {}
for r in runs:
    for c in r.get("corridors", []):
        by.setdefault((r["method"], c["id"]), []).append(c)
for (method, cid), cs in sorted(by.items()):
    ok = [c for c in cs if c["ok"]]
    if not ok:
        print(f"| {method} | {cid} | – | not measured | – |")
        continue
    la = [100 * c["length_accuracy"] for c in ok]
    wa = [100 * c["width_accuracy"] for c in ok]
    print(f"| {method} | {cid} | {ok[0]['length_true_m']:.2f} | {min(la):.2f} / {statistics.mean(la):.2f} "
          f"({len(ok)}/{len(cs)} runs measured) | {min(wa):.2f} |")
