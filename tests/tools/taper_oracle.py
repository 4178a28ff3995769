#!/usr/bin/python3
"""Corners rounded and chamfered (`,R`, `,C`, NCVC's R and its taper corner models) and the wire
offset on 4-axis programs, against GEOS (Debian's python3-shapely): an independent construction
of each plane's contour (issue 55).

usage: taper_oracle.py KERF TAPER_DIR WORKDIR

For each case below: `KERF export PROGRAM -o WORKDIR/NAME.dxf`, its LOWER and UPPER layers read
with ezdxf, the moves from and to the start hole left out (a taper's start-up and cancel), and the
rest held against the contour GEOS builds from the sharp programmed polygon:
  - opening by r (buffer -r, then +r with round joins) rounds convex corners by r, closing by r
    (+r with mitre joins, then -r round) rounds concave ones;
  - the taper's offset d = H tan(angle) of the sharp polygon is buffer(-d) with mitre joins (sharp
    corners, the offset elements extended to meet); of a rounded contour, buffer(-d) (a cone);
  - a chamfer c is the polygon less the corner triangles of legs c;
  - the wire's path w outside a contour is buffer(w) with round joins (arcs about convex corners),
    inside a rounded contour buffer(-w).
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

D2 = 20 * math.tan(math.radians(2))  # the die cut with the wire offset: 2 degrees
RECT2 = Polygon([(2, 2), (38, 2), (38, 18), (2, 18)])  # the frustum's upper face
W = 0.15  # the wire offset, mm


def outward(p, w):
    """The wire's path outside a contour: its offsets joined by arcs about the convex corners."""
    return p.buffer(w, join_style=ROUND, resolution=RES)


def wing_section(s):
    """tests/taper/foam_wing_workpiece.nc cut at s of the way from the X Y carriage to the U V one: each
    move's two sides at the same t (proportional to length), the nose's XY arc with its straight U V."""
    def mix(a, b):
        return ((1 - s) * a[0] + s * b[0], (1 - s) * a[1] + s * b[1])
    pts = [mix((0, 0), (20, 4)), mix((100, 0), (80, 4))]
    for k in range(1, 20000):
        t = k / 20000
        a = math.pi * (-0.5 + t)
        pts.append(mix((100 + 10 * math.cos(a), 10 + 10 * math.sin(a)), (80, 4 + 12 * t)))
    pts += [mix((100, 20), (80, 16)), mix((0, 20), (20, 16))]
    return Polygon(pts)


S0, S1 = 100 / 600, 400 / 600  # the foam block's faces between the carriages at z 0 and 600

