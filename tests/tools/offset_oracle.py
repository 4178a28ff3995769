#!/usr/bin/python3
"""GEOS (Debian's python3-shapely) as the oracle for Kerf's wire offset.

usage: offset_oracle.py KERF DRAWING|random:SEED:COUNT|shape:NAME WORKDIR R [R ...]

For each radius R and side (outside, inside) it runs `KERF check --json --offset R --side SIDE` on
the drawing and, for every closed contour with a wire path, compares that path with GEOS's buffer
of the same contour (round joins): the contour's exact elements from Kerf's JSON are flattened
to within SAGITTA, buffered by +R (outside) or -R (inside), and
  - area: Kerf's exact signed area of its loops against the buffer's area;
  - hausdorff: the discrete Hausdorff distance between Kerf's loops and the buffer's boundary,
    both flattened or simplified to within COARSE (so the figure may be up to 2 COARSE too large).
random:SEED:COUNT writes COUNT random closed polylines with bulges (arcs) with ezdxf first;
shape:slot and shape:split write a die with a slot narrower than the wire and a contour pinched
narrower than it. Prints JSON: {"cases": [{file, contour, side, radius, loops, geos_parts,
kerf_area, geos_area, area_error, hausdorff, lost}]}.
"""
import json
import math
import os
import random
import subprocess
import sys

import numpy

from shapely.geometry import LineString, MultiLineString, Polygon

# mm: how far the flattened contour may leave its arcs (the buffer's input). Not finer: with points
# about 0.01 mm apart (2e-6 at R 12) GEOS 3.11's negative buffer came out wrong on random contours
# (its boundary up to 3 mm from the contour at R 1, where every point must be 1 away; a Monte-Carlo
# check of "inside and at least R from the boundary" agreed with Kerf and not with GEOS). From 1e-5
# on, GEOS is right.
SAGITTA = 1e-5
COARSE = 1e-4  # mm: the flattening and simplification for the Hausdorff distance (adds <= 2e-4)


def arc_points(e, sagitta=SAGITTA):
    """The arc's points from its start, at most sagitta from it, without its end: an (n, 2) array."""
    cx, cy = e["centre"]
    r = e["radius"]
    sweep = e["sweep"]
    sx, sy = e["start"]
    a0 = math.atan2(sy - cy, sx - cx)
    step = 2 * math.acos(max(-1.0, 1 - sagitta / r)) if r > sagitta else math.pi
    n = max(2, int(math.ceil(abs(sweep) / step)))
    a = a0 + sweep * numpy.arange(n) / n
    return numpy.column_stack((cx + r * numpy.cos(a), cy + r * numpy.sin(a)))


def flatten(elements, sagitta=SAGITTA):
    """A closed chain of lines and arcs as its vertices (the first not repeated): an (n, 2) array."""
    pieces = [arc_points(e, sagitta) if e["kind"] == "arc" else numpy.array([e["start"]], dtype=float)
              for e in elements]
    return numpy.vstack(pieces) if pieces else numpy.empty((0, 2))


