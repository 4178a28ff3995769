#!/usr/bin/env python3
"""The CI workflow example of docs/ci.md, run as a runner would run its steps.

  ci_workflow_check.py DOCS_CI_MD KERF_DIR SAMPLES WORK

The YAML block after `<!-- ci-workflow -->` is parsed (python3-yaml); every `run:` step but the
install runs with `sh -e` (a container job's default shell) in a scratch folder whose programs/ are
the samples, with the kerf under test first on PATH. Twice:
- clean samples: every step passes, kerf.sarif is a SARIF log, kerf.xml JUnit, report/ has the
  index and a page, a picture and a 3D page per program;
- plus a program with an error: the report steps still pass (the error is in the SARIF and on its
  page), and the gate fails.
"""
import json
import os
import shutil
import subprocess
import sys

import yaml

doc, kerf_dir, samples, work = sys.argv[1:5]
text = open(doc, encoding="utf-8").read()
block = text.split("<!-- ci-workflow -->", 1)[1].split("```yaml", 1)[1].split("```", 1)[0]
workflow = yaml.safe_load(block)
steps = workflow["jobs"]["kerf"]["steps"]
runs = [s for s in steps if "run" in s and "install" not in s.get("name", "").lower()]
assert any("upload-sarif" in s.get("uses", "") for s in steps), "the workflow should upload the SARIF"
assert any("upload-artifact" in s.get("uses", "") for s in steps), "the workflow should keep the report"
assert len(runs) >= 4, f"expected the SARIF, JUnit, HTML report and gate steps, found {len(runs)}"
env = dict(os.environ, PATH=os.path.abspath(kerf_dir) + os.pathsep + os.environ["PATH"])
failures = []


def attempt(label, bad):
    folder = os.path.join(work, label)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(folder, "programs"))
    programs = [f for f in sorted(os.listdir(samples)) if f.endswith(".nc")]
    for f in programs:
        shutil.copy(os.path.join(samples, f), os.path.join(folder, "programs", f))
    if bad:
        with open(os.path.join(folder, "programs", "zz_bad.nc"), "w") as f:
            f.write("G21 G90\nG92 X0 Y0\nG02 X10 Y0 R4\nM30\n")
        programs.append("zz_bad.nc")
    codes = {}
    for step in runs:
        r = subprocess.run(["sh", "-e", "-c", step["run"]], cwd=folder, env=env, capture_output=True, text=True,
                           timeout=600)
        codes[step["name"]] = r.returncode
        print(f"{label}: step '{step['name']}' exit {r.returncode}")
        if r.returncode not in (0, 1) or (r.returncode and "gate" not in step["name"].lower()):
            failures.append(f"{label}: step '{step['name']}' exit {r.returncode}: {r.stderr[-400:]}")
    gate = [c for n, c in codes.items() if "gate" in n.lower()]
    if gate != [1 if bad else 0]:
        failures.append(f"{label}: the gate exited {gate}, expected {1 if bad else 0}")
    log = json.load(open(os.path.join(folder, "kerf.sarif")))
    results = log["runs"][0]["results"]
    has_error = any(r["level"] == "error" for r in results)
    if log["version"] != "2.1.0" or has_error != bad:
        failures.append(f"{label}: kerf.sarif version {log['version']}, error results {has_error}")
    if "<testsuites" not in open(os.path.join(folder, "kerf.xml"), encoding="utf-8").read():
        failures.append(f"{label}: kerf.xml is not a JUnit report")
    report = os.path.join(folder, "report")
    if not os.path.isfile(os.path.join(report, "index.html")):
        failures.append(f"{label}: no report/index.html")
        return
    for p in programs:
        for made in (p + ".html", p + ".3d.html", p + ".thumb.png", p + ".top.png", p + ".iso.png"):
            if not os.path.isfile(os.path.join(report, made)):
                failures.append(f"{label}: no report/{made}")
            elif made.endswith(".png"):
                with open(os.path.join(report, made), "rb") as f:
                    if f.read(8) != b"\x89PNG\r\n\x1a\n":
                        failures.append(f"{label}: {made} is not a PNG")
    if bad and "arc radius" not in open(os.path.join(report, "zz_bad.nc.html"), encoding="utf-8").read():
        failures.append(f"{label}: the error is not on zz_bad.nc's page")

attempt("clean", False)
attempt("with_error", True)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
