#!/usr/bin/python3
"""The peer's acceptance test (../shared/realworld/peer-tests/wireedmparser-z39RobofilPost.test.ts,
a post whose output cut a real part on a Charmilles Robofil 100), held for Kerf.

usage: z39_peer_check.py KERF DXF WORKDIR

Runs `kerf cam DXF --machine robofil --offset-by controller` with the peer's placement (the drawing
moved by (6.894299, -19.024251), the contour started at its vertex nearest (-1.2, -18.946), the wire
threaded at (0, 0)), then checks what the peer checks: one contour of 156 elements, 78 G3 blocks,
cut length 178.637 mm, enclosed area 1216.888 mm^2, the first lines, absolute I J at 3 decimals
equal to the drawing's arc centres, start/end radius mismatch <= 0.001106 mm, CRLF only, M02 last,
no G21/G17/G54/G40/M30; and that `kerf check` of the program, with the machine's D0 register in an
--offsets table, finds nothing wrong (no warning).
Exit 0 when everything holds; otherwise every failure is printed.
"""
import json
import math
import os
import re
import subprocess
import sys

SHIFT = (6.894299, -19.024251)


def main():
    kerf, dxf, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "z39.iso")
    failures = []

    def expect(cond, what):
        if not cond:
            failures.append(what)

    run = subprocess.run([kerf, "cam", dxf, "--machine", "robofil", "--offset-by", "controller", "--shift",
                          "%r,%r" % SHIFT, "--start", "-1.2,-18.946", "--entry", "0,0", "-o", out],
                         capture_output=True, text=True)
    expect(run.returncode == 0, "kerf cam exit %d: %s" % (run.returncode, run.stderr[-1500:]))
    if run.returncode != 0:
        print("\n".join(failures))
        return 1
    m = re.search(r"contour 1: outside, (\d+) elements, ([\d.]+) mm, area ([\d.]+)", run.stderr)
    expect(m is not None, "no contour summary in: " + run.stderr)
    if m:
        expect(int(m.group(1)) == 156, "elements %s, not 156" % m.group(1))
        expect(abs(float(m.group(2)) - 178.637) <= 0.0005, "cut length %s, not 178.637" % m.group(2))
        expect(abs(float(m.group(3)) - 1216.888) <= 0.0015, "area %s, not 1216.888" % m.group(3))
    expect(len(re.findall(r"kerf: contour", run.stderr)) == 1, "more than one contour")
    raw = open(out, "rb").read().decode("ascii")
    expect(raw.endswith("M02\r\n"), "the program does not end with M02 CRLF")
    expect(re.search(r"(?<!\r)\n", raw) is None, "a line ends without CR")
    body = raw.replace("\r\n", "\n")
    lines = body.rstrip("\n").split("\n")
    expect(lines[:5] == ["G92 X0.000 Y0.000", "G60", "G38", "G42 D0", "G90"], "first lines %r" % lines[:5])
    expect(lines[5:7] == ["G1 X-1.200 Y-18.946", "G1 X-0.500 Y-20.228"], "lead-in lines %r" % lines[5:7])
    expect(lines[-1] == "M02", "last line %r" % lines[-1])
    expect(re.search(r"\b(?:G21|G17|G54|G40|M30)\b", body) is None, "a forbidden code is written")
    expect(not any(l.startswith("G0 ") or l.startswith("G00") for l in lines), "a rapid is written")

    # The drawing's own arc centres (kerf check --json: exact elements), moved as the peer moves them.
    report = json.loads(subprocess.run([kerf, "check", "--json", "--offset", "0.1", "--side", "outside", dxf],
                                       capture_output=True, text=True).stdout)
    centres = {(round(e["centre"][0] + SHIFT[0], 3), round(e["centre"][1] + SHIFT[1], 3))
               for e in report["drawing"]["contours"][0]["path"] if e["kind"] == "arc"}
    at = None
    arcs = 0
    worst = 0.0
    for line in lines:
        words = dict((k, float(v)) for k, v in re.findall(r"\b([XYIJ])([+-]?(?:\d+(?:\.\d*)?|\.\d+))", line))
        if line.startswith("G3 ") or line.startswith("G2 "):
            arcs += line.startswith("G3 ")
            expect((words["I"], words["J"]) in centres, "I J %r is not a drawing centre" % line)
            expect(re.search(r"I-?\d+\.\d{3}\b", line) and re.search(r"J-?\d+\.\d{3}\b", line), "I J not at 3 decimals")
            r0 = math.hypot(at[0] - words["I"], at[1] - words["J"])
            r1 = math.hypot(words["X"] - words["I"], words["Y"] - words["J"])
            worst = max(worst, abs(r0 - r1))
        if "X" in words and "Y" in words:
            at = (words["X"], words["Y"])
    expect(arcs == 78, "%d G3 blocks, not 78" % arcs)
    expect(worst <= 0.001106 + 1e-9, "radius mismatch %.6f above 0.001106" % worst)

    # --offset-by controller leaves the offset to the machine's register D0; the shop's table gives
    # it (0.1 mm, as the drawing's check above), so the check sees the wire path the machine cuts.
    table = os.path.join(work, "robofil.offsets")
    with open(table, "w") as f:
        f.write("D000 = 0.1\n")
    check = subprocess.run([kerf, "check", "--machine", "robofil", "--offsets", table, out], capture_output=True,
                           text=True)
    expect(check.returncode == 0, "kerf check exit %d" % check.returncode)
    expect(re.search(r": (error|warning):", check.stderr) is None, "kerf check is not clean:\n" + check.stderr)
    print("z39 Robofil post: %d G3 blocks, radius mismatch %.6f mm, %d lines%s" %
          (arcs, worst, len(lines), "" if not failures else "; FAILED:\n  " + "\n  ".join(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
