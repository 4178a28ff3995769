#!/usr/bin/env python3
"""kerf check --format sarif and --format junit over folders of real programs, checked by others.

  ci_reports_check.py KERF MULTITOOL WORK DIR...

- The SARIF log of every file under the folders is validated by Microsoft's SARIF Multitool
  (`validate`, from the npm registry; .ci/install-deps.sh --tests installs it): no result of level
  error. Its warnings are printed.
- SARIF and JUnit both carry what the text output carries: for each file, the diagnostics of
  `kerf check FILE --json` (the list the terminal shows) are the SARIF results of that file (code,
  line, column, level), and its errors are the lines of the JUnit testcase's failure.
- The JUnit XML is read back with xml.etree: one testcase per file, the failure and error counts.
"""
import json
import os
import subprocess
import sys
import urllib.parse
import xml.etree.ElementTree as ET

kerf, multitool, work, folders = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
os.makedirs(work, exist_ok=True)
failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def run(*args):
    return subprocess.run([kerf, *args], capture_output=True, text=True, errors="replace", timeout=600)


sarif_run = run("check", *folders, "--format", "sarif")
if sarif_run.returncode not in (0, 1):
    fail(f"kerf check --format sarif exited {sarif_run.returncode}: {sarif_run.stderr[-500:]}")
log_path = os.path.join(work, "kerf.sarif")
with open(log_path, "w") as f:
    f.write(sarif_run.stdout)
log = json.loads(sarif_run.stdout)
run0 = log["runs"][0]
def path_of(uri):
    path = urllib.parse.unquote(uri)
    return path[len("file://"):] if path.startswith("file://") else path


files = [path_of(a["location"]["uri"]) for a in run0["artifacts"]]
print(f"{len(files)} files, {len(run0['results'])} results, {len(run0['tool']['driver']['rules'])} rules")
if len(files) < 10:
    fail(f"only {len(files)} files found under {folders}")

# The independent validator.
validated = os.path.join(work, "validation.sarif")
if os.path.exists(validated):
    os.remove(validated)
env = dict(os.environ, DOTNET_SYSTEM_GLOBALIZATION_INVARIANT="1", DOTNET_CLI_TELEMETRY_OPTOUT="1")
v = subprocess.run([multitool, "validate", log_path, "-o", validated], capture_output=True, text=True, env=env,
                   timeout=600)
if v.returncode != 0 or not os.path.exists(validated):
    fail(f"the SARIF Multitool did not run (exit {v.returncode}): {v.stdout[-800:]} {v.stderr[-800:]}")
else:
    for r in json.load(open(validated))["runs"][0].get("results", []):
        level = r.get("level", "warning")
        text = r["message"].get("text") or str(r["message"].get("arguments", ""))
        print(f"multitool {level} {r['ruleId']}: {text[:200]}")
        if level == "error":
            fail(f"the SARIF Multitool says {r['ruleId']}: {text[:300]}")

# Per file: the text output's diagnostics (as --json lists them) against SARIF and JUnit.
by_file = {}
for r in run0["results"]:
    loc = r["locations"][0]["physicalLocation"]
    name = path_of(loc["artifactLocation"]["uri"])
    region = loc.get("region", {})
    # A finding about the whole file spans all its lines, with no column (--json gives no line).
    line = region.get("startLine") if "startColumn" in region else None
    by_file.setdefault(name, []).append((r["ruleId"], line, region.get("startColumn"), r["level"]))

junit_run = run("check", *folders, "--format", "junit")
suite = ET.fromstring(junit_run.stdout)
cases = {os.path.normpath(c.get("name")): c for c in suite.iter("testcase")}
if len(cases) != len(files):
    fail(f"JUnit has {len(cases)} testcases for {len(files)} files")
failed_cases = sum(1 for c in cases.values() if c.find("failure") is not None)
if suite.get("failures") != str(failed_cases):
    fail(f"JUnit says {suite.get('failures')} failures, its testcases {failed_cases}")

for name in files:
    one = run("check", name, "--json")
    if one.returncode == 2:
        fail(f"{name}: not read ({one.stderr[-300:]})")
        continue
    shown = json.loads(one.stdout)["diagnostics"]
    expected = sorted((d["code"], d.get("line"), d.get("column"), d["severity"]) for d in shown)
    got = sorted(by_file.get(name, []), key=str)
    if sorted(expected, key=str) != got:
        fail(f"{name}: SARIF carries {got[:5]}... for the text output's {expected[:5]}...")
    case = cases.get(name)
    if case is None:
        fail(f"{name}: no JUnit testcase")
        continue
    errors = [d for d in shown if d["severity"] == "error"]
    failure = case.find("failure")
    if bool(errors) != (failure is not None):
        fail(f"{name}: {len(errors)} errors, JUnit failure {failure is not None}")
    if failure is not None:
        lines = [l for l in (failure.text or "").splitlines() if l.strip() and not l.startswith("(")]
        if len(lines) != len(errors) or any(f"[{e['code']}]" not in l for e, l in zip(errors, lines)):
            fail(f"{name}: the JUnit failure lists {lines[:3]} for errors {[e['code'] for e in errors][:3]}")

print(f"{len(files)} files: SARIF valid and complete, JUnit complete" if not failures else f"{len(failures)} failures")
sys.exit(1 if failures else 0)
