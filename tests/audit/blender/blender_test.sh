# What the Blender tests share, sourced with their arguments FDHCERT REPO and a name for the
# work folder: the skip (exit 77) without blender, $fdhcert and $repo, $work (removed at exit
# unless FDH_KEEP_TEST_FILES=1), fail().
command -v blender >/dev/null || { echo "SKIP: no blender (./run installs it as root)"; exit 77; }
fdhcert=$(realpath "$1")
repo=$(realpath "$2")
work=$(mktemp -d "${TMPDIR:-/tmp}/$3.XXXXXX")
cleanup() {
  if [ "${FDH_KEEP_TEST_FILES:-}" = 1 ]; then echo "FDH_KEEP_TEST_FILES: kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
