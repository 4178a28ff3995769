#!/usr/bin/env python3
"""kerf export PROGRAM -o out.dxf, read back by ezdxf (Debian's python3-ezdxf): an independent
reader. For R12 and R2000 it checks that ezdxf reads the file with the version asked for, that its
audit finds no error, that every entity is a LINE, ARC or CIRCLE on the layers Kerf documents, and
that the length on layer LOWER (and UPPER) equals the cut length `kerf check --json` reports for the
same program, and UPPER sits at the upper plane's height. A program cut in several passes puts pass
k on LOWER_PASSk (and UPPER_PASSk): each as long as the passes numbered k in the structure that
`kerf check --json` reports (docs/passes.md). Then Kerf reads its own drawing back
(`kerf check out.dxf --json`): as many contours, as long.

usage: dxf_export_check.py KERF PROGRAM WORKDIR [kerf options...]
exit 0 when everything holds; otherwise prints what did not and exits 1."""
import json
import math
import os
import subprocess
import sys

import ezdxf

kerf, program, work = sys.argv[1], sys.argv[2], sys.argv[3]
extra = sys.argv[4:]
os.makedirs(work, exist_ok=True)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def kerf_json(path, options):
    r = subprocess.run([kerf, "check", "--json", path] + options, capture_output=True, text=True)
    if r.returncode >= 2:
        sys.exit(f"kerf check {path} failed ({r.returncode}): {r.stderr[:2000]}")
    return json.loads(r.stdout)


def length(e):
    t = e.dxftype()
    if t == "LINE":
        return math.dist(e.dxf.start, e.dxf.end)
    if t == "CIRCLE":
        return 2 * math.pi * e.dxf.radius
    sweep = (e.dxf.end_angle - e.dxf.start_angle) % 360.0
    return math.radians(sweep) * e.dxf.radius


summary = kerf_json(program, extra)["summary"]
taper = summary.get("taper")
want = {"LOWER": taper["lower_length_mm"] if taper else summary["cut_length_mm"]}
if taper:
    want["UPPER"] = taper["upper_length_mm"]
contours = summary.get("structure", {}).get("contours", [])
by_pass = max((len(c["passes"]) for c in contours), default=0) > 1
if by_pass:  # the lower plane's length of each pass number; the upper one's only its layer
    want = {}
    for c in contours:
        for k, p in enumerate(c["passes"], 1):
            want[f"LOWER_PASS{k}"] = want.get(f"LOWER_PASS{k}", 0.0) + p["length_mm"]
layers = {"LOWER", "UPPER", "PROGRAMMED", "RAPID"} | {
    f"{plane}_PASS{k}" for plane in ("LOWER", "UPPER") for k in range(1, 256)}

stem = os.path.splitext(os.path.basename(program))[0]
for version, acad in (("r12", "AC1009"), ("r2000", "AC1015")):
    out = os.path.join(work, f"{stem}.{version}.dxf")
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([kerf, "export", program, "-o", out, "--dxf", version] + extra, capture_output=True, text=True)
    check(r.returncode < 2, f"{version}: kerf export exited {r.returncode}: {r.stderr[-500:]}")
    if r.returncode >= 2:
        continue
    doc = ezdxf.readfile(out)
    check(doc.dxfversion == acad, f"{version}: ezdxf reads version {doc.dxfversion}, not {acad}")
    audit = doc.audit()
    check(not audit.has_errors, f"{version}: ezdxf audit errors: {[e.message for e in audit.errors]}")
    per_layer = {}
    heights = {}
    for e in doc.modelspace():
        check(e.dxftype() in ("LINE", "ARC", "CIRCLE"), f"{version}: unexpected entity {e.dxftype()}")
        layer = e.dxf.layer
        check(layer in layers, f"{version}: unexpected layer {layer}")
        per_layer[layer] = per_layer.get(layer, 0.0) + length(e)
        z = e.dxf.start[2] if e.dxftype() == "LINE" else e.dxf.center[2]
        heights.setdefault(layer.split("_")[0], set()).add(round(z, 9))
    for layer, mm in want.items():
        got = per_layer.get(layer, 0.0)
        check(abs(got - mm) <= 1e-6 * max(1.0, mm), f"{version}: layer {layer} is {got:.9f} mm long, kerf check says {mm:.9f}")
    if taper:
        check(heights.get("UPPER") == {round(taper["upper_z"], 9)},
              f"{version}: UPPER at z {heights.get('UPPER')}, not {taper['upper_z']}")
        check(heights.get("LOWER") == {round(taper["lower_z"], 9)},
              f"{version}: LOWER at z {heights.get('LOWER')}, not {taper['lower_z']}")
    # Kerf reads its own drawing: everything on it chains into contours as long as the layers.
    back = kerf_json(out, [])
    total = sum(c["length"] for c in back["drawing"]["contours"])
    check(abs(total - sum(per_layer.values())) <= 1e-6 * max(1.0, total),
          f"{version}: kerf reads {total:.9f} mm back, ezdxf {sum(per_layer.values()):.9f}")
    print(f"{version}: {sum(1 for _ in doc.modelspace())} entities, layers "
          + ", ".join(f"{k} {v:.6f} mm" for k, v in sorted(per_layer.items())))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
