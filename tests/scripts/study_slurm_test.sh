#!/usr/bin/env bash
# The Slurm recipe for real: starts a one-node Slurm cluster on localhost from
# Debian's packages (munged, slurmctld and slurmd, each on its own key,
# socket, ports and folders under a temporary directory, so no system service
# is touched), has src/scripts/study_slurm.sh submit a three-task job array and
# its dependent merge job over the labelled synthetic office, waits for them,
# and compares the merge with the unsharded study: the table and statistics
# must be the same, byte for byte. Everything it starts it stops, and every
# wait is bounded. Skips (exit 77) where the packages are missing
# (src/scripts/setup.sh installs slurm-wlm and munge) or the daemons cannot
# start here (no root).
# usage: study_slurm_test.sh OCCLUSION_BINARY
set -euo pipefail
occlusion="$(realpath "$1")"
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$source_dir/tests/scripts/study_shards_common.sh"

for program in munged munge slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$program" >/dev/null ||
    skip "$program is not installed (apt-get install slurm-wlm munge, or src/scripts/setup.sh)"
done
[[ $(id -u) -eq 0 ]] || skip "a private Slurm cluster needs root here (SlurmUser=root)"

work="$(mktemp -d "${TMPDIR:-/tmp}/occlusion-slurm.XXXXXX")"
chmod 711 "$work"  # munged wants its socket's folder reachable by all
export SLURM_CONF="$work/slurm.conf"
pids=()

stop_cluster() {
  scancel --quiet --full "--name=occlusion-study" "--name=occlusion-study-merge" 2>/dev/null || true
  local pid
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for _ in $(seq 1 50); do
    local alive=false
    for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null && alive=true; done
    $alive || break
    sleep 0.2
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap stop_cluster EXIT

# Each daemon in the foreground, as our child: its pid is ours to stop.
start() {
  local name="$1"
  shift
  "$@" >"$work/$name.out" 2>&1 &
  pids+=($!)
}

show_logs() {
  local log
  for log in "$work"/*.out "$work"/*.log "$work"/study/slurm/*.log; do
    [[ -f "$log" ]] && { echo "== $log"; tail -n 20 "$log"; } >&2
  done
  return 0
}

dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
start munged munged --foreground --force --key-file="$work/munge.key" \
  --socket="$work/munge.sock" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munged.seed"
for _ in $(seq 1 50); do
  munge --socket="$work/munge.sock" --no-input >/dev/null 2>&1 && break
  sleep 0.2
done
munge --socket="$work/munge.sock" --no-input >/dev/null 2>&1 ||
  { show_logs; skip "munged does not start here"; }

# Ports from the pid, so that two runs on one machine do not collide.
port=$((20000 + ($$ % 4000) * 2))
mkdir -p "$work/state" "$work/spool"
cat >"$SLURM_CONF" <<CONF
ClusterName=occlusiontest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
start slurmctld slurmctld -D -c -f "$SLURM_CONF"
start slurmd slurmd -D -N localhost -f "$SLURM_CONF"
state=""
for _ in $(seq 1 60); do
  state="$(sinfo --noheader --format=%T 2>/dev/null || true)"
  [[ "$state" == idle ]] && break
  sleep 1
done
[[ "$state" == idle ]] || { show_logs; fail "the Slurm node did not become idle (state '$state')"; }
echo "Slurm cluster up on localhost (ports $port, $((port + 1)))"

cd "$work"
run_whole_study "$work/whole"
submitted="$(bash "$source_dir/src/scripts/study_slurm.sh" --shards 3 --out "$work/study" \
  --occlusion "$occlusion" --sbatch --cpus-per-task=1 --submit -- "${study_options[@]}")"
echo "$submitted"
merge_job="$(awk '$1 == "merge" {print $2}' <<<"$submitted")"
[[ -n "$merge_job" ]] || fail "study_slurm.sh printed no merge job"
for _ in $(seq 1 300); do
  [[ -z "$(squeue --noheader 2>/dev/null)" ]] && break
  sleep 1
done
[[ -z "$(squeue --noheader)" ]] || { show_logs; fail "the jobs did not finish within 300 s"; }
for i in 0 1 2; do
  [[ -s "$work/study/shard_$i/study.csv" ]] || { show_logs; fail "shard $i wrote no study.csv"; }
done
grep -q "runs merged from 3 CSV files" "$work/study/slurm/merge.log" ||
  { show_logs; fail "the merge job did not merge the three shards"; }
compare_studies "$work/whole" "$work/study"
