#!/usr/bin/env bash
# `pip install .` as a user runs it (ctest python_pip; docs/python.md): a venv of its own with
# Debian's packages visible (--system-site-packages), pip install --no-build-isolation offline,
# then `import fdhcert` from the venv, its version and metadata, the stubs against the installed
# module, a part of the pytest suite against the installed module; then `pip uninstall -y
# fdhcert` and the venv must hold exactly what it held before the install.
# The build reuses this build folder (FDHCERT_CMAKE_BUILD_DIR, setup.py) to keep the test short;
# a plain `pip install .` builds from scratch.
#   test_pip.sh SOURCE BUILD VERSION FDHCERT_BIN
set -euo pipefail
src=$1 build=$2 version=$3 program=$4
py=/usr/bin/python3
for module in venv pip setuptools wheel pytest numpy; do
  if ! $py -c "import $module" 2>/dev/null; then
    echo "skipped: Debian's python3 has no $module (python3-venv python3-pip python3-setuptools python3-wheel)"
    exit 77
  fi
done
fail() { echo "FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-pip.XXXXXX")
trap 'rm -rf "$work"' EXIT
# Without pip of its own (ensurepip takes seconds): Debian's pip, seen through the system
# site-packages, installs into the venv it runs in.
$py -m venv --system-site-packages --without-pip "$work/venv"
vpy=$work/venv/bin/python
before=$(cd "$work/venv" && find . | sort)
export PIP_NO_INDEX=1 PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1
unset PYTHONPATH
cd "$work"  # never the source folder: `import fdhcert` must find the venv's
FDHCERT_CMAKE_BUILD_DIR=$build "$vpy" -m pip install --no-build-isolation -q "$src" ||
  fail "pip install"
site=$("$vpy" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')
"$vpy" - "$site" "$version" <<'PY' || fail "the installed module"
import importlib.metadata as metadata, sys
import fdhcert
site, version = sys.argv[1:]
assert fdhcert.__file__.startswith(site), f"fdhcert imported from {fdhcert.__file__}, not {site}"
assert metadata.version("fdhcert") == version, metadata.version("fdhcert")
meta = metadata.metadata("fdhcert")
assert meta["Summary"].startswith("Exact verification"), meta["Summary"]
assert meta["Requires-Dist"] == "numpy", meta["Requires-Dist"]
files = {str(f) for f in metadata.files("fdhcert")}
assert "fdhcert-stubs/__init__.pyi" in files and "fdhcert-stubs/py.typed" in files, files
print("installed", fdhcert.__file__, version)
PY
shown=$("$vpy" -m pip show fdhcert) || fail "pip show"
grep -qx "Version: $version" <<<"$shown" || fail "pip show: no Version: $version in $shown"
# The stubs as installed, and a part of the module's pytest suite, against the venv's module.
FDHCERT_STUBS=$site/fdhcert-stubs/__init__.pyi FDHCERT_BIN=$program FDH_SOURCE_DIR=$src \
  "$vpy" -m pytest -q -p no:cacheprovider "$src/tests/package/test_stubs.py" \
  "$src/python/tests/test_fdhcert.py" -k "stubs or registry or classify_of_files or kdop or contact_time or bad_input" ||
  fail "pytest against the installed module"
"$vpy" -m pip uninstall -y -q fdhcert || fail "pip uninstall"
after=$(cd "$work/venv" && find . | sort)
left=$(comm -13 <(echo "$before") <(echo "$after"))
[ -z "$left" ] || fail "pip uninstall left in the venv: $left"
if "$vpy" -c "import fdhcert" 2>/dev/null; then fail "fdhcert still imports after pip uninstall"; fi
echo "pip install, import, tests, uninstall: ok"
