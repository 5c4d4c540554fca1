#!/usr/bin/env python3
"""The readers a user would try instead of ours, on the same photos, for bench/real_photos.sh:
  tesseract-cli: the `tesseract` command on the whole image (sparse text, --psm 11, Debian's LSTM model);
  rapidocr:      RapidOCR (PP-OCRv4 detection + recognition, ONNX Runtime, one thread) from PyPI.
Runs inside the throwaway venv real_photos.sh makes (rapidocr-onnxruntime, which brings opencv-python);
never a dependency of the package. Each text line becomes a candidate room when it fits the package's
default room grammar after removing separators; lines are also split at spaces ("Room 204").
Writes one JSON per reader in real_photos_score.py's format.
Usage: real_photos_baselines.py OUT_DIR WIDTH_PX (0: native) IMAGE...
"""
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

import cv2

SEPARATORS = "-./ \t\r\n:,\u00b7\u00a0\u2013\u2014\u2010\u2011\u2212\u2022\u2219\u22c5"
PATTERN = re.compile(r"[0-9]{1,6}[A-Z]{0,2}|[A-Z]{1,2}[0-9]{2,6}[A-Z]{0,2}")


def rooms_in(line):
    out = []
    for candidate in [line] + line.split():
        canon = "".join(c.upper() if c.isascii() else c for c in candidate if c not in SEPARATORS)
        if canon and PATTERN.fullmatch(canon) and candidate.strip() not in out:
            out.append(candidate.strip())
    return out


def scaled(path, width_px, tmp):
    image = cv2.imread(path, cv2.IMREAD_COLOR)
    if width_px and image.shape[1] != width_px:
        s = width_px / image.shape[1]
        image = cv2.resize(image, None, fx=s, fy=s, interpolation=cv2.INTER_AREA if s < 1 else cv2.INTER_LINEAR)
    out = os.path.join(tmp, "image.png")
    cv2.imwrite(out, image)
    return out, image


def box_of(quad):
    """Axis-aligned [x, y, w, h] of a RapidOCR quadrilateral, in the scaled image's pixels."""
    xs, ys = [p[0] for p in quad], [p[1] for p in quad]
    return [int(min(xs)), int(min(ys)), int(max(xs) - min(xs) + 0.5), int(max(ys) - min(ys) + 0.5)]


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    out_dir, width_px, images = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    from rapidocr_onnxruntime import RapidOCR
    engine = RapidOCR(intra_op_num_threads=1, inter_op_num_threads=1)
    runs = {name: {"reader": name, "width_px": width_px, "images": []} for name in ("tesseract-cli", "rapidocr")}
    env = dict(os.environ, OMP_THREAD_LIMIT="1")
    with tempfile.TemporaryDirectory() as tmp:
        for path in images:
            png, image = scaled(path, width_px, tmp)
            t0 = child_cpu()
            text = subprocess.run(["tesseract", png, "stdout", "--psm", "11", "-l", "eng"], env=env,
                                  capture_output=True, text=True).stdout
            cpu = child_cpu() - t0
            reads = [{"room": r, "raw_text": line} for line in text.splitlines() for r in rooms_in(line)]
            runs["tesseract-cli"]["images"].append({"file": path, "cpu_seconds": cpu, "reads": reads})
            t0 = time.process_time()
            result, _ = engine(image)
            cpu = time.process_time() - t0
            reads = [{"room": r, "raw_text": line[1], "confidence": float(line[2]), "box_px": box_of(line[0])}
                     for line in (result or []) for r in rooms_in(line[1])]
            runs["rapidocr"]["images"].append({"file": path, "cpu_seconds": cpu, "reads": reads})
    for name, run in runs.items():
        with open(os.path.join(out_dir, f"{name}_{width_px or 'native'}.json"), "w", encoding="utf-8") as f:
            json.dump(run, f, indent=1)


if __name__ == "__main__":
    main()
