#!/usr/bin/env bash
# The main job's summary (verify/report/main_job.sh, `./run verify`) on a small run: the quick
# report, one short scene, Table 1 of 3 frames, all into a folder of the test's own. It must
# succeed and print at most 30 lines: certified with the counts, a line per scene, Table 1's
# headline row and where the report is; not the certificate's tables.
# usage: test_main_job.sh FDHCERT SOURCE_DIR
set -euo pipefail
fdhcert=$1
cd "$2"
work=$(mktemp -d "${TMPDIR:-/tmp}/fdh_main_job.XXXXXX")
if [ "${FDH_KEEP_TEST_FILES:-}" = 1 ]; then
  echo "kept: $work"
else
  trap 'rm -rf "$work"' EXIT
fi
mkdir "$work/scenes-in"
grep -v '^frames' corpus/scenes/table.scene >"$work/scenes-in/table.scene"
echo "frames 20" >>"$work/scenes-in/table.scene"

FDH_VERIFY_SMALL=1 FDH_VERIFY_OUT="$work/out" FDH_VERIFY_SCENES="$work/scenes-in" \
  verify/report/main_job.sh "$fdhcert" >"$work/summary" 2>"$work/errors" || {
  echo "FAIL: the main job ended with status $?"; cat "$work/summary" "$work/errors"; exit 1; }
cat "$work/summary"
fail() { echo "FAIL: $*"; exit 1; }
lines=$(wc -l <"$work/summary")
[ "$lines" -le 30 ] || fail "the summary has $lines lines, more than 30"
grep -Eq '^certified: [0-9]+ checks, 0 violations \([0-9]+ corpus, [0-9]+ fuzzed' "$work/summary" ||
  fail "no 'certified: N checks, 0 violations (...)' line"
grep -Eq '^promises \(violations/queries\): robust point-triangle 0/[0-9]+' "$work/summary" ||
  fail "no line of the promises"
grep -Eq '^bounding volumes .*fdhcert 0/[0-9]+' "$work/summary" || fail "no bounding-volume line"
grep -Eq '^table +[0-9]+x[0-9]+ +20 frames .* crossing 0 self-crossing' "$work/summary" ||
  fail "no line for the scene"
grep -Eq '^Table 1 at [0-9]+x[0-9]+, k = 18' "$work/summary" || fail "no Table 1 headline"
grep -Eq '^  linear-system [0-9.]+ \(FP [0-9]+, FN [0-9]+\), paper-intended .*, robust ' \
  "$work/summary" || fail "no Table 1 row"
grep -Fq "Full report: $work/out/report/index.html" "$work/summary" || fail "no line naming the report"
! grep -q '^|' "$work/summary" || fail "the certificate's tables were printed"
for f in report/index.html report/report.md report/certificate.json report/certificate.md \
  report/speed_accuracy.svg report/table1.md scenes/table.png scenes/table.json; do
  [ -s "$work/out/$f" ] || fail "no $f"
done
echo "ok: $lines lines"
