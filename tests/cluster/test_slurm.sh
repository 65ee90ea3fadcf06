#!/usr/bin/env bash
# The cluster recipe of docs/cluster.md, run for real: munge, slurmctld and slurmd on localhost
# from a generated configuration, docs/cluster/fuzz-shard.sbatch as a 4-task array job, then
# docs/cluster/merge.sbatch after it; the merged corpus must equal one uninterrupted run's,
# file for file. Skips (exit 77) unless run as root with Debian's slurm-wlm and munge.
#   test_slurm.sh FDHCERT REPO
set -euo pipefail
fdhcert=$(realpath "$1")
repo=$(realpath "$2")
skip() { echo "SKIP: $*"; exit 77; }
# The doc shows the scripts this test submits, word for word (checked even where it skips).
for script in fuzz-shard merge; do
  python3 -c 'import sys; sys.exit(open(sys.argv[2]).read() not in open(sys.argv[1]).read())' \
    "$repo/docs/cluster.md" "$repo/docs/cluster/$script.sbatch" ||
    { echo "FAIL: docs/cluster.md does not show docs/cluster/$script.sbatch as it is"; exit 1; }
done
[ "$(id -u)" = 0 ] || skip "needs root (it starts munged, slurmctld and slurmd)"
for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
  command -v "$tool" >/dev/null || skip "no $tool: install slurm-wlm and munge (./run does, as root)"
done

work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-slurm.XXXXXX")
export SLURM_CONF=$work/slurm.conf
cleanup() {
  scontrol shutdown >/dev/null 2>&1 || true
  for pidfile in "$work"/slurmd.pid "$work"/slurmctld.pid "$work"/munge/pid; do
    [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
  done
  sleep 1
  if [ "${FDH_KEEP_TEST_FILES:-}" = 1 ]; then echo "FDH_KEEP_TEST_FILES: kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT
fail() {
  echo "FAIL: $*"
  for log in "$work"/log/*; do echo "--- $log"; tail -n 20 "$log"; done
  exit 1
}

start_daemons() {
  mkdir -p "$work"/{munge,state,spool,log,run}
  chmod 711 "$work/munge"  # munged wants its socket's folder searchable by all
  dd if=/dev/urandom of="$work/munge/key" bs=1024 count=1 status=none
  chmod 400 "$work/munge/key"
  # Ports of this run's own, so that a second run or a real cluster on the host is not disturbed.
  local port=$((20000 + $$ % 20000))
  sed -e "s|@WORK@|$work|g" -e "s|@PORT@|$port|g" -e "s|@PORT1@|$((port + 1))|g" \
    "$repo/tests/cluster/slurm.conf.in" >"$SLURM_CONF"
  munged --force -S "$work/munge/sock" --key-file "$work/munge/key" --pid-file "$work/munge/pid" \
    --log-file "$work/log/munged.log" --seed-file "$work/munge/seed"
  slurmctld -f "$SLURM_CONF"
  slurmd -f "$SLURM_CONF" -N localhost
  for _ in $(seq 60); do
    [ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ] && return 0
    sleep 0.5
  done
  fail "the node never came up idle"
}

# Waits for every job of this test to leave the queue; a job left waiting on a failed one fails
# the test at once.
wait_for_jobs() {
  for _ in $(seq 600); do
    [ -z "$(squeue -h -o %i)" ] && return 0
    squeue -h -o %r | grep -q DependencyNeverSatisfied && fail "a shard job failed"
    sleep 0.5
  done
  fail "jobs still queued after 300 s: $(squeue)"
}

start_daemons
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
