#!/usr/bin/env bash
# The Debian package (ctest package_deb; docs/package.md): cpack -G DEB from this build folder,
# then the package unpacked into a temporary root (dpkg -x) and tried there: the program
# (--version, a classify, its manual page), `import fdhcert` from the root's dist-packages, the
# corpus, and examples/consumer built against the root (test_consumer.cmake); lintian, when
# installed, must report no error. Skipped (77) without dpkg-deb or dpkg-shlibdeps.
#   test_deb.sh SOURCE BUILD VERSION GENERATOR
set -euo pipefail
src=$1 build=$2 version=$3 generator=$4
for tool in dpkg-deb dpkg-shlibdeps; do
  command -v $tool >/dev/null || { echo "skipped: no $tool (dpkg-dev; ./run installs it as root)"; exit 77; }
done
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT

start=$SECONDS
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack"; }
deb=$work/out/fdhcert_${version}_$(dpkg --print-architecture)
deb=$deb.deb
[ -f "$deb" ] || { ls "$work/out"; fail "no $(basename "$deb")"; }
echo "cpack: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB, $((SECONDS - start)) s"
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
for needed in libc6 libstdc++6 python3 python3-numpy; do
  [[ ", $depends" == *", $needed "* || ", $depends," == *", $needed,"* ]] ||
    fail "Depends names no $needed"
done

root=$work/root
dpkg -x "$deb" "$root"
fdhcert=$root/usr/bin/fdhcert
[ "$("$fdhcert" --version)" = "fdhcert $version" ] || fail "fdhcert --version: $("$fdhcert" --version)"
"$fdhcert" classify "$src/tests/data/moving.vf" | grep -q '^ *robust ' || fail "classify"
[ -f "$root/usr/share/fdhcert/corpus/scenes/table.scene" ] || fail "no corpus in the package"
man -l "$root/usr/share/man/man1/fdhcert.1.gz" 2>&1 | grep -q "COMMAND: CERTIFY" ||
  fail "man -l of the packaged fdhcert(1)"
[ -f "$root/usr/share/doc/fdhcert/copyright" ] || fail "no copyright file"
PYTHONPATH=$root/usr/lib/python3/dist-packages PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 - "$root" <<'PY' ||
import sys
import numpy as np
import fdhcert
assert fdhcert.__file__.startswith(sys.argv[1]), fdhcert.__file__
tri = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
falling = np.array([[[0.25, 0.25, 1], *tri, [0.25, 0.25, -1], *tri]])
assert fdhcert.vertex_face_ccd(falling).tolist() == [True]
print("import fdhcert:", fdhcert.__file__)
PY
  fail "import fdhcert from the package"

cmake -DBUILD="$build" -DSRC="$src" -DWORK="$work/consumer" -DGENERATOR="$generator" \
  -DPREFIX="$root/usr" -P "$src/tests/package/test_consumer.cmake" >"$work/consumer.log" 2>&1 ||
  { cat "$work/consumer.log"; fail "the CMake consumer against the package"; }
echo "consumer against the package: ok"

if command -v lintian >/dev/null; then
  # lintian leaves its ELF cache (mldbm-elf-*) in $TMPDIR: ours, removed with the rest.
  TMPDIR=$work lintian --fail-on error --tag-display-limit 0 "$deb" || fail "lintian reports errors"
  echo "lintian: no error"
else
  echo "lintian: not installed (./run installs it as root), not run"
fi
