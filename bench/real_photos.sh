#!/usr/bin/env bash
# The doorplate reader on real photographs of room signs (issue 15), beside the readers a user would try
# instead, in one run: every reader on every photo at the robot camera's 640 px width and at native size.
# Writes docs/results/real-photos.md (the tables; the prose around them is kept) and its JSON beside it in
# results/real_photos/. The photos are NOT part of the package: they are read from PHOTO_DIR (default
# ../shared/data/doorplate_photos, with labels.tsv); without them the bench says so and exits 0.
# Needs: a build (scripts/build.sh), the learned models (scripts/fetch_ocr_models.sh) for the db/ppocr
# rows, network access to PyPI for the RapidOCR baseline (a throwaway venv; skipped if it cannot install).
# Usage: bench/real_photos.sh [PHOTO_DIR]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
photos="${1:-$repo/../shared/data/doorplate_photos}"
if [ ! -f "$photos/labels.tsv" ]; then
  echo "real_photos: no labelled photos in $photos (labels.tsv missing): nothing to measure"; exit 0
fi
source "$repo/scripts/env.sh"
tool="$DOORPLATE_BUILD/devel/lib/doorplate_localization/doorplate_read_image"
[ -x "$tool" ] || { echo "real_photos: $tool not built (run scripts/build.sh)"; exit 1; }
out="$repo/results/real_photos"; mkdir -p "$out"
mapfile -t images < <(ls "$photos"/*.jpg "$photos"/*.png 2>/dev/null | sort)
echo "real_photos: ${#images[@]} photos from $photos"
readers=("mser tesseract" "mser ppocr" "db tesseract" "db ppocr")
runs=()
for width in 640 0; do
  for reader in "${readers[@]}"; do
    set -- $reader
    json="$out/${1}_${2}_${width/#0/native}.json"
    if "$tool" --detector "$1" --recognizer "$2" --width "$width" --json "$json" "${images[@]}" > "$out/${1}_${2}_${width/#0/native}.log" 2>&1; then
      runs+=("$json")
    else
      echo "real_photos: $1 + $2 at width $width failed (see $out/${1}_${2}_${width/#0/native}.log)"
      tail -2 "$out/${1}_${2}_${width/#0/native}.log"
    fi
  done
done
venv="$out/baseline-venv"
if [ ! -x "$venv/bin/python" ]; then
  (/usr/bin/python3 -m venv "$venv" && "$venv/bin/pip" install -q --disable-pip-version-check \
     rapidocr-onnxruntime==1.4.4) > "$out/baseline-venv.log" 2>&1 || { echo "real_photos: RapidOCR venv failed (see $out/baseline-venv.log)"; rm -rf "$venv"; }
fi
if [ -x "$venv/bin/python" ] && command -v tesseract > /dev/null; then
  for width in 640 0; do
    OMP_NUM_THREADS=1 "$venv/bin/python" "$repo/bench/real_photos_baselines.py" "$out" "$width" "${images[@]}"
    runs+=("$out/tesseract-cli_${width/#0/native}.json" "$out/rapidocr_${width/#0/native}.json")
  done
else
  echo "real_photos: baselines skipped (need the venv and the tesseract command: apt-get install tesseract-ocr)"
fi
python3 "$repo/bench/real_photos_score.py" "$photos/labels.tsv" "$out/table.md" "${runs[@]}"
echo "real_photos: table in $out/table.md (copy it into docs/results/real-photos.md with the date and commit)"
