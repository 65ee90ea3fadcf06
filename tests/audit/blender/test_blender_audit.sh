#!/usr/bin/env bash
# A real simulator's output through `fdhcert audit`: Blender bakes two small cloth scenes
# (bake_cloth.py: a 20x20 cloth dropped on a sphere, and one crumpled with self-collision, 30
# frames each) and the audit must decide every frame and step of each: exit 0 (clean) or 1 (a
# violation), never 2 or a crash, with a certificate that has its fields. It does not demand
# clean: Blender's cloth may pass through (docs/audit.md, "Blender's cloth"). Each is audited
# again at Blender's distance, 0.015 m (--min-distance): the same intersections, and the
# certificate's proximity block.
# Skips (exit 77) where `blender` is not installed (./run installs it when run as root).
#   test_blender_audit.sh FDHCERT REPO
set -euo pipefail
. "$(dirname "$0")/blender_test.sh" "$1" "$2" fdh-blender
grid=20
frames=30

for scene in drop crumple; do
  frames_dir=$work/$scene-frames
  out=$work/$scene-audit
  blender -b --factory-startup -P "$repo/tests/audit/blender/bake_cloth.py" -- \
    --scene "$scene" --grid "$grid" --frames "$frames" --out "$frames_dir" \
    >"$work/$scene-bake.log" 2>&1 || { tail -n 30 "$work/$scene-bake.log"; fail "$scene: the bake failed"; }
  grep '^bake_cloth:' "$work/$scene-bake.log"
  written=$(find "$frames_dir" -name 'frame_*.obj' | wc -l)
  [ "$written" -eq "$frames" ] || fail "$scene: $written frame files, expected $frames"

  status=0
  "$fdhcert" audit "$frames_dir" --json --out "$out" >"$work/$scene-audit.json" 2>"$work/$scene-audit.err" ||
    status=$?
  cat "$work/$scene-audit.err"
  [ "$status" -eq 0 ] || [ "$status" -eq 1 ] || fail "$scene: fdhcert audit exited $status (0 or 1 expected)"
  python3 "$repo/tests/audit/check_audit_json.py" "$work/$scene-audit.json" "$out" \
    --frames "$frames" --status "$status" --cloth-vertices $((grid * grid)) ||
    fail "$scene: the audit's certificate is not as expected"

  # The proximity path at Blender's own distance (0.015 m): decided to the end, the intersection
  # counts those of the audit without D, the proximity block present (issue 31).
  status=0
  "$fdhcert" audit "$frames_dir" --json --min-distance 0.015 >"$work/$scene-near.json" \
    2>"$work/$scene-near.err" || status=$?
  [ "$status" -eq 0 ] || [ "$status" -eq 1 ] ||
    { cat "$work/$scene-near.err"; fail "$scene: audit --min-distance exited $status"; }
  python3 - "$work/$scene-audit.json" "$work/$scene-near.json" "$frames" <<'PY' ||
import json, sys
plain, near = (json.load(open(p)) for p in sys.argv[1:3])
frames = int(sys.argv[3])
assert near["frames"] == frames and len(near["per_frame"]) == frames, "not every frame decided"
for kind, n in plain["totals"].items():
    assert near["totals"][kind] == n, f"{kind}: {near['totals'][kind]} at D, {n} without"
p = near["proximity"]
assert p["min_distance"] == 0.015 and p["near_rule"] == {"rings": 2, "first_frame": True}
assert sum(near["totals"].values()) == near["violations"]
assert near["clean"] == (near["violations"] == 0)
print(near["summary"])
PY
    fail "$scene: the audit at --min-distance 0.015 is not as expected"
done
echo "PASS"
