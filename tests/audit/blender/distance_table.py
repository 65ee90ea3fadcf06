"""How often a simulator keeps the distance it promised: `fdhcert audit --min-distance D` over
bake folders at each D asked, as one Markdown table (docs/audit.md, "Blender's distance").

  distance_table.py FDHCERT [--distance D]... FOLDER...

FOLDER holds one OBJ per frame (tests/audit/blender/bake_cloth.py writes them); each is audited
at each D (default Blender's 0.015 m and half of it, 0.0075 m) with the default rule on pairs near
by construction. A frame keeps the self distance when neither it nor the step into it has a
self- kind (intersection or proximity: cloth against cloth); the object distance likewise with
the obstacle kinds. The nearest pairs are the certificate's (the lower bound of each exact
distance), among the pairs within reach of D that the rule keeps.
Prints the table; exit status 0, or 2 when an audit fails to run.
"""

import argparse
import json
import subprocess
import sys

SELF = ("self-",)
OBJECT = ("obstacle-", "cloth-vertex-obstacle", "cloth-edge-obstacle-edge")


def kept(per_frame, prefixes):
    """Frames with no violation of the kinds starting with one of `prefixes`."""
    return sum(1 for f in per_frame
               if not any(n for k, n in f.items() if k != "frame" and k.startswith(prefixes)))


def audit(fdhcert, folder, d):
    r = subprocess.run([fdhcert, "audit", folder, "--json", "--quiet", "--min-distance", repr(d)],
                       capture_output=True, text=True)
    if r.returncode not in (0, 1):
        sys.exit(f"distance_table: {folder} at {d}: fdhcert audit exited {r.returncode}: "
                 f"{r.stderr.strip()}")
    return json.loads(r.stdout)


def row(folder, d, c):
    frames, per_frame = c["frames"], c["per_frame"]
    t = c["totals"]
    self_n = sum(n for k, n in t.items() if k.startswith(SELF))
    obj_n = sum(n for k, n in t.items() if k.startswith(OBJECT))
    has_obstacle = c["obstacles"]["triangles"] > 0
    near = c["proximity"]["nearest"]
    ex = c["proximity"]["excluded"]
    return (f"| {folder} | {d:g} | {kept(per_frame, SELF)} of {frames} ({self_n} violations) | "
            + f"{nearest(near['self'])} | "
            + (f"{kept(per_frame, OBJECT)} of {frames} ({obj_n} violations) | "
               f"{nearest(near['obstacle'])}" if has_obstacle else "(no obstacle) | ")
            + f" | {ex['rings']} + {ex['first_frame']} |")


def nearest(n):
    """The nearest pair's distance (its lower bound, exact to the digits shown) and frame."""
    if n is None:
        return "none within reach of D"
    return f"{n['distance_lo']:.4g} m (frame {n['frame']})"


def main():
    p = argparse.ArgumentParser(prog="distance_table.py", description=__doc__.splitlines()[0])
    p.add_argument("fdhcert")
    p.add_argument("folders", nargs="+")
    p.add_argument("--distance", type=float, action="append")
    a = p.parse_args()
    print("| frames | D (m) | frames keeping the self distance | nearest cloth pair | frames "
          "keeping the object distance | nearest cloth-obstacle pair | tests left out (rings + "
          "first frame) |")
    print("|---|---|---|---|---|---|---|")
    for folder in a.folders:
        for d in a.distance or (0.015, 0.0075):
            print(row(folder, d, audit(a.fdhcert, folder, d)), flush=True)


if __name__ == "__main__":
    main()
