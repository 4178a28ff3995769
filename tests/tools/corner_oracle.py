#!/usr/bin/python3
"""Corners rounded and chamfered (`,R`, `,C`, NCVC's R and its taper corner models) against GEOS
(Debian's python3-shapely): an independent construction of each plane's contour.

usage: corner_oracle.py KERF CORNERS_DIR WORKDIR

For each case below: `KERF export PROGRAM -o WORKDIR/NAME.dxf`, its LOWER and UPPER layers read
with ezdxf, the moves from and to the start hole left out (a taper's start-up and cancel), and the
rest held against the contour GEOS builds from the sharp programmed polygon:
  - opening by r (buffer -r, then +r with round joins) rounds convex corners by r, closing by r
    (+r with mitre joins, then -r round) rounds concave ones;
  - the taper's offset d = H tan(angle) of the sharp polygon is buffer(-d) with mitre joins (sharp
    corners, the offset elements extended to meet); of a rounded contour, buffer(-d) (a cone);
  - a chamfer c is the polygon less the corner triangles of legs c.
Both ways (Kerf to GEOS, GEOS to Kerf, except on the upper plane within the start-up's gap), the
largest distance must be within 2 um. Prints one line a case; exit 1 if any fails.
"""
import math
import os
import subprocess
import sys

import ezdxf
from shapely.geometry import LineString, MultiLineString, Point, Polygon

TOLERANCE = 0.002  # mm
RES = 512  # GEOS buffer segments per quarter circle: sagitta of r = 3 mm below 1e-5 mm
STEP = 0.02  # mm between the points Kerf's elements are sampled at

MITRE, ROUND = 2, 1


def opening(p, r):
    return p.buffer(-r, join_style=MITRE, resolution=RES).buffer(r, join_style=ROUND, resolution=RES)


def closing(p, r):
    return p.buffer(r, join_style=MITRE, resolution=RES).buffer(-r, join_style=ROUND, resolution=RES)


def inset(p, d):
    """The sharp offset d inwards (the taper's offset of a contour leaning into it)."""
    return p.buffer(-d, join_style=MITRE, mitre_limit=10, resolution=RES)


def chamfered(p, c):
    out = p
    pts = list(p.exterior.coords)[:-1]
    n = len(pts)
    for k in range(n):
        a, b, nxt = pts[k - 1], pts[k], pts[(k + 1) % n]
        u = (a[0] - b[0], a[1] - b[1])
        v = (nxt[0] - b[0], nxt[1] - b[1])
        lu, lv = math.hypot(*u), math.hypot(*v)
        tri = Polygon([b, (b[0] + c * u[0] / lu, b[1] + c * u[1] / lu), (b[0] + c * v[0] / lv, b[1] + c * v[1] / lv)])
        out = out.difference(tri)
    return out


RECT = Polygon([(0, 0), (40, 0), (40, 20), (0, 20)])
L_SHAPE = Polygon([(0, 0), (30, 0), (30, 10), (10, 10), (10, 30), (0, 30)])
# 30 x 20 with an arc of radius 15 from (30, 0) to (30, 20) bulging to +x.
_cx = 30 - math.sqrt(15 ** 2 - 10 ** 2)
_cap = [(_cx + 15 * math.cos(a), 10 + 15 * math.sin(a))
        for a in [-math.asin(10 / 15) + 2 * math.asin(10 / 15) * k / 4096 for k in range(4097)]]
CAP = Polygon([(0, 0)] + _cap + [(0, 20)])
D = 20 * math.tan(math.radians(3))  # the NCVC dies: 20 mm thick, 3 degrees

CASES = [
    # name, program, {layer: expected polygon}, start hole (x, y) or None, upper gap centre or None
    ("rectangle_r", "rectangle_corner_r.nc", {"LOWER": opening(RECT, 2)}, None, None),
    ("rectangle_c", "rectangle_chamfer.nc", {"LOWER": chamfered(RECT, 1.5)}, None, None),
    ("l_shape", "l_shape_corner_r_c.nc", {"LOWER": opening(closing(L_SHAPE, 3), 1)}, None, None),
    ("cap_line_arc", "cap_line_arc.nc", {"LOWER": opening(CAP, 1)}, None, None),
    ("taper_equal", "ncvc_taper_equal.nc",
     {"LOWER": opening(RECT, 2), "UPPER": opening(inset(RECT, D), 2)}, (20, 10), (20, D)),
    ("taper_conical", "ncvc_taper_conical.nc",
     {"LOWER": opening(RECT, 2), "UPPER": opening(RECT, 2).buffer(-D, join_style=ROUND, resolution=RES)},
     (20, 10), (20, D)),
    ("taper_independent", "ncvc_taper_independent.nc",
     {"LOWER": opening(RECT, 2), "UPPER": opening(inset(RECT, D), 3)}, (20, 10), (20, D)),
]


def sample(e):
    """Points along a LINE or ARC entity, at most STEP apart."""
    if e.dxftype() == "LINE":
        a, b = e.dxf.start, e.dxf.end
        n = max(1, int(math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / STEP)))
        return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n + 1)]
    c, r = e.dxf.center, e.dxf.radius
    a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
    if a1 <= a0:
        a1 += 2 * math.pi
    n = max(2, int(math.ceil((a1 - a0) * r / STEP)), int(math.ceil((a1 - a0) / 0.002)))
    return [(c[0] + r * math.cos(a0 + (a1 - a0) * k / n), c[1] + r * math.sin(a0 + (a1 - a0) * k / n))
            for k in range(n + 1)]


def touches(pts, hole):
    return hole is not None and any(math.hypot(p[0] - hole[0], p[1] - hole[1]) < 1e-6 for p in (pts[0], pts[-1]))


def main():
    kerf, corners, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    failed = 0
    for name, program, layers, hole, gap in CASES:
        out = os.path.join(work, name + ".dxf")
        r = subprocess.run([kerf, "export", os.path.join(corners, program), "-o", out], capture_output=True, text=True)
        if r.returncode != 0:
            print(f"{name}: kerf export failed ({r.returncode}): {r.stderr[-2000:]}")
            failed += 1
            continue
        doc = ezdxf.readfile(out)
        for layer, expected in layers.items():
            ring = expected.exterior
            pieces = [sample(e) for e in doc.modelspace() if e.dxf.layer == layer and e.dxftype() in ("LINE", "ARC")]
            pieces = [p for p in pieces if not touches(p, hole)]
            if not pieces:
                print(f"{name} {layer}: no elements")
                failed += 1
                continue
            kerf_to_geos = max(ring.distance(Point(p)) for piece in pieces for p in piece)
            cut = MultiLineString([LineString(p) for p in pieces])
            skip = 1.01 * D + 1e-3 if layer == "UPPER" and gap else 0.0
            probes = [Point(q) for q in ring.coords
                      if not skip or math.hypot(q[0] - gap[0], q[1] - gap[1]) > skip]
            dense = ring.segmentize(STEP) if hasattr(ring, "segmentize") else ring
            probes += [Point(q) for q in dense.coords if not skip or math.hypot(q[0] - gap[0], q[1] - gap[1]) > skip]
            geos_to_kerf = max(cut.distance(p) for p in probes)
            worst = max(kerf_to_geos, geos_to_kerf)
            ok = worst <= TOLERANCE
            failed += not ok
            print(f"{name} {layer}: Kerf to GEOS {kerf_to_geos * 1000:.3f} um, GEOS to Kerf {geos_to_kerf * 1000:.3f} um"
                  f" {'ok' if ok else 'FAILED'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
