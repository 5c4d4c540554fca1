#!/usr/bin/env bash
# Real plate faces on simulated walls (issue 15 item 4): the plates of the shared real photographs,
# cropped, hung on the walls of a simulated corridor (`image:` signs, docs/world-format.md), then read by
# the whole robot pipeline — camera rendering, band, MSER, recogniser, tracker — in `doorplate_eval ocr`,
# with each recogniser, at 640×480 and 1280×720; and used by Text AMCL in `doorplate_eval localize`.
# The crops come from RapidOCR's boxes of each label (bench/real_photos.sh's baseline, run first: an
# independent reader, so our reader does not choose its own test plates); photos RapidOCR did not read are
# left out and counted. Nothing of the photos is committed: everything goes to results/photo_world/.
# Usage: bench/photo_world.sh [PHOTO_DIR]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
photos="${1:-$repo/../shared/data/doorplate_photos}"
rapid="$repo/results/real_photos/rapidocr_native.json"
if [ ! -f "$photos/labels.tsv" ]; then echo "photo_world: no labelled photos in $photos: nothing to do"; exit 0; fi
[ -f "$rapid" ] || { echo "photo_world: $rapid missing: run bench/real_photos.sh first"; exit 1; }
source "$repo/scripts/env.sh"
bin="$DOORPLATE_BUILD/devel/lib/doorplate_localization"
out="$repo/results/photo_world"; mkdir -p "$out"
python3 - "$photos/labels.tsv" "$rapid" "$out/crops.tsv" <<'PY'
import json, sys
sep = "-./ \t:,\u00b7\u00a0\u2013\u2014"
canon = lambda t: "".join(c.upper() for c in t if c not in sep)
labels = {}
with open(sys.argv[1], encoding="utf-8") as f:
    head = f.readline().rstrip("\n").split("\t")
    for line in f:
        row = dict(zip(head, line.rstrip("\n").split("\t")))
        labels[row["file"]] = row["room_number_text"]
run = json.load(open(sys.argv[2], encoding="utf-8"))
kept, skipped = [], []
for image in run["images"]:
    name = image["file"].rsplit("/", 1)[-1]
    hits = [r for r in image["reads"] if canon(r["room"]) == canon(labels.get(name, "?"))]
    if not hits:
        skipped.append(name); continue
    x, y, w, h = hits[0]["box_px"]
    mx, my = int(0.5 * h), int(0.6 * h)  # the plate around the text line
    kept.append(f"{image['file']}\t{max(0, x - mx)}\t{max(0, y - my)}\t{w + 2 * mx}\t{h + 2 * my}\t{labels[name]}")
with open(sys.argv[3], "w", encoding="utf-8") as f:
    f.write("# image_path\tx\ty\tw\th\ttext (RapidOCR's box of the label, grown to the plate)\n" + "\n".join(kept) + "\n")
print(f"photo_world: {len(kept)} plates; left out (not read by RapidOCR): {', '.join(skipped) or 'none'}")
PY
"$bin/doorplate_photo_world" --crops "$out/crops.tsv" --out "$out"
world="$out/worlds/photo_plates.yaml"
for size in 640x480 1280x720; do
  for r in tesseract ppocr; do
    echo "== ocr $r $size"
    OMP_THREAD_LIMIT=1 "$bin/doorplate_eval" ocr --world "$world" --passes 1 --seed 1 --detector-every 0 \
      --recognizer "$r" --camera-px "$size" --json "$out/ocr_${r}_${size}.json" | grep -E "^world|pass 0:|accuracy"
  done
done
echo "== localize text_amcl (ppocr)"
OMP_THREAD_LIMIT=1 "$bin/doorplate_eval" localize --world "$world" --method text_amcl --trials 10 --seed 1 --recognizer ppocr \
  --json "$out/localize_text_amcl.json" | grep -vE "^  trial"
