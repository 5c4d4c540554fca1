#!/usr/bin/env python3
"""Checks an rviz screenshot of rviz/localization.rviz: the particle cloud (PoseArray, colour 255;25;0) and
the text-landmark markers (orange arrows 0.9;0.6;0.1 from the map conversions, white text) are drawn.
Prints "ok: ..." or "missing: ..." with the pixel counts; exit code 0 either way (the caller decides).
Usage: count_colors.py SCREEN.ppm [--min-pixels N]   (binary P6 PPM, as `import -window root x.ppm` writes)"""
import sys

import numpy as np


def read_ppm(path):
    """A binary P6 PPM with maxval 255 as an (h, w, 3) int array."""
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; '#' comments skipped
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError(f"{path}: not a P6 PPM with maxval 255")
    w, h = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data, dtype=np.uint8, count=w * h * 3, offset=pos + 1)
    return pixels.reshape(h, w, 3).astype(int)


def count(rgb, lo, hi):
    mask = np.all((rgb >= np.array(lo)) & (rgb <= np.array(hi)), axis=-1)
    return int(mask.sum())


def main():
    path = sys.argv[1]
    min_pixels = int(sys.argv[3]) if len(sys.argv) > 3 and sys.argv[2] == "--min-pixels" else 200
    rgb = read_ppm(path)
    # Shaded by rviz's light: allow a band around each colour. Particles: red, almost no green/blue (the laser
    # scan, 255;80;80, has far more blue). Landmark arrows: orange (much red, some green, little blue).
    particles = count(rgb, (170, 0, 0), (255, 60, 40))
    landmarks = count(rgb, (170, 100, 0), (255, 185, 60))
    missing = [name for name, n in (("particles", particles), ("landmarks", landmarks)) if n < min_pixels]
    print(("missing: " + ", ".join(missing) if missing else "ok:") +
          f" particle pixels {particles}, landmark pixels {landmarks} (need {min_pixels} each)")


if __name__ == "__main__":
    main()
