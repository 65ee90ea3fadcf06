#!/usr/bin/env bash
# The same Blender animation in every format `fdhcert audit` reads, exported by Blender's own
# bundled add-ons (bake_cloth.py --formats: io_mesh_ply's binary PLY per frame, io_export_pc2's
# PC2 and io_shape_mdd's MDD with the cloth's OBJ mesh, beside our OBJ frames as a bake folder of
# numbered cloth frames and an un-numbered obstacle). Every audit must equal the OBJ frames'
# (same_audit.py). Skips (exit 77) where `blender` or one of its add-ons is not installed.
#   test_blender_formats.sh FDHCERT REPO
set -euo pipefail
. "$(dirname "$0")/blender_test.sh" "$1" "$2" fdh-blender-formats
grid=20
frames=30

blender -b --factory-startup -P "$repo/tests/audit/blender/bake_cloth.py" -- \
  --scene drop --grid "$grid" --frames "$frames" --formats --out "$work/bake" \
  >"$work/bake.log" 2>&1 || { tail -n 30 "$work/bake.log"; fail "the bake or an export failed"; }
grep '^bake_cloth:' "$work/bake.log"
f=$work/bake/formats

# audit NAME ARGS...: the certificate in $work/NAME.json; exit 0 or 1 only.
audit() {
  local name=$1 status=0
  shift
  "$fdhcert" audit "$@" --json >"$work/$name.json" 2>"$work/$name.err" || status=$?
  sed "s/^/$name: /" "$work/$name.err"
  [ "$status" -eq 0 ] || [ "$status" -eq 1 ] || fail "$name: fdhcert audit exited $status"
}

audit objs "$f/objs"
audit frames "$work/bake"
audit ply "$f/ply"
audit pc2 "$f/cloth.obj" "$f/cloth.pc2" --obstacle "$f/objs/obstacle_sphere.obj"
audit mdd "$f/cloth.obj" "$f/cloth.mdd" --obstacle "$f/objs/obstacle_sphere.obj"
grep -q "the frames are cloth_\*.obj ($frames files); fixed obstacles: obstacle_sphere.obj" \
  "$work/objs.err" || fail "the bake folder's note is missing"

same="python3 $repo/tests/audit/blender/same_audit.py"
$same "$work/objs.json" "$work/frames.json" "frame files with both objects" || fail "frames"
$same "$work/objs.json" "$work/pc2.json" "PC2 (io_export_pc2)" || fail "PC2"
$same "$work/objs.json" "$work/mdd.json" "MDD (io_shape_mdd)" || fail "MDD"
$same "$work/objs.json" "$work/ply.json" "PLY (io_mesh_ply)" --renumbered || fail "PLY"
echo "PASS"
