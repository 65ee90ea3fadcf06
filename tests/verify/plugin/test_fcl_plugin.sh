#!/bin/bash
# The FCL example plug-in (verify/plugin/example/fcl_plugin.cpp) run as a user runs it
# (docs/plugins.md, "Wrapping a real library"): certified with quick options, then fuzzed on a
# few families. Its false alarms and its misses must both be stored as shrunk cases, by
# direction and family, with the hourglass family's inversion visible (both fp- and fn- cases
# under fcl-ccd/hourglass/), every stored case's truth (the twin's) opposite to its direction's
# answer, fcl-ccd failing on every one on replay and the exact twin giving every stored truth;
# the committed corpus/plugins/fcl-ccd/ the same.
# Usage: test_fcl_plugin.sh FDHCERT PLUGIN SOURCE_DIR
set -euo pipefail
fdhcert=$1 plugin=$2 src=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-fcl-plugin.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
  echo "test_fcl_plugin: $*" >&2
  exit 1
}

# certify: promise none, so the run is certified and fcl-ccd is measured (its metamorphic row).
# The corpus is the hand-made queries and FCL's own cases, without the scenes (the bulk of the
# time, and the same for every plug-in).
mkdir -p "$work/corpus"
cp -r "$src/corpus/queries" "$src/corpus/plugins" "$work/corpus/"
"$fdhcert" certify --quick --per-family 40 --soups 5 --peer-cases 40 --quiet \
  --corpus "$work/corpus" --plugin "$plugin" --out "$work/cert" >"$work/certify.txt"
python3 - "$work/cert/certificate.json" <<'EOF'
import json, sys
c = json.load(open(sys.argv[1]))
rows = [m for m in c["metamorphic"] if m["method"] == "fcl-ccd"]
assert c["certified"], "certify with the FCL plug-in is not certified"
assert rows and rows[0]["promise"] == "none" and rows[0]["checked"] > 0, rows
assert not [p for p in c["promises"] if p["method"] == "fcl-ccd"], "fcl-ccd promises nothing"
EOF

# fuzz: each family's disagreements shrunk by direction; the summary counts both directions.
for family in hourglass parallel-edges angled; do
  "$fdhcert" fuzz --plugin "$plugin" --method fcl-ccd --family "$family" --count 150 \
    --threads 2 --out "$work/fuzz" --quiet >"$work/fuzz-$family.txt"
  grep -q '^fcl-ccd by direction: [0-9]* FP (false alarms), [0-9]* FN (misses)$' \
    "$work/fuzz-$family.txt" || fail "no count by direction for $family"
done
grep -Eq '^fcl-ccd by direction: [1-9][0-9]* FP .*, [1-9][0-9]* FN' "$work/fuzz-hourglass.txt" ||
  fail "hourglass: expected both false alarms and misses: $(cat "$work/fuzz-hourglass.txt")"

# Stored cases (OUT or the committed corpus): hourglass has both directions, each file's
# direction is in its name, id and comment, and replay finds fcl-ccd failing on every one.
check_stored() {
  local dir=$1
  ls "$dir"/fcl-ccd/hourglass/fp-*.vf >/dev/null 2>&1 || fail "$dir: no false alarm of hourglass"
  ls "$dir"/fcl-ccd/hourglass/fn-*.vf >/dev/null 2>&1 || fail "$dir: no miss of hourglass"
  local f d n=0
  for f in "$dir"/fcl-ccd/*/f[pn]-*.vf; do
    d=$(basename "$f" | cut -c1-2)
    grep -Eq "^(vf|ee) fcl-ccd/[a-z-]+/$d " "$f" || fail "$f: the id does not name $d"
    # The stored truth is the twin's: exact says no to a false alarm, hit to a miss.
    case $d in
      fp) grep -q ': a false alarm (FP)\.$' "$f" && grep -q ' 0$' "$f" || fail "$f: not an FP" ;;
      fn) grep -q ': a miss (FN)\.$' "$f" && grep -q ' 1$' "$f" || fail "$f: not an FN" ;;
    esac
    n=$((n + 1))
  done
  "$fdhcert" replay "$dir" --plugin "$plugin" --methods exact,fcl-ccd --json >"$work/replay.json"
  python3 - "$work/replay.json" "$n" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
n = int(sys.argv[2])
assert r["cases"] == n, (r["cases"], n)
assert r["exact_mismatches"] == [] and r["methods"]["exact"]["failing"] == 0, r
assert r["methods"]["fcl-ccd"]["failing"] == n, r["methods"]["fcl-ccd"]
EOF
}
check_stored "$work/fuzz"
check_stored "$src/corpus/plugins"
echo "test_fcl_plugin: certified; fuzz and the committed corpus store FCL's false alarms and misses apart"
