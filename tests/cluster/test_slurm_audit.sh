#!/usr/bin/env bash
# The audit's cluster recipe of docs/cluster.md, run for real on a localhost Slurm
# (slurm_localhost.sh): a sequence with a planted crossing, docs/cluster/audit-part.sbatch as a
# PARTS-task array job, then docs/cluster/audit-merge.sbatch after it; the merged certificate must
# be the whole run's (the same JSON but for the costs, the same picture and case files). Skips
# (exit 77) unless run as root with Debian's slurm-wlm and munge.
#   test_slurm_audit.sh FDHCERT REPO [FRAMES_DIR PARTS]
# With FRAMES_DIR (frames already written, e.g. 1000x1000 ones) it audits those instead, and
# prints both certificates' summaries and costs.
set -euo pipefail
fdhcert=$(realpath "$1")
repo=$(realpath "$2")
frames=${3:+$(realpath "$3")}
parts=${4:-2}
# shellcheck source=tests/cluster/slurm_localhost.sh
source "$repo/tests/cluster/slurm_localhost.sh"
doc_shows_scripts audit-part audit-merge
start_cluster

if [ -z "$frames" ]; then
  # The sphere's first 24 frames, cloth vertex 312 pushed into the sphere at frame 12 (a frame
  # that parts 1/2 and 2/2 share), as docs/audit.md plants it.
  frames=$work/frames
  "$fdhcert" simulate "$repo/corpus/scenes/sphere.scene" --frames 24 --obj "$frames" --no-check \
    >/dev/null
  sed -i '314s/.*/v 0.013 0.5 0.021/' "$frames/frame_00012.obj"
fi
env_list="ALL,FRAMES=$frames,OUT=$work/run,FDHCERT=$fdhcert"
mkdir -p "$work/run"
cd "$work/run"
array=$(sbatch --parsable --array=1-"$parts" --export="$env_list" -o "$work/log/part-%a.out" \
  "$repo/docs/cluster/audit-part.sbatch")
sbatch --parsable --dependency=afterok:"$array" --export="$env_list" -o "$work/log/merge.out" \
  "$repo/docs/cluster/audit-merge.sbatch" >/dev/null
wait_for_jobs
[ -s "$work/run/audit/audit.json" ] || fail "the merge job did not finish"

# The whole run, on this machine, outside Slurm.
status=0
"$fdhcert" audit "$frames" --quiet --out "$work/whole" >/dev/null || status=$?
[ "$status" -le 1 ] || fail "the whole run failed (exit $status)"
diff -r -x audit.json -x audit.md "$work/whole" "$work/run/audit" ||
  fail "the merged parts' picture or case files differ from the whole run's"
python3 - "$work" "${3:-}" <<'PY' || fail "the merged certificate differs from the whole run's"
import json, sys
work, given = sys.argv[1], sys.argv[2]
whole = json.load(open(f"{work}/whole/audit.json"))
merged = json.load(open(f"{work}/run/audit/audit.json"))
costs = whole.pop("cost"), merged.pop("cost")
assert whole == merged, [k for k in whole if whole[k] != merged.get(k)]
if not given:
    assert whole["violations"] > 0 and whole["first_violation"]["frame"] == 11, whole["summary"]
print("whole: ", whole["summary"], json.dumps(costs[0]))
print("merged:", merged["summary"], json.dumps(costs[1]))
PY
echo "slurm: $parts parts of the audit merged into the whole run's certificate"