# Each case: its program, the options to read it with, each layer's expected polygon, the start hole
# (moves from and to it are left out), and on the upper plane the start-up's gap (centre, radius).
CASES = [
    dict(name="rectangle_r", program="rectangle_corner_r.nc", layers={"LOWER": opening(RECT, 2)}),
    dict(name="rectangle_c", program="rectangle_chamfer.nc", layers={"LOWER": chamfered(RECT, 1.5)}),
    dict(name="l_shape", program="l_shape_corner_r_c.nc", layers={"LOWER": opening(closing(L_SHAPE, 3), 1)}),
    dict(name="cap_line_arc", program="cap_line_arc.nc", layers={"LOWER": opening(CAP, 1)}),
    dict(name="taper_equal", program="ncvc_taper_equal.nc", hole=(20, 10), gap=((20, D), D),
         layers={"LOWER": opening(RECT, 2), "UPPER": opening(inset(RECT, D), 2)}),
    dict(name="taper_conical", program="ncvc_taper_conical.nc", hole=(20, 10), gap=((20, D), D),
         layers={"LOWER": opening(RECT, 2),
                 "UPPER": opening(RECT, 2).buffer(-D, join_style=ROUND, resolution=RES)}),
    dict(name="taper_independent", program="ncvc_taper_independent.nc", hole=(20, 10), gap=((20, D), D),
         layers={"LOWER": opening(RECT, 2), "UPPER": opening(inset(RECT, D), 3)}),
    # The wire offset on a taper-angle program: the programmed contour offset on the program plane
    # (inside the die: its rounded corners shrink to R 1.85), the taper from that path (outwards
    # by 20 tan 2), its corners equal-radius: R 1.85 on the upper plane too.
    dict(name="taper_die_offset", program="ncvc_taper_die_offset.nc", options=["--offset", str(W)], hole=(20, 10),
         gap=((20, W - D2), D2),
         layers={"LOWER": opening(RECT, 2).buffer(-W, join_style=ROUND, resolution=RES),
                 "UPPER": opening(inset(RECT, W - D2), 2 - W)}),
    # Charmilles (robofil profile) G28: sharp corners tapered into arcs about each corner (the upper
    # face: the sides offset outwards by 20 tan 3, joined by arcs of that radius: buffer with round
    # joins); G29: arcs tapered into cylinders (R 2 on both faces, tangent to each face's sides).
    dict(name="robofil_g28", program="robofil_g28_die.nc", options=["--machine", "robofil", "--thickness", "20"],
         hole=(20, 10), gap=((20, -D), D),
         layers={"LOWER": RECT, "UPPER": RECT.buffer(D, join_style=ROUND, resolution=RES)}),
    dict(name="robofil_g29", program="robofil_g29_die.nc", options=["--machine", "robofil", "--thickness", "20"],
         hole=(20, 10), gap=((20, -D), D),
         layers={"LOWER": opening(RECT, 2), "UPPER": opening(RECT.buffer(D, join_style=MITRE, mitre_limit=10,
                                                                        resolution=RES), 2)}),
    # --workpiece: a foam program's carriages are the machine's planes; the part is cut between the
    # block's faces (exact sections of the straight moves, the nose's within 1 um).
    dict(name="foam_workpiece", program="foam_wing_workpiece.nc", options=["--workpiece", "100,400"],
         holes=[(-10 + 20 * S0, 4 * S0), (-10 + 20 * S1, 4 * S1)],
         layers={"LOWER": wing_section(S0), "UPPER": wing_section(S1)}),
    # The wire offset on a two-contour program: each plane's contour offset by the same value.
    dict(name="xyuv_frustum_offset", program="xyuv_frustum_offset.nc",
         options=["--offset", str(W), "--thickness", "10"], hole=(-5, 10),
         layers={"LOWER": outward(RECT, W), "UPPER": outward(RECT2, W)}),
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


def densify(coords):
    """The ring's vertices and points at most STEP apart between them: a side Kerf left out is found."""
    pts = list(coords)
    out = []
    for a, b in zip(pts, pts[1:]):
        n = max(1, int(math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / STEP)))
        out += [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n)]
    return out


def touches(pts, hole):
    return hole is not None and any(math.hypot(p[0] - hole[0], p[1] - hole[1]) < 1e-6 for p in (pts[0], pts[-1]))


def main():
    kerf, corners, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    failed = 0
    for case in CASES:
        name, layers = case["name"], case["layers"]
        holes, gap = case.get("holes", [case["hole"]] if "hole" in case else []), case.get("gap")
        out = os.path.join(work, name + ".dxf")
        r = subprocess.run([kerf, "export", os.path.join(corners, case["program"]), "-o", out] + case.get("options", []),
                           capture_output=True, text=True)
        if r.returncode != 0:
            print(f"{name}: kerf export failed ({r.returncode}): {r.stderr[-2000:]}")
            failed += 1
            continue
        doc = ezdxf.readfile(out)
        for layer, expected in layers.items():
            ring = expected.exterior
            pieces = [sample(e) for e in doc.modelspace() if e.dxf.layer == layer and e.dxftype() in ("LINE", "ARC")]
            pieces = [p for p in pieces if not any(touches(p, h) for h in holes)]
            if not pieces:
                print(f"{name} {layer}: no elements")
                failed += 1
                continue
            kerf_to_geos = max(ring.distance(Point(p)) for piece in pieces for p in piece)
            cut = MultiLineString([LineString(p) for p in pieces])
            centre, skip = gap if layer == "UPPER" and gap else ((0, 0), 0.0)
            skip = 1.01 * skip + 1e-3 if skip else 0.0
            probes = [Point(q) for q in densify(ring.coords)
                      if not skip or math.hypot(q[0] - centre[0], q[1] - centre[1]) > skip]
            geos_to_kerf = max(cut.distance(p) for p in probes)
            worst = max(kerf_to_geos, geos_to_kerf)
            ok = worst <= TOLERANCE
            failed += not ok
            print(f"{name} {layer}: Kerf to GEOS {kerf_to_geos * 1000:.3f} um, GEOS to Kerf {geos_to_kerf * 1000:.3f} um"
                  f" {'ok' if ok else 'FAILED'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
