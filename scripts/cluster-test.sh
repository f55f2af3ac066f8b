#!/usr/bin/env bash
# Renders the landing on a real scheduler and checks the frames against one unsharded run, byte for
# byte: a single-node Slurm started here (munged, slurmctld, slurmd, all in a scratch directory, on
# their own ports) runs the job-array recipes of docs/clusters/ with `sbatch --wait`; GNU parallel runs
# the docs' parallel recipes; indexed-Job shards run with JOB_COMPLETION_INDEX as Kubernetes sets it.
# Prints the time of each run (bench/README.md quotes them). Daemons are stopped by their pids on every
# exit; every wait is bounded, so a Slurm that cannot start fails with its log, never hangs.
# Usage: scripts/cluster-test.sh [--bench] [HLRSCRIPT]   (default build/runtime/hlrscript; needs root)
# --bench also times bench/scenes/turntable-100k.hls with --jobs 1 and 2 and through a Slurm array.
# KEEP=1 keeps the scratch directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=0
if [ "${1:-}" = --bench ]; then bench=1; shift; fi
hlrscript=$(realpath "${1:-$root/build/runtime/hlrscript}")
[ -x "$hlrscript" ] || { echo "cluster-test: no hlrscript at $hlrscript: build first (scripts/build.sh)"; exit 1; }
bash "$root/scripts/setup.sh" --cluster
for tool in munged mungekey slurmctld slurmd sbatch sinfo parallel; do
  command -v "$tool" >/dev/null || { echo "cluster-test: $tool is missing: run scripts/setup.sh"; exit 1; }
done
[ "$(id -u)" -eq 0 ] || { echo "cluster-test: slurmd starts jobs as their user, so it must run as root: sudo $0"; exit 1; }

