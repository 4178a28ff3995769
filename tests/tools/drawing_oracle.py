#!/usr/bin/python3
"""GEOS (Debian's python3-shapely) as the oracle for `kerf check --drawing` (issue 43).

usage: drawing_oracle.py KERF DXF_DIR WORKDIR

For every real drawing with a closed contour, its first closed contour alone (written with ezdxf
from the exact elements Kerf's JSON gives) is made into a wire path 0.15 mm outside and inside
(`kerf cam --decimals 4`), and that program is held against the contour as written, with no
--offset: every element is about 0.15 mm from the path, more at the corners the wire rolls round
or cuts short. Kerf's largest deviation (both ways, certified) must equal GEOS's Hausdorff distance
between the contour and the path (the path read from the program here, lead-in left out), both
flattened within SAGITTA, with points at most DENSE apart along each: GEOS's discrete Hausdorff
distance is then at most DENSE / 2 + SAGITTA below the true one and SAGITTA above it (on these
shapes the farthest points are vertices, and the two agree far closer: the largest difference is
printed).
Prints one line per case and exits 1 when a case disagrees by more than that."""
import glob
import json
import math
import os
import re
import subprocess
import sys

import ezdxf
import numpy
from shapely.geometry import LineString

SAGITTA = 1e-5  # mm: flattened arcs stay this close to the arcs
DENSE = 0.1  # mm: points along every flattened piece at most this far apart


def arc_points(cx, cy, r, a0, sweep):
    step = 2 * math.acos(max(-1.0, 1 - SAGITTA / r)) if r > SAGITTA else math.pi
    n = max(2, int(math.ceil(abs(sweep) / step)))
    a = a0 + sweep * numpy.arange(n + 1) / n
    return numpy.column_stack((cx + r * numpy.cos(a), cy + r * numpy.sin(a)))


def dense_points(points):
    """Points along the polyline at most DENSE apart, its vertices among them."""
    out = [points[:1]]
    for p, q in zip(points[:-1], points[1:]):
        n = max(1, int(math.ceil(numpy.hypot(*(q - p)) / DENSE)))
        out.append(p + numpy.outer(numpy.arange(1, n + 1) / n, q - p))
    return numpy.vstack(out)


def hausdorff(a, b):
    """GEOS's discrete Hausdorff distance between the two polylines with points at most DENSE
    apart along each: at most DENSE / 2 below the Hausdorff distance of the polylines."""
    return LineString(dense_points(a)).hausdorff_distance(LineString(dense_points(b)))


def contour_points(elements):
    pieces = []
    for e in elements:
        if e["kind"] == "arc":
            cx, cy = e["centre"]
            sx, sy = e["start"]
            pieces.append(arc_points(cx, cy, e["radius"], math.atan2(sy - cy, sx - cx), e["sweep"]))
        else:
            pieces.append(numpy.array([e["start"], e["end"]], dtype=float))
    return numpy.vstack(pieces)


def write_contour(elements, path):
    doc = ezdxf.new("R2000")
    doc.units = 4  # $INSUNITS millimetres (ezdxf writes metres by default, which Kerf follows)
    msp = doc.modelspace()
    for e in elements:
        if e["kind"] == "arc":
            cx, cy = e["centre"]
            sx, sy = e["start"]
            ex, ey = e["end"]
            a0, a1 = math.degrees(math.atan2(sy - cy, sx - cx)), math.degrees(math.atan2(ey - cy, ex - cx))
            if abs(e["sweep"]) >= 2 * math.pi - 1e-12:
                msp.add_circle((cx, cy), e["radius"])
            elif e["sweep"] > 0:
                msp.add_arc((cx, cy), e["radius"], a0, a1)
            else:
                msp.add_arc((cx, cy), e["radius"], a1, a0)
        else:
            msp.add_line(tuple(e["start"]), tuple(e["end"]))
    doc.saveas(path)


def program_points(path):
    """The moves of a program kerf cam wrote (G90, mm, I J incremental), the lead-in left out."""
    x = y = None
    pieces, moves = [], 0
    for line in open(path):
        words = dict((w[0], float(w[1:])) for w in re.findall(r"[A-Z]-?[0-9.]+", line.split("(")[0]))
        g = re.findall(r"G0?([0-3])\b", line)
        if "G92" in line:
            x, y = words["X"], words["Y"]
            continue
        if not g or "X" not in words:
            continue
        nx, ny = words["X"], words["Y"]
        moves += 1
        if moves > 1:  # the first move is the lead-in from the start hole
            if g[-1] in ("2", "3"):
                cx, cy = x + words["I"], y + words["J"]
                r = math.hypot(x - cx, y - cy)
                a0, a1 = math.atan2(y - cy, x - cx), math.atan2(ny - cy, nx - cx)
                sweep = a1 - a0
                if g[-1] == "3":
                    sweep = sweep % (2 * math.pi) or 2 * math.pi
                else:
                    sweep = -((-sweep) % (2 * math.pi) or 2 * math.pi)
                pieces.append(arc_points(cx, cy, r, a0, sweep))
            else:
                pieces.append(numpy.array([[x, y], [nx, ny]]))
        x, y = nx, ny
    return numpy.vstack(pieces)


def main():
    kerf, dxf_dir, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    failures, cases, apart = [], 0, 0.0
    for drawing in sorted(glob.glob(os.path.join(dxf_dir, "*.dxf"))):
        name = os.path.splitext(os.path.basename(drawing))[0]
        run = subprocess.run([kerf, "check", "--json", "--offset", "0.15", "--side", "outside", drawing],
                             capture_output=True, text=True)
        closed = [c for c in json.loads(run.stdout)["drawing"]["contours"] if c["closed"] and "path" in c]
        if not closed:
            continue
        elements = closed[0]["path"]
        contour_dxf = os.path.join(work, name + ".contour.dxf")
        write_contour(elements, contour_dxf)
        outline = contour_points(elements)
        for side in ("outside", "inside"):
            program = os.path.join(work, f"{name}.{side}.nc")
            if os.path.exists(program):
                os.remove(program)
            made = subprocess.run([kerf, "cam", contour_dxf, "--offset", "0.15", "--side", side, "--decimals", "4",
                                   "-o", program], capture_output=True, text=True)
            if made.returncode != 0:
                failures.append(f"{name} {side}: kerf cam exited {made.returncode}: {made.stderr[-300:]}")
                continue
            checked = subprocess.run([kerf, "check", "--json", program, "--drawing", contour_dxf],
                                     capture_output=True, text=True)
            kerf_worst = json.loads(checked.stdout)["summary"]["comparison"]["worst_mm"]
            geos = hausdorff(outline, program_points(program))
            cases += 1
            apart = max(apart, abs(kerf_worst - geos))
            # Kerf: within 0.15 um of the true distance (deviation.h); GEOS: at most DENSE / 2 + SAGITTA
            # below it, SAGITTA above it.
            ok = geos - SAGITTA - 2e-4 <= kerf_worst <= geos + DENSE / 2 + SAGITTA + 2e-4
            print(f"{name} {side}: kerf {kerf_worst:.6f} mm, GEOS {geos:.6f} mm{'' if ok else '  DISAGREE'}")
            if not ok:
                failures.append(f"{name} {side}: kerf {kerf_worst:.6f} against GEOS {geos:.6f} mm")
    print(f"{cases} cases; {len(failures)} disagree; Kerf and GEOS at most {apart * 1000:.3f} um apart")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures or cases == 0 else 0)


main()
