# A one-node Slurm cluster on localhost for the cluster tests (sourced by test_slurm.sh and
# test_slurm_audit.sh; functions only, $repo set by the test): start_cluster skips (exit 77)
# unless run as root with Debian's slurm-wlm and munge, else makes a fresh folder $work that the
# EXIT trap removes, and starts munged, slurmctld and slurmd from tests/cluster/slurm.conf.in with
# ports and folders of this run's own.
skip() { echo "SKIP: $*"; exit 77; }
fail() {
  echo "FAIL: $*"
  for log in "${work:-/nonexistent}"/log/*; do [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }; done
  exit 1
}

start_cluster() {
  [ "$(id -u)" = 0 ] || skip "needs root (it starts munged, slurmctld and slurmd)"
  for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
    command -v "$tool" >/dev/null || skip "no $tool: install slurm-wlm and munge (./run does, as root)"
  done
  work=$(mktemp -d "${TMPDIR:-/tmp}/fdh-slurm.XXXXXX")
  export SLURM_CONF=$work/slurm.conf
  trap cleanup EXIT
  start_daemons
}

cleanup() {
  scontrol shutdown >/dev/null 2>&1 || true
  for pidfile in "$work"/slurmd.pid "$work"/slurmctld.pid "$work"/munge/pid; do
    [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
  done
  sleep 1
  if [ "${FDH_KEEP_TEST_FILES:-}" = 1 ]; then echo "FDH_KEEP_TEST_FILES: kept $work"; else rm -rf "$work"; fi
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
    squeue -h -o %r | grep -q DependencyNeverSatisfied && fail "a job the merge waits for failed"
    sleep 0.5
  done
  fail "jobs still queued after 300 s: $(squeue)"
}

# Fails unless docs/cluster.md shows docs/cluster/NAME.sbatch word for word, for each NAME.
doc_shows_scripts() {
  local script
  for script in "$@"; do
    python3 -c 'import sys; sys.exit(open(sys.argv[2]).read() not in open(sys.argv[1]).read())' \
      "$repo/docs/cluster.md" "$repo/docs/cluster/$script.sbatch" ||
      fail "docs/cluster.md does not show docs/cluster/$script.sbatch as it is"
  done
}
