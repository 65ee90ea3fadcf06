"""One shipped scene's run: `fdhcert simulate --json`'s own exact audit (inside, crossing,
self_crossing, summed over the frames it checks: every audit_every-th and the last) against
`fdhcert audit --json` of the same run's --obj frames (every frame and every step between them).
Both must find nothing. Prints one line for the scene, and the audit's first violations if it
found any; exit status 1 unless both are clean.
  compare_with_simulate.py SCENE SIMULATE.json AUDIT.json
"""

import json
import sys


def violation_text(v):
    if v["step"]:
        toi = v["toi"]
        where = f"step {v['frame']} -> {v['to_frame']}, t in [{toi['t_lo']!r}, {toi['t_hi']!r}]"
        pair = f"vertices {v['vertices']}" + (f" (triangle {v['triangle']})"
                                              if v.get("triangle") is not None else "")
    else:
        where = f"frame {v['frame']}"
        pair = f"triangles {v['triangles']} (vertices {v['triangle_vertices']})"
    places = f" at {', '.join(v['places'])}" if v.get("places") else ""
    return f"{v['kind']} at {where}: {pair}{places}"


def main():
    scene, sim_path, audit_path = sys.argv[1:4]
    with open(sim_path) as f:
        sim = json.load(f)
    with open(audit_path) as f:
        audit = json.load(f)
    internal = {k: sim[k] for k in ("inside", "crossing", "self_crossing")}
    print(f"{scene}: {sim['frames']} frames; simulate's audit: inside {internal['inside']}, "
          f"crossing {internal['crossing']}, self_crossing {internal['self_crossing']}; "
          f"fdhcert audit: {audit['summary']}")
    internal_clean = all(v in (0, None) for v in internal.values())
    for v in audit["kept"]:
        print(f"  {violation_text(v)}")
    if audit["clean"] and internal_clean:
        return 0
    if audit["clean"] != internal_clean:
        print(f"  MISMATCH: simulate's own audit says {'clean' if internal_clean else 'not clean'}, "
              f"fdhcert audit {'clean' if audit['clean'] else 'not clean'}")
    return 1


if __name__ == "__main__":
    sys.exit(main())
