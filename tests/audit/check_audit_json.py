"""Checks `fdhcert audit --json`'s certificate (docs/formats.md, "audit output") against what the
run must have decided: every frame and step, the exit status agreeing with the verdict, the
counts adding up. Prints the summary line and what is wrong; exit status 1 when anything is.
  check_audit_json.py AUDIT.json OUT_DIR --frames F --status S [--cloth-vertices N]
"""

import argparse
import json
import os
import sys


def problems(report, out_dir, a):
    frames = report.get("frames")
    if frames != a.frames:
        yield f"frames {frames}, expected {a.frames} (every frame decided)"
    if report.get("steps") != a.frames - 1:
        yield f"steps {report.get('steps')}, expected {a.frames - 1}"
    per_frame = report.get("per_frame", [])
    if len(per_frame) != a.frames:
        yield f"{len(per_frame)} per_frame entries, expected {a.frames}"
    if a.cloth_vertices is not None and report["cloth"]["vertices"] != a.cloth_vertices:
        yield f"cloth vertices {report['cloth']['vertices']}, expected {a.cloth_vertices}"
    total = report["violations"]
    if sum(report["totals"].values()) != total:
        yield f"totals {report['totals']} do not add up to violations {total}"
    per_frame_sum = sum(v for f in per_frame for k, v in f.items() if k != "frame")
    if per_frame_sum != total:
        yield f"per_frame counts add up to {per_frame_sum}, not violations {total}"
    if report["clean"] != (total == 0):
        yield f"clean {report['clean']} with {total} violations"
    if (a.status == 0) != report["clean"]:
        yield f"exit status {a.status} with clean {report['clean']}"
    if report["clean"] != (report["first_violation"] is None):
        yield "first_violation given for a clean run, or missing for a violating one"
    if not os.path.isfile(os.path.join(out_dir, "audit.json")):
        yield f"no audit.json in {out_dir}"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("json")
    p.add_argument("out_dir")
    p.add_argument("--frames", type=int, required=True)
    p.add_argument("--status", type=int, required=True)
    p.add_argument("--cloth-vertices", type=int)
    a = p.parse_args()
    try:
        with open(a.json) as f:
            report = json.load(f)
        found = list(problems(report, a.out_dir, a))
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"{a.json}: not a certificate: {e!r}")
        return 1
    print(f"{a.json}: {report['summary']}")
    for what in found:
        print(f"  {what}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
