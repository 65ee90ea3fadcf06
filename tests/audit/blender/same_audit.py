"""Two `fdhcert audit --json` certificates of the same animation read from two formats must be
the same certificate: everything but the costs, the summary's and places' file names and, with
--renumbered (PLY: Blender's exporter numbers the vertices in the order the faces first use
them), the vertex numbers and the candidate counts that follow from them.

  python3 same_audit.py WANT.json HAVE.json NAME [--renumbered]
Exit status 0 when the same, 1 (saying what differs) otherwise."""

import json
import sys


def comparable(cert, renumbered):
    c = {k: v for k, v in cert.items() if k not in ("cost", "summary", "kept")}
    first = c.get("first_violation")
    if first:
        first = {k: v for k, v in first.items() if k not in ("places", "case_file")}
        if renumbered:
            first.pop("vertices", None)
            first.pop("triangle_vertices", None)
        c["first_violation"] = first
    if renumbered:
        c.pop("candidates", None)
    return c


def main(argv):
    want_path, have_path, name = argv[1:4]
    renumbered = "--renumbered" in argv[4:]
    with open(want_path) as f:
        want = comparable(json.load(f), renumbered)
    with open(have_path) as f:
        have = comparable(json.load(f), renumbered)
    if want == have:
        first = (want.get("first_violation") or {}).get("kind", "none")
        verdict = "clean" if want["clean"] else f"{want['violations']} violations"
        print(f"same_audit: {name}: the same certificate ({verdict}, first: {first})")
        return 0
    for key in sorted(set(want) | set(have)):
        if want.get(key) != have.get(key):
            print(f"same_audit: {name}: {key} differs:\n  want {json.dumps(want.get(key))[:400]}"
                  f"\n  have {json.dumps(have.get(key))[:400]}")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