def write_random(file, seed, count):
    import ezdxf  # only the generated drawings need it: importing it costs a second per run
    from ezdxf import path as dxfpath
    rng = random.Random(seed)
    doc = ezdxf.new("R2000")
    doc.units = 4  # mm ($INSUNITS; ezdxf's default is metres)
    msp = doc.modelspace()
    for k in range(count):
        while True:
            n = rng.randint(4, 24)
            ox, oy = (k % 5) * 40.0, (k // 5) * 40.0
            pts = []
            for i in range(n):
                a = 2 * math.pi * (i + rng.uniform(-0.3, 0.3)) / n
                r = rng.uniform(4.0, 15.0)
                pts.append((ox + r * math.cos(a), oy + r * math.sin(a), 0, 0, rng.choice([0.0, 0.0, 1.0]) *
                            rng.uniform(-0.4, 0.4)))
            # keep the ones whose outline (as ezdxf reads the bulges) is a simple polygon
            e = msp.add_lwpolyline(pts, format="xyseb", close=True)
            flat = [(v.x, v.y) for v in dxfpath.make_path(e).flattening(1e-5)]
            if Polygon(flat).is_valid:
                break
            msp.delete_entity(e)
    doc.saveas(file)


def write_shape(path, name):
    import ezdxf
    doc = ezdxf.new("R2000")
    doc.units = 4  # mm ($INSUNITS; ezdxf's default is metres)
    msp = doc.modelspace()
    if name == "slot":  # a die with a channel 0.2 wide and 4 long: narrower than a 0.3 wire
        pts = [(0, 0), (20, 0), (20, 10), (10.1, 10), (10.1, 14), (9.9, 14), (9.9, 10), (0, 10)]
    elif name == "split":  # two squares joined by a neck 0.2 wide: the inside offset splits in two
        pts = [(0, 0), (10, 0), (10, 4.9), (15, 4.9), (15, 0), (25, 0), (25, 10), (15, 10), (15, 5.1),
               (10, 5.1), (10, 10), (0, 10)]
    else:
        raise SystemExit("unknown shape " + name)
    msp.add_lwpolyline(pts, close=True)
    doc.saveas(path)


def main():
    kerf, drawing, work = sys.argv[1], sys.argv[2], sys.argv[3]
    radii = [float(r) for r in sys.argv[4:]]
    os.makedirs(work, exist_ok=True)
    if drawing.startswith("random:"):
        _, seed, count = drawing.split(":")
        path = os.path.join(work, "random-%s.dxf" % seed)
        write_random(path, int(seed), int(count))
        drawing = path
    elif drawing.startswith("shape:"):
        path = os.path.join(work, "shape-%s.dxf" % drawing[6:])
        write_shape(path, drawing[6:])
        drawing = path
    cases = []
    for radius in radii:
        for side in ("outside", "inside"):
            run = subprocess.run([kerf, "check", "--json", "--offset", repr(radius), "--side", side, drawing],
                                 capture_output=True, text=True)
            if run.returncode > 1:
                raise SystemExit("kerf failed on %s: %s" % (drawing, run.stderr[-2000:]))
            report = json.loads(run.stdout)
            for number, c in enumerate(report["drawing"]["contours"], start=1):
                if "wire" not in c:
                    continue
                wire = c["wire"]
                if wire["degenerate"]:  # no area: Kerf cuts nothing there, and says so
                    cases.append({"file": os.path.basename(drawing), "contour": number, "degenerate": True})
                    continue
                outline = flatten(c["path"])
                contour = Polygon(outline)
                ccw = contour.exterior.is_ccw
                # the side Kerf took for this contour (holes get the other one)
                outside = (wire["offset"] < 0) == ccw
                # The region the contour encloses, as GEOS makes it valid (a contour that touches
                # itself at a point is still one region).
                region = contour if contour.is_valid else contour.buffer(0)
                geos = region.buffer(radius if outside else -radius, resolution=256, join_style=1)
                kerf_area = wire["signed_area"] * (1 if ccw else -1)
                lines = []
                flat_loops = 0  # loops of no area: the wire fits a slot exactly (GEOS: nothing)
                for loop in wire["loops"]:
                    fine = flatten(loop)
                    if len(fine) < 3 or abs(Polygon(fine).area) <= 1e-6 * sum(
                            math.dist(p["start"], p["end"]) for p in loop):
                        flat_loops += 1
                        continue
                    pts = flatten(loop, COARSE)
                    if len(pts) >= 2:
                        lines.append(LineString(numpy.vstack((pts, pts[:1]))))
                if geos.is_empty:
                    boundary = None
                else:
                    # Douglas-Peucker: the distance is all that is measured, so no topology is kept
                    boundary = geos.boundary.simplify(COARSE, preserve_topology=False)
                if lines and boundary is not None and not boundary.is_empty:
                    ours = MultiLineString(lines) if len(lines) > 1 else lines[0]
                    hausdorff = ours.hausdorff_distance(boundary)
                elif not lines and (boundary is None or boundary.is_empty):
                    hausdorff = 0.0
                else:
                    hausdorff = float("inf")
                parts = 0 if geos.is_empty else len(getattr(geos, "geoms", [geos]))
                cases.append({
                    "file": os.path.basename(drawing),
                    "contour": number,
                    "side": "outside" if outside else "inside",
                    "radius": radius,
                    "loops": len(wire["loops"]) - flat_loops,
                    "flat_loops": flat_loops,
                    "geos_parts": parts,
                    "kerf_area": kerf_area,
                    "geos_area": geos.area,
                    "area_error": abs(kerf_area - geos.area) / max(geos.area, 1e-12) if geos.area > 0 else abs(kerf_area),
                    # what the oracle's own flattening of the contour can change the buffer's area by
                    "area_slack": contour.length * SAGITTA,
                    "hausdorff": hausdorff,
                    "lost": len(wire["lost"]),
                    "lost_codes": [d["code"] for d in report["diagnostics"] if d["code"] in ("K0902", "K0903")],
                })
    print(json.dumps({"cases": cases}))


if __name__ == "__main__":
    main()