work=$(mktemp -d /tmp/hlr-cluster.XXXXXX)
chmod 755 "$work"
pids=()   # the daemons started, and their names
names=()
stop_daemons() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  if [ "${KEEP:-0}" = 1 ]; then echo "cluster-test: kept $work"; else rm -rf "$work"; fi
  exit "$status"
}
trap stop_daemons EXIT
trap 'exit 130' INT TERM
fail() {
  echo "cluster-test: $*"
  for log in "$work"/slurm/*.err "$work"/slurm/*.log "$work"/munge/munged.log; do
    [ -s "$log" ] && { echo "--- $log (last lines)"; tail -n 15 "$log"; }
  done
  exit 1
}
wait_for() {  # wait_for SECONDS WHAT COMMAND...: polls until COMMAND succeeds, while every daemon lives
  local seconds=$1 what=$2 i
  shift 2
  for _ in $(seq $((seconds * 10))); do
    "$@" >/dev/null 2>&1 && return 0
    for i in "${!pids[@]}"; do
      kill -0 "${pids[$i]}" 2>/dev/null || fail "${names[$i]} exited while waiting for $what"
    done
    sleep 0.1
  done
  fail "$what did not happen within $seconds s"
}

# munge: its own key and socket, run as root (--force) so the scratch directory needs no munge user.
mkdir -p "$work/munge/key" "$work/munge/run"
chmod 700 "$work/munge/key"
mungekey --create --keyfile="$work/munge/key/munge.key" >/dev/null
socket=$work/munge/run/munge.socket
munged -F --force --socket="$socket" --key-file="$work/munge/key/munge.key" --pid-file="$work/munge/munged.pid" \
  --seed-file="$work/munge/seed" --log-file="$work/munge/munged.log" >>"$work/munge/munged.log" 2>&1 &
pids+=($!)
names+=(munged)
wait_for 10 "munged's socket" test -S "$socket"

# Slurm: one node (this machine, every core), one partition, nothing that needs systemd or cgroups.
mkdir -p "$work/slurm/state" "$work/slurm/spool"
ctld_port=$((20000 + RANDOM % 20000))
slurmd_port=$((ctld_port + 1))
export SLURM_CONF=$work/slurm/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=hlrtest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=main Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
cat >"$work/slurm/cgroup.conf" <<EOF
CgroupPlugin=cgroup/v1
EOF
# In the foreground (-D) so that $! is the daemon; what it says before its log file opens goes to .err.
slurmctld -D -i -f "$SLURM_CONF" >/dev/null 2>"$work/slurm/slurmctld.err" &
pids+=($!)
names+=(slurmctld)
wait_for 30 "slurmctld answering" scontrol ping
slurmd -D -N localhost -f "$SLURM_CONF" >/dev/null 2>"$work/slurm/slurmd.err" &
pids+=($!)
names+=(slurmd)
node_idle() { [ "$(sinfo -h -n localhost -o %t)" = idle ]; }
wait_for 60 "the node becoming idle" node_idle
echo "cluster-test: Slurm $(sinfo -V | cut -d' ' -f2) up: node localhost, $(nproc) CPUs"

# The scene, as a user would have it: the script and its include in one folder, hlrscript on PATH.
run=$work/run
mkdir -p "$run"
cp "$root/examples/desens/landing.hls" "$root/examples/desens/carrier-model.hls" "$run/"
export PATH=$(dirname "$hlrscript"):$PATH
export SOURCE_DATE_EPOCH=1700000000  # the PDF's date, so files from different runs can be compared
cd "$run"
frames=48
mkdir ref
started=$(date +%s%N)
hlrscript landing.hls -o 'ref/f-{frame:04}.pdf' -q --jobs 1 >/dev/null 2>&1
seconds() {  # seconds START_NS: the time since, as 1.23
  local ms=$((($(date +%s%N) - $1) / 1000000))
  printf '%d.%02d' $((ms / 1000)) $((ms % 1000 / 10))
}
echo "cluster-test: unsharded, --jobs 1: $frames frames in $(seconds "$started") s"
[ "$(find ref -name '*.pdf' | wc -l)" -eq "$frames" ] || fail "the unsharded run did not write $frames files"

same_as_ref() {  # same_as_ref WHAT: out/ holds exactly ref/'s files, byte for byte
  diff -r ref out >/dev/null || { diff -rq ref out | head; fail "$1: the frames differ from the unsharded run"; }
  echo "cluster-test: $1: $frames frames in $(seconds "$started") s, byte for byte the unsharded run"
  rm -rf out logs
}

submit() {  # submit SCRIPT: sbatch --wait, bounded
  mkdir -p out logs
  started=$(date +%s%N)
  timeout 300 sbatch --wait --quiet "$root/docs/clusters/$1" ||
    { cat logs/* 2>/dev/null | tail -n 20; fail "sbatch --wait $1 failed or timed out"; }
}
submit landing-array.sbatch
[ "$(find logs -name 'landing-*.out' | wc -l)" -eq 4 ] || fail "the array did not run 4 tasks"
same_as_ref "Slurm array --array=1-4%2, --shard auto"
submit landing-chunks.sbatch
[ "$(find logs -name 'chunks-*.out' | wc -l)" -eq 5 ] || fail "the chunked array did not run 5 tasks"
same_as_ref "Slurm array of 10-frame chunks, --frames"

# GNU parallel, as docs/clusters.md gives it: jobs on this host, then 'hosts' (':' is this host
# without ssh, so the multi-host form runs here too).
mkdir out
started=$(date +%s%N)
parallel --will-cite -N0 -j 3 hlrscript landing.hls -o "'out/f-{frame:04}.pdf'" -q --shard auto/3 ::: 1 2 3 \
  >/dev/null 2>&1 || fail "GNU parallel jobs failed"
same_as_ref "GNU parallel, 3 jobs, --shard auto/3"
mkdir out
started=$(date +%s%N)
parallel --will-cite -N0 -S 2/:,2/: --wd "$PWD" hlrscript landing.hls -o "'out/f-{frame:04}.pdf'" -q \
  --shard auto/4 ::: $(seq 4) >/dev/null 2>&1 || fail "GNU parallel over -S hosts failed"
same_as_ref "GNU parallel, -S 2/:,2/:, --shard auto/4"

# Kubernetes indexed Job: each pod sees JOB_COMPLETION_INDEX 0 ... completions-1.
mkdir out
started=$(date +%s%N)
for index in $(seq 0 7); do
  JOB_COMPLETION_INDEX=$index hlrscript landing.hls -o 'out/f-{frame:04}.pdf' -q --shard auto/8 >/dev/null 2>&1 ||
    fail "the pod with JOB_COMPLETION_INDEX=$index failed"
done
same_as_ref "8 indexed-Job pods, --shard auto/8"

# The recipes docs/clusters.md shows are these files, word for word.
for recipe in landing-array.sbatch landing-chunks.sbatch; do
  [[ "$(<"$root/docs/clusters.md")" == *"$(<"$root/docs/clusters/$recipe")"* ]] ||
    fail "docs/clusters.md does not show docs/clusters/$recipe as it is"
done
if ((bench)); then
  # Frames per second: the landing and the 100k-face turntable, on one and two cores, and the
  # turntable as a two-task array (one core each), scheduling latency included.
  cp "$root/bench/scenes/turntable-100k.hls" .
  for scene in landing turntable-100k; do
    n=$(hlrscript "$scene.hls" -o "bench-$scene-{frame:04}.pdf" -q --jobs 1 2>&1 | sed -n 's/.*: \([0-9]*\) frames.*/\1/p')
    for jobs in 1 2; do
      started=$(date +%s%N)
      hlrscript "$scene.hls" -o "bench-$scene-{frame:04}.pdf" -q --jobs "$jobs" >/dev/null 2>&1
      s=$(seconds "$started")
      echo "bench: $scene, $n frames, --jobs $jobs: $s s, $(awk "BEGIN {printf \"%.1f\", $n / $s}") frames/s"
    done
  done
  # sbatch --wait polls every few seconds, so the tasks stamp their own start and end.
  mkdir -p out logs
  started=$(date +%s%N)
  timeout 600 sbatch --wait --quiet --array=1-2 --cpus-per-task=1 --output='logs/tt-%a.out' --wrap \
    'echo start $(date +%s%N); hlrscript turntable-100k.hls -o "out/t-{frame:04}.pdf" -q --shard auto --jobs 1; echo end $(date +%s%N)' ||
    fail "the bench array failed"
  first=$(awk '$1 == "start" {print $2}' logs/tt-*.out | sort -n | head -1)
  last=$(awk '$1 == "end" {print $2}' logs/tt-*.out | sort -n | tail -1)
  [ "$(find out -name '*.pdf' | wc -l)" -eq 16 ] && [ -n "$first" ] && [ -n "$last" ] || fail "the bench array lost frames"
  for from in "$started" "$first"; do
    ms=$(((last - from) / 1000000))
    what=$([ "$from" = "$started" ] && echo "submitted to last frame" || echo "first task start to last frame")
    echo "bench: turntable-100k, 16 frames, Slurm --array=1-2 (1 CPU each), $what: $(awk "BEGIN {printf \"%.2f s, %.1f frames/s\", $ms / 1000, 16000 / $ms}")"
  done
fi
echo "cluster-test: passed"
