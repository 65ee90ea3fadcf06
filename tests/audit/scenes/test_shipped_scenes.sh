#!/usr/bin/env bash
# fdhcert's own simulator through `fdhcert audit`: every shipped scene (corpus/scenes/*.scene) is
# run by `simulate --obj --audit-self --json`, and `fdhcert audit` of its frames must be clean
# (exit 0) and decide every frame and step; simulate's own frame audit (the same engine, its
# checked frames alone) must be clean too.
# A scene runs min(its frames, FRAMES, PARTICLE_FRAMES / its particles) frames, so that the
# 200x200 fold stays within the test's time.
#   test_shipped_scenes.sh FDHCERT REPO FRAMES PARTICLE_FRAMES
set -euo pipefail
fdhcert=$(realpath "$1")
repo=$(realpath "$2")
max_frames=$3
particle_frames=$4

work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-shipped-audit.XXXXXX")
cleanup() {
  if [ "${FDH_KEEP_TEST_FILES:-}" = 1 ]; then echo "FDH_KEEP_TEST_FILES: kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT

# The value of a scene file's KEY line (docs/formats.md, "scene"), or DEFAULT.
scene_value() {
  awk -v key="$2" -v def="$3" '$1 == key { v = $2 } END { print (v == "" ? def : v) }' "$1"
}

failed=()
for scene in "$repo"/corpus/scenes/*.scene; do
  name=$(basename "$scene" .scene)
  grid=$(scene_value "$scene" grid 0)
  frames=$(scene_value "$scene" frames 0)
  budget=$((particle_frames / (grid * grid)))
  ((frames > max_frames)) && frames=$max_frames
  ((frames > budget)) && frames=$budget
  ((frames >= 2)) || frames=2
  dir=$work/$name
  "$fdhcert" simulate "$scene" --frames "$frames" --obj "$dir/frames" --audit-self --json --quiet \
    >"$dir.simulate.json" || { failed+=("$name (simulate failed)"); continue; }
  status=0
  "$fdhcert" audit "$dir/frames" --json --out "$dir/audit" >"$dir.audit.json" || status=$?
  if [ "$status" -ne 0 ] && [ "$status" -ne 1 ]; then
    failed+=("$name (fdhcert audit exited $status)")
    continue
  fi
  python3 "$repo/tests/audit/check_audit_json.py" "$dir.audit.json" "$dir/audit" \
    --frames $((frames + 1)) --status "$status" --cloth-vertices $((grid * grid)) >"$dir.check.txt" ||
    { cat "$dir.check.txt"; failed+=("$name (the certificate)"); }
  # One line per scene; exit 1 unless simulate's frame audit found nothing.
  python3 - "$name" "$dir.simulate.json" "$dir.audit.json" <<'PY' || failed+=("$name (simulate's frame audit is not clean)")
import json, sys
name, sim, audit = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
print(f"{name}: {sim['frames']} frames; simulate's frame audit: crossing {sim['crossing']}, "
      f"self_crossing {sim['self_crossing']}; fdhcert audit: {audit['summary']}")
sys.exit(sim["crossing"] != 0 or sim["self_crossing"] != 0)
PY
  [ "$status" -eq 0 ] || failed+=("$name (fdhcert audit found violations)")
  rm -rf "$dir"  # the fold's frames are large: one scene's on disk at a time
done
if [ ${#failed[@]} -gt 0 ]; then
  printf 'FAIL: %s\n' "${failed[@]}"
  exit 1
fi
echo "PASS"
