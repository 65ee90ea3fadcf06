#!/usr/bin/env bash
# The cluster recipe of docs/cluster.md, run for real: munge, slurmctld and slurmd on localhost
# from a generated configuration, docs/cluster/fuzz-shard.sbatch as a 4-task array job, then
# docs/cluster/merge.sbatch after it; the merged corpus must equal one uninterrupted run's,
# file for file. Skips (exit 77) unless run as root with Debian's slurm-wlm and munge.
#   test_slurm.sh FDHCERT REPO
set -euo pipefail
fdhcert=$(realpath "$1")
repo=$(realpath "$2")
# shellcheck source=tests/cluster/slurm_localhost.sh
source "$repo/tests/cluster/slurm_localhost.sh"
# The doc shows the scripts this test submits, word for word (checked even where it skips).
doc_shows_scripts fuzz-shard merge
start_cluster
shards=4 count=600
opts=(METHOD=linear-system FAMILY=sliver SEED=2026 COUNT=$count)
env_list=$(IFS=,; echo "ALL,OUT=$work/run,FDHCERT=$fdhcert,${opts[*]}")
mkdir -p "$work/run"
cd "$work/run"
array=$(sbatch --parsable --array=1-$shards --export="$env_list" -o "$work/log/fuzz-%a.out" \
  "$repo/docs/cluster/fuzz-shard.sbatch")
sbatch --parsable --dependency=afterok:"$array" --export="$env_list" -o "$work/log/merge.out" \
  "$repo/docs/cluster/merge.sbatch" >/dev/null
wait_for_jobs
[ -s "$work/run/replay.json" ] || fail "the merge job did not finish"

# One uninterrupted run of the same options, on this machine, outside Slurm.
"$fdhcert" fuzz --method linear-system --family sliver --seed 2026 --count $count \
  --out "$work/single" --json >"$work/single.json"
diff -r "$work/single/linear-system" "$work/run/merged/linear-system" ||
  fail "the merged shards differ from the uninterrupted run"
cases=$(find "$work/run/merged" -name '*.vf' | wc -l)
[ "$cases" -gt 0 ] || fail "no case found: the comparison proves nothing"
python3 - "$work" "$shards" <<'PY' || fail "the shards' counts do not add up to the run's"
import json, sys
work, shards = sys.argv[1], int(sys.argv[2])
single = json.load(open(f"{work}/single.json"))
parts = [json.load(open(f"{work}/run/shard-{i}.json")) for i in range(1, shards + 1)]
assert sum(p["cases"] for p in parts) == single["cases"], "cases"
assert sum(p["disagreements"] for p in parts) == single["disagreements"], "disagreements"
replay = json.load(open(f"{work}/run/replay.json"))
assert replay["exact_mismatches"] == [], replay["exact_mismatches"]
PY
echo "slurm: $shards shards of $count cases merged into $cases case files, the same as one run"
