#!/usr/bin/env python3
"""Scores doorplate readers on labelled still photographs (bench/real_photos.sh writes the inputs).

Inputs: the photos' labels.tsv and one JSON per reader run:
  {"reader": NAME, "width_px": W, "images": [{"file": F, "cpu_seconds": S, "reads": [{"room": T, ...}]}]}
where "room" is a text the reader reports as a room number ("" = refused). The baselines' texts are
put through the same room grammar (the package's default, docs/text-map-format.md) before scoring.

Per photo, with the label's canonical form K (separators removed, upper case: the package's rule):
  correct     some reported room has canonical form K;
  wrong reads reported rooms whose canonical form is not K (a misread digit, or another number in the
              picture taken for the room); "acted on" = those equal to another photo's room (a building
              holding all these rooms: the localizer's text map would contain it and act on the read).
In-pattern photos: labels matching the old default [0-9]{3,4}[A-Z]?.
Usage: real_photos_score.py LABELS.tsv OUT.md RUN.json...
"""
import json
import os
import re
import statistics
import sys

SEPARATORS = "-./ \t\r\n:,\u00b7\u00a0\u2013\u2014\u2010\u2011\u2212\u2022\u2219\u22c5"
DEFAULT_PATTERN = re.compile(r"[0-9]{1,6}[A-Z]{0,2}|[A-Z]{1,2}[0-9]{2,6}[A-Z]{0,2}")
OLD_PATTERN = re.compile(r"[0-9]{3,4}[A-Z]?")


def canonical(text):
    return "".join(c.upper() if c.isascii() else c for c in text if c not in SEPARATORS)


def reader_name(run):
    return run.get("reader") or f"{run['detector']} + {run['recognizer']}" + (" (band)" if run.get("band") else "")


def load_labels(path):
    labels = {}
    with open(path, encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            row = dict(zip(header, line.rstrip("\n").split("\t")))
            labels[row["file"]] = row["room_number_text"]
    return labels


def score_run(run, labels):
    rooms_of_set = {canonical(v) for v in labels.values()}
    per_photo, times = [], []
    for image in run["images"]:
        name = os.path.basename(image["file"])
        if name not in labels:
            continue
        truth = canonical(labels[name])
        reported = [canonical(r["room"]) for r in image["reads"] if r.get("room")]
        reported = [r for r in reported if r]
        wrong = [r for r in reported if r != truth]
        per_photo.append({
            "file": name, "label": labels[name], "in_pattern": bool(OLD_PATTERN.fullmatch(labels[name])),
            "correct": truth in reported, "wrong": wrong,
            "wrong_acted_on": [r for r in wrong if r in rooms_of_set],
        })
        times.append(image.get("cpu_seconds", 0.0))
    return per_photo, times


def summary_row(run, per_photo, times):
    n_in = sum(p["in_pattern"] for p in per_photo)
    ok_in = sum(p["correct"] for p in per_photo if p["in_pattern"])
    ok = sum(p["correct"] for p in per_photo)
    wrong = sum(len(p["wrong"]) for p in per_photo)
    acted = sum(len(p["wrong_acted_on"]) for p in per_photo)
    pct = lambda a, b: f"{100.0 * a / b:.1f} %" if b else "-"
    return (f"| {reader_name(run)} | {run.get('width_px') or 'native'} | {ok_in}/{n_in} ({pct(ok_in, n_in)}) | "
            f"{ok}/{len(per_photo)} ({pct(ok, len(per_photo))}) | {wrong} | {acted} | "
            f"{1e3 * statistics.mean(times):.0f} | {1e3 * statistics.median(times):.0f} |")


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    labels = load_labels(sys.argv[1])
    runs = []
    for path in sys.argv[3:]:
        with open(path, encoding="utf-8") as f:
            runs.append(json.load(f))
    lines = ["| reader | width px | in-pattern plates read | all plates read | wrong reads | wrong reads "
             "naming another room of the set | mean ms / image | median ms / image |",
             "|---|---|---|---|---|---|---|---|"]
    details = []
    for run in runs:
        per_photo, times = score_run(run, labels)
        lines.append(summary_row(run, per_photo, times))
        missed = [p["label"] for p in per_photo if not p["correct"]]
        wrong = [f"{p['label']}→{','.join(p['wrong'])}" for p in per_photo if p["wrong"]]
        details.append(f"- **{reader_name(run)} @ {run.get('width_px') or 'native'}**: missed "
                       f"{', '.join(missed) or 'none'}; wrong reads {'; '.join(wrong) or 'none'}")
    with open(sys.argv[2], "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n\nPer reader, the photos it missed (label) and its wrong reads "
                  "(label→read):\n\n" + "\n".join(details) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
