#!/usr/bin/env python3
"""Seed 003 (CAWEP), Table 1, through the kerf program: the sine y = 10 sin(x/10), x in [0, 20],
and the involute x = 10(cos t + t sin t), y = 10(sin t - t cos t), t in [0, 2], given as --curve
expressions and fitted with biarcs at +-0.005 mm. CAWEP needs 16 and 14 nodes, with span errors of
1.2-4.3 um.

For each curve: `kerf check --curve ... --json` gives the nodes and each span's error; `kerf export
--curve ... -o curve.dxf` writes the arcs, which ezdxf reads back; the error of every span is then
measured here, independently of Kerf, as the largest distance from 20,001 points of the true curve
(evaluated in Python) to the arcs. Holds when the nodes are no more than CAWEP's and every span is
within 5 um by both measures (and the two measures agree within 0.1 um).

usage: curve_table1_check.py KERF WORKDIR"""
import json
import math
import os
import subprocess
import sys

import ezdxf

kerf, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
CURVES = [
    ("sine", "x = t; y = 10*sin(t/10)", "0:20", lambda t: (t, 10 * math.sin(t / 10)), 16),
    ("involute", "x = 10*(cos(t) + t*sin(t)); y = 10*(sin(t) - t*cos(t))", "0:2",
     lambda t: (10 * (math.cos(t) + t * math.sin(t)), 10 * (math.sin(t) - t * math.cos(t))), 14),
]
failures = []


def arc_distance(p, arc):
    cx, cy, r, a0, a1 = arc
    ang = math.degrees(math.atan2(p[1] - cy, p[0] - cx)) % 360.0
    sweep = (a1 - a0) % 360.0
    if (ang - a0) % 360.0 <= sweep:
        return abs(math.hypot(p[0] - cx, p[1] - cy) - r)
    ends = [(cx + r * math.cos(math.radians(a)), cy + r * math.sin(math.radians(a))) for a in (a0, a1)]
    return min(math.dist(p, e) for e in ends)


def line_distance(p, line):
    (ax, ay), (bx, by) = line
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    u = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2))
    return math.hypot(p[0] - ax - u * dx, p[1] - ay - u * dy)


for name, expr, t_range, f, cawep in CURVES:
    args = ["--curve", expr, "--t", t_range, "--curve-tolerance", "0.005"]
    r = subprocess.run([kerf, "check", "--json"] + args, capture_output=True, text=True)
    if r.returncode >= 2:
        sys.exit(f"kerf check failed: {r.stderr}")
    curve = json.loads(r.stdout)["drawing"]["curve"]
    spans = curve["spans"]
    out = os.path.join(work, f"{name}.dxf")
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([kerf, "export", "-o", out] + args, capture_output=True, text=True)
    if r.returncode >= 2:
        sys.exit(f"kerf export failed: {r.stderr}")
    arcs, lines = [], []
    for e in ezdxf.readfile(out).modelspace():
        if e.dxftype() == "ARC":
            arcs.append((e.dxf.center[0], e.dxf.center[1], e.dxf.radius, e.dxf.start_angle, e.dxf.end_angle))
        elif e.dxftype() == "LINE":
            lines.append(((e.dxf.start[0], e.dxf.start[1]), (e.dxf.end[0], e.dxf.end[1])))

    def distance(p):
        return min([arc_distance(p, a) for a in arcs] + [line_distance(p, l) for l in lines])

    nodes = len(spans) + 1
    print(f"{name}: {nodes} nodes (CAWEP {cawep}), {len(arcs)} arcs, {len(lines)} lines")
    print("  span        t0         t1   kerf um  measured um")
    if nodes > cawep:
        failures.append(f"{name}: {nodes} nodes, CAWEP needs {cawep}")
    worst = 0.0
    for k, s in enumerate(spans):
        measured = max(distance(f(s["t0"] + (s["t1"] - s["t0"]) * i / 20000)) for i in range(20001))
        worst = max(worst, measured)
        print(f"  {k + 1:4d} {s['t0']:10.6f} {s['t1']:10.6f} {s['error_mm'] * 1000:9.3f} {measured * 1000:12.3f}")
        if measured > 0.005 or s["error_mm"] > 0.005:
            failures.append(f"{name}: span {k + 1} is {measured * 1000:.3f} um off (kerf says {s['error_mm'] * 1000:.3f})")
        if abs(measured - s["error_mm"]) > 1e-4:
            failures.append(f"{name}: span {k + 1}: kerf says {s['error_mm'] * 1000:.3f} um, measured {measured * 1000:.3f}")
    print(f"  largest {worst * 1000:.3f} um (CAWEP's spans: 1.2-4.3 um)")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
