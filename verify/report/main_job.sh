#!/usr/bin/env bash
# The main job, as `./run verify` runs it after the build: `fdhcert report` (the certificate,
# the measurements and their charts, report.md and index.html) into docs/report, every shipped
# scene into docs/scenes, and the paper's Table 1 into docs/report. Standard output gets a
# summary of about 20 lines (each command's --summary, or its line per scene); the full
# certificate is in its files. Exit status: the first command's that failed, else 0.
#
# usage: verify/report/main_job.sh FDHCERT   (from the repository's top folder)
# For a small run (tests/verify/report/test_main_job.sh):
#   FDH_VERIFY_OUT=DIR      report/ and scenes/ go under DIR (default: docs)
#   FDH_VERIFY_SCENES=DIR   the scenes to run (default: corpus/scenes)
#   FDH_VERIFY_SMALL=1      report --quick without the CCD sample, no movies, Table 1 of 3 frames
set -euo pipefail
fdhcert=$1
out=${FDH_VERIFY_OUT:-docs}
scenes=${FDH_VERIFY_SCENES:-corpus/scenes}
report_args=() scene_args=(--movies) table_args=() extra=()
if [ "${FDH_VERIFY_SMALL:-}" = 1 ]; then
  report_args=(--quick) scene_args=() table_args=(--frames 3)
elif [ -d ../shared/ccd-sample ]; then  # the CCD benchmark sample, when it is beside the clone
  mapfile -t extra < <(find ../shared/ccd-sample -name '*.csv' | sort)
fi
status=0
echo "== certificate and measurements: fdhcert report"
"$fdhcert" report --summary --out "$out/report" "${report_args[@]}" "${extra[@]}" || status=$?
echo "== cloth scenes: fdhcert scenes"
"$fdhcert" scenes --scenes "$scenes" --out "$out/scenes" "${scene_args[@]}" || status=$?
echo "== the paper's Table 1: fdhcert table1"
"$fdhcert" table1 --summary --out "$out/report" "${table_args[@]}" || status=$?
echo "Full report: $out/report/index.html (to browse) and report.md; certificate:" \
  "$out/report/certificate.md; charts: $out/report/*.svg and *.png; Table 1: $out/report/table1.md"
exit $status
