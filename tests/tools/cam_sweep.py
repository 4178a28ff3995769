#!/usr/bin/env python3
"""kerf cam over every real drawing: for each DXF in ../shared/realworld/dxf with a closed contour,
its first closed contour is made into a program — outside and inside, ISO and 3B, wire offset
0.15 mm — and `kerf check` of what was written must exit 0 with no error. Drawings with no closed
contour are listed as such (kerf cam refuses them with K0606, as it must).
Then each program is held against its own drawing (`kerf check --drawing`, issue 43): the wire
paths moved back by the offset to their side (ISO at four decimals, 3B read from the start hole the
ISO program gives), and the same contour made with the offset left to the controller (G41/G42,
ISO): every piece of the part edge lies within 0.001 mm of the drawing, and at least the contour's
elements lie within 0.001 mm of it. 3B within 0.0025 mm: its end points are whole micrometres, and
moving the path back by the offset turns a short segment's rounding into more at the part's
corners (docs/drawing.md).

usage: cam_sweep.py KERF DXF_DIR WORKDIR"""
import glob
import json
import os
import re
import subprocess
import sys

kerf, dxf_dir, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures, made, no_closed, compared, worst = [], 0, [], 0, {"iso": 0.0, "3b": 0.0}
for path in sorted(glob.glob(os.path.join(dxf_dir, "*.dxf"))):
    name = os.path.splitext(os.path.basename(path))[0]
    r = subprocess.run([kerf, "check", "--json", path], capture_output=True, text=True)
    contours = json.loads(r.stdout)["drawing"]["contours"]
    closed = [i + 1 for i, c in enumerate(contours) if c["closed"]]
    if not closed:
        r = subprocess.run([kerf, "cam", path, "--offset", "0.15", "--side", "outside", "-o",
                            os.path.join(work, name + ".none")], capture_output=True, text=True)
        if r.returncode != 1 or "K0606" not in r.stderr:
            failures.append(f"{name}: no closed contour, but cam exited {r.returncode}: {r.stderr[-300:]}")
        no_closed.append(name)
        continue
    held = []  # (label, program, options) to hold against the drawing
    for side in ("outside", "inside"):
        for to in ("iso", "3b"):
            out = os.path.join(work, f"{name}.{side}.{to}")
            if os.path.exists(out):
                os.remove(out)
            decimals = ["--decimals", "4"] if to == "iso" else []
            r = subprocess.run([kerf, "cam", path, "--offset", "0.15", "--side", side, "--contour", str(closed[0]),
                                "--to", to, "-o", out] + decimals, capture_output=True, text=True)
            if r.returncode != 0:
                errors = [l for l in r.stderr.splitlines() if "error" in l]
                failures.append(f"{name} contour {closed[0]} {side} {to}: cam exited {r.returncode}: {errors[:2]}")
                continue
            c = subprocess.run([kerf, "check", out], capture_output=True, text=True)
            if c.returncode != 0:
                failures.append(f"{name} {side} {to}: kerf check of the program exits {c.returncode}")
                continue
            made += 1
            start = []
            if to == "3b":  # 3B is relative: it starts where the ISO program's G92 says
                g92 = re.search(r"G92 X(-?[0-9.]+) Y(-?[0-9.]+)", open(os.path.join(work, f"{name}.{side}.iso")).read())
                start = ["--start", f"{g92.group(1)},{g92.group(2)}"]
            held.append((f"{name} {side} {to}", out, ["--offset", "0.15", "--side", side] + start,
                         0.0025 if to == "3b" else 0.001))
    # The program against its own drawing.
    out = os.path.join(work, f"{name}.controller.iso")
    if os.path.exists(out):
        os.remove(out)
    # Four decimals: the 0.5 um rounding of three would take an arc's end up to 0.7 um off on its own.
    r = subprocess.run([kerf, "cam", path, "--offset-by", "controller", "--side", "outside", "--contour",
                        str(closed[0]), "--to", "iso", "--decimals", "4", "-o", out], capture_output=True, text=True)
    if r.returncode != 0:
        failures.append(f"{name}: cam --offset-by controller exited {r.returncode}: {r.stderr[-300:]}")
        continue
    held.append((f"{name} controller iso", out, [], 0.001))
    wanted = contours[closed[0] - 1]["elements"]
    for label, program, options, bound in held:
        c = subprocess.run([kerf, "check", "--json", program, "--drawing", path] + options, capture_output=True,
                           text=True)
        comparison = json.loads(c.stdout)["summary"]["comparison"]
        edge_worst = max((e["deviation_mm"] for e in comparison["edge"]), default=0.0)
        within = sum(1 for e in comparison["elements"] if e["deviation_mm"] <= bound)
        # Both ways: the contour's elements (each the largest of the element to the edge and back).
        element_worst = max((e["deviation_mm"] for e in comparison["elements"] if e["deviation_mm"] <= bound),
                            default=0.0)
        if edge_worst > bound or within < wanted:
            failures.append(f"{label}: against its drawing, the edge up to {edge_worst:.6f} mm off, {within} "
                            f"elements within {bound} mm of {wanted} in the contour")
            continue
        compared += 1
        kind = "3b" if label.endswith("3b") else "iso"
        worst[kind] = max(worst[kind], edge_worst, element_worst)
print(f"{compared} programs held against their own drawings: largest deviation {worst['iso'] * 1000:.3f} um "
      f"(ISO), {worst['3b'] * 1000:.3f} um (3B)")
print(f"{made} programs made and checked clean; no closed contour (refused, K0606): {', '.join(no_closed)}")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
