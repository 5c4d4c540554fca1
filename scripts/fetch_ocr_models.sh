#!/usr/bin/env bash
# Installs the optional learned text reader's models (PP-OCRv4 detector and recogniser, Apache-2.0, from
# the rapidocr-onnxruntime wheel on PyPI) in the form Debian 12's OpenCV 4.6 dnn runs.
# The package works without them (Tesseract is the default recogniser, MSER the default detector); the
# `ppocr` recogniser and the `db` detector need them (docs/parameters.md, docs/results/real-photos.md).
# Steps: a throwaway venv (onnx, onnxsim from PyPI) → the wheel → static input shapes + constant folding
# (onnxsim) → scripts/ocr_models/patch_for_opencv.py → MODEL_DIR. Nothing of the venv stays.
# Usage: scripts/fetch_ocr_models.sh [MODEL_DIR]   (default /usr/local/share/doorplate_localization/ocr_models)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-${DOORPLATE_OCR_MODEL_DIR:-/usr/local/share/doorplate_localization/ocr_models}}"
wheel_version=1.4.4
rec_width_px=(320 160)  # the recogniser's fixed input widths (OpenCV 4.6 needs static shapes); height 48
if [ -f "$out/VERSION" ] && [ "$(cat "$out/VERSION")" = "rapidocr-onnxruntime-$wheel_version v1" ]; then
  echo "fetch_ocr_models: $out is up to date"; exit 0
fi
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"  # Debian's python3 (has venv), not a pyenv shim
# The venv's pip trusts certifi's roots; trust the machine's store instead (as Debian's own pip does), so a
# site whose proxy CA is installed system-wide works too.
if [ -z "${PIP_CERT:-}" ] && [ -f /etc/ssl/certs/ca-certificates.crt ]; then
  export PIP_CERT=/etc/ssl/certs/ca-certificates.crt
fi
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
python3 -m venv "$work/venv"
"$work/venv/bin/pip" install -q --disable-pip-version-check "onnx>=1.14" "onnxsim>=0.4" numpy
"$work/venv/bin/pip" download -q --disable-pip-version-check --no-deps -d "$work" \
  "rapidocr-onnxruntime==$wheel_version"
(cd "$work" && python3 -m zipfile -e rapidocr_onnxruntime-*.whl wheel)
models="$work/wheel/rapidocr_onnxruntime/models"
py="$work/venv/bin/python"
mkdir -p "$work/out"
for w in "${rec_width_px[@]}"; do
  "$py" -m onnxsim "$models/ch_PP-OCRv4_rec_infer.onnx" "$work/rec_$w.onnx" \
    --overwrite-input-shape "1,3,48,$w" > "$work/onnxsim_$w.log" 2>&1 || { cat "$work/onnxsim_$w.log"; exit 1; }
  "$py" "$repo/scripts/ocr_models/patch_for_opencv.py" "$work/rec_$w.onnx" "$work/out/ppocrv4_rec_48x$w.onnx"
done
mv "$work/out/ppocrv4_rec_48x${rec_width_px[0]}.onnx.dict.txt" "$work/out/ppocrv4_rec_dict.txt"
rm -f "$work"/out/*.onnx.dict.txt
"$py" "$repo/scripts/ocr_models/patch_for_opencv.py" "$models/ch_PP-OCRv4_det_infer.onnx" "$work/out/ppocrv4_det.onnx"
echo "rapidocr-onnxruntime-$wheel_version v1" > "$work/out/VERSION"
mkdir -p "$out"
cp "$work"/out/* "$out/"
echo "fetch_ocr_models: installed $(ls "$work/out" | tr '\n' ' ')in $out"
