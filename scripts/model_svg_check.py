#!/usr/bin/env python3
"""Checks a screenshot of a `model.svg` against the SVG and the run's `result.json`.

    scripts/model_svg_check.py OUT_DIR SCREENSHOT.png

OUT_DIR is a `flexfem run --out` directory (model.svg, result.json). Checks, each an exit 1
with a message when it fails:

1. the screenshot is not blank: at least 2 % of its pixels differ from the white background;
2. the drawing is inside the view: no pixel of the drawing within 3 px of the image border
   (the canvas is the SVG's own size, white around the drawing);
3. every notch symbol's `data-utilisation` equals the utilisation `result.json` gives that hinge
   (static: `load_cases[i].hinges[j].utilisation` of element N for the label `element N`;
   stage: `hinge_stress.revolute/spherical[leg] / material.allowable`), to 1e-9 relative;
4. the screenshot's colour at each symbol's `data-sample` point is the colour map's colour for
   that utilisation (src/report/model_svg.rs: green 0 → yellow 0.5 → red 1, magenta above 1,
   grey without an allowable), within 16 per channel (anti-aliasing).

Standard library only (the PNG is decoded with zlib).
"""

import json
import math
import re
import struct
import sys
import zlib
from pathlib import Path


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB/RGBA, non-interlaced PNG."""
    data = Path(path).read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, w = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise SystemExit(f"{path}: unsupported PNG (depth {depth}, colour type {colour})")
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[i]
        line = bytearray(raw[i + 1 : i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pr) & 255
        rows.append([tuple(line[k : k + 3]) for k in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def colour(u):
    """The colour map of src/report/model_svg.rs::utilisation_colour."""
    if u is None:
        return (170, 170, 170)
    if u > 1.0:
        return (200, 0, 200)
    u = max(u, 0.0)
    # Rust's f64::round rounds half away from zero.
    rnd = lambda v: int(math.floor(v + 0.5))
    return (rnd(230.0 * min(2.0 * u, 1.0)), rnd(200.0 * min(2.0 * (1.0 - u), 1.0)), 40)


def expected_utilisations(result, load_case):
    """label -> utilisation from result.json, for the load case the picture shows."""
    cases = [c for c in result.get("load_cases", []) if c.get("name") == load_case]
    if not cases:
        return {}
    c = cases[0]
    if "hinge_stress" in c:
        allowable = result["material"]["allowable"]
        out = {}
        for kind in ("revolute", "spherical"):
            for i, s in enumerate(c["hinge_stress"][kind]):
                out[f"leg {i + 1} {kind}"] = s / allowable
        return out
    return {f"element {h['element']}": h["utilisation"] for h in c.get("hinges", [])}


def main():
    out_dir, png = Path(sys.argv[1]), sys.argv[2]
    svg = (out_dir / "model.svg").read_text()
    result = json.loads((out_dir / "result.json").read_text())
    w, h, rows = read_png(png)
    fails = []

    ink = [(x, y) for y, row in enumerate(rows) for x, p in enumerate(row) if min(p) < 245]
    if len(ink) < 0.02 * w * h:
        fails.append(f"blank: {len(ink)} drawn pixels of {w * h}")
    if ink:
        xs = [p[0] for p in ink]
        ys = [p[1] for p in ink]
        box = (min(xs), min(ys), max(xs), max(ys))
        if box[0] < 3 or box[1] < 3 or box[2] > w - 4 or box[3] > h - 4:
            fails.append(f"drawing {box} touches the border of the {w}x{h} view")

    load_case = re.search(r'data-load-case="([^"]*)"', svg).group(1).replace("&quot;", '"')
    expected = expected_utilisations(result, load_case)
    marks = re.findall(r'<g class="hinge" data-label="([^"]*)" data-utilisation="([^"]*)" data-sample="([^"]*)"', svg)
    checked = 0
    for label, u, sample in marks:
        u = None if u == "none" else float(u)
        if label in expected:
            e = expected[label]
            if u is None or abs(u - e) > 1e-9 * max(abs(e), 1e-300):
                fails.append(f"{label}: model.svg says utilisation {u}, result.json {e}")
        elif u is not None:
            fails.append(f"{label}: utilisation {u} in model.svg but no such hinge in result.json")
        x, y = (float(v) for v in sample.split())
        px = rows[int(round(y))][int(round(x))]
        want = colour(u)
        if max(abs(a - b) for a, b in zip(px, want)) > 16:
            fails.append(f"{label}: pixel {px} at ({x}, {y}), colour map gives {want} for {u}")
        checked += 1
    if expected and checked != len(expected):
        fails.append(f"{checked} hinge symbols for {len(expected)} hinges in result.json")
    name = out_dir.name
    if fails:
        print(f"model_svg_check {name}: FAILED")
        for f in fails:
            print("  " + f)
        sys.exit(1)
    print(f"model_svg_check {name}: ok ({w}x{h}, {len(ink)} drawn pixels, {checked} hinge colours checked)")


if __name__ == "__main__":
    main()
