#!/usr/bin/env bash
# Brings up a one-node Slurm cluster on localhost (munged, slurmctld and slurmd from Debian's
# slurm-wlm and munge, as root, configured in a temporary directory on free ports) and runs
# jobs/slurm/evolve.sbatch and jobs/slurm/chain.sh on tiny synthetic experiments:
#   complete:  one job runs an evolution to the end (COMPLETED, exit 0, --max-hours passed,
#              every generation in the history)
#   srun:      the same script with CAMBRIAN_LAUNCHER=srun (srun --mpi=pmix), stopped by SIGUSR1
#   resume:    a chain of six jobs (afterany) with a 1 minute limit; the first is stopped
#              by `scancel --signal=USR1 --batch`, checkpoints and exits 0, the next ones
#              continue from the checkpoint and stop before their --max-hours, until one
#              completes the run and cancels the rest; the history is identical
#              (analysis/compare_histories.py) to a straight run of the same experiment
#   islands:   jobs/slurm/islands.sbatch, two islands, stopped by SIGUSR1 and continued by a
#              second job: every island's digest is the straight run's
# The daemons are stopped on exit, whatever happens; on failure their logs are printed.
# Run by CTest (label slurm); fails (never skips) when Slurm cannot be started.
# usage: slurm_check.sh CAMBRIAN SOURCE_DIR WORK_DIR [complete|srun|resume|islands|all]
set -euo pipefail

if [ "${1:-}" = --help ] || [ $# -lt 3 ]; then
  sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = --help ] && exit 0 || exit 2
fi
cambrian=$(realpath "$1") source=$(realpath "$2") work=$3 what=${4:-all}

# failure: say why, then the trap prints the logs
fail() { echo "slurm_check: FAIL: $*" >&2; exit 1; }
log() { echo "slurm_check: $*"; }

# preconditions: root and the Slurm and munge programs
[ "$(id -u)" -eq 0 ] || fail "must run as root (the test starts slurmd, which runs jobs as root)"
for p in munged munge slurmctld slurmd sbatch squeue scontrol sinfo scancel mpirun python3; do
  command -v "$p" > /dev/null ||
    fail "'$p' not found: install slurm-wlm, slurm-client and munge (jobs/setup/install-deps.sh)"
done

# directories: job outputs under WORK_DIR, daemon state in a short /tmp path (socket length)
rm -rf "$work" && mkdir -p "$work"
work=$(realpath "$work")
state=$(mktemp -d /tmp/cambrian-slurm.XXXXXX)
chmod 755 "$state"
mkdir -p "$state"/{munge,ctld,spool,log}
chmod 755 "$state/munge"
export SLURM_CONF=$state/slurm.conf

# stop everything this script started, by pid; print logs when failing
cleanup() {
  local rc=$?
  set +e
  trap - EXIT INT TERM
  # background runs of this script (the straight run)
  local children
  children=$(jobs -p)
  # shellcheck disable=SC2086  # one pid per word
  [ -z "$children" ] || kill $children 2> /dev/null
  if [ -f "$state/slurmctld.pid" ]; then
    scancel --full --quiet --user root > /dev/null 2>&1
    for _ in $(seq 1 20); do [ -z "$(squeue -h 2> /dev/null)" ] && break; sleep 0.5; done
  fi
  for daemon in slurmd slurmctld munge/munged; do
    local pidfile=$state/$daemon.pid pid
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2> /dev/null
    for _ in $(seq 1 20); do kill -0 "$pid" 2> /dev/null || break; sleep 0.25; done
    kill -9 "$pid" 2> /dev/null
  done
  cp -r "$state/log" "$work/daemon-logs" 2> /dev/null
  if [ "$rc" -ne 0 ]; then
    for f in "$state"/log/*.log "$state"/munge/munged.log "$work"/*.out; do
      [ -f "$f" ] || continue
      echo "----- $f (last 40 lines)"
      tail -n 40 "$f"
    done
    echo "slurm_check: FAILED (exit $rc); logs kept in $work/daemon-logs"
  fi
  rm -rf "$state"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# wait_for SECONDS DESCRIPTION COMMAND...: polls COMMAND every half second until it succeeds
wait_for() {
  local limit=$1 what=$2 start=$SECONDS
  shift 2
  until "$@" > /dev/null 2>&1; do
    [ $((SECONDS - start)) -lt "$limit" ] || fail "timed out after ${limit}s waiting for $what"
    sleep 0.5
  done
}

# two free TCP ports on loopback for slurmctld and slurmd
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

# munged with its own key and socket
dd if=/dev/urandom of="$state/munge/munge.key" bs=1 count=1024 status=none
chmod 600 "$state/munge/munge.key"
munged --socket="$state/munge/munge.sock" --key-file="$state/munge/munge.key" \
  --log-file="$state/munge/munged.log" --pid-file="$state/munge/munged.pid" \
  --seed-file="$state/munge/munged.seed" || fail "munged did not start"
wait_for 10 "munged" munge -n -S "$state/munge/munge.sock"

# slurm.conf: this host as controller and the one node; no cgroups, accounting or systemd
host=$(hostname -s)
cat > "$SLURM_CONF" <<EOF
ClusterName=cambrian-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$state/munge/munge.sock
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
SlurmdParameters=config_overrides
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MailProg=/bin/true
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
KillWait=10
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=4 Boards=1 SocketsPerBoard=1 CoresPerSocket=4 ThreadsPerCore=1 RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF

# the controller, then the node; the node must come up idle
slurmctld -i -f "$SLURM_CONF" || fail "slurmctld did not start"
wait_for 30 "slurmctld to answer (scontrol ping)" bash -c 'scontrol ping | grep -q UP'
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
wait_for 30 "the node to be idle" bash -c 'sinfo -h -o %T | grep -qx idle'
log "one-node cluster up: $(sinfo -h -o '%P %D %T %C') (ports $ctld_port, $slurmd_port)"

# job environment: Open MPI as root, oversubscription allowed, the executable
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export CAMBRIAN_EXE=$cambrian
cd "$work"

# experiment: synthetic task; write_config FILE GENERATIONS COST_US
write_config() {
  cat > "$1" <<EOF
[task]
name = synthetic
synthetic_cost_us = $3
synthetic_cost_per_gene_us = 20
synthetic_noise = 0.2
[evolution]
population = 12
generations = $2
selection = tournament
[run]
seed = 11
EOF
}

# job_field JOBID FIELD: one field of `scontrol show job`
job_field() { scontrol -o show job "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }
job_done() { case $(job_field "$1" JobState) in COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY) return 0 ;; esac; return 1; }
# expect_completed JOBID: the job ended COMPLETED with exit 0
expect_completed() {
  wait_for "${2:-90}" "job $1 to end" job_done "$1"
  local st ec
  st=$(job_field "$1" JobState) ec=$(job_field "$1" ExitCode)
  [ "$st" = COMPLETED ] && [ "$ec" = 0:0 ] || fail "job $1 ended $st with exit code $ec"
}
# generations_in DIR: data lines of DIR/generations.tsv
generations_in() { [ -f "$1/generations.tsv" ] && echo $(($(wc -l < "$1/generations.tsv") - 1)) || echo 0; }

# complete: one job, start to finish
check_complete() {
  write_config "$work/complete.ini" 6 1000
  local id
  id=$(sbatch --parsable -J complete --ntasks=2 --time=5 --signal=B:USR1@30 \
         "$source/jobs/slurm/evolve.sbatch" --config complete.ini)
  log "complete: submitted job $id"
  expect_completed "$id"
  local out=$work/complete-$id.out
  [ -f "$out" ] || fail "no log complete-$id.out (logs are named <job name>-<job id>.out)"
  grep -q 'evolve.sbatch: fresh start; time left [0-9]* s, --max-hours 0\.0' "$out" ||
    fail "complete: the log does not show --max-hours from the time left"
  grep -q '^gen 6/6 ' "$out" || fail "complete: the run did not reach generation 6"
  [ -f "$work/runs/complete/history.h5" ] || fail "complete: no runs/complete/history.h5"
  [ "$(generations_in "$work/runs/complete")" -eq 6 ] ||
    fail "complete: runs/complete/generations.tsv has $(generations_in "$work/runs/complete") generations"
  log "complete: job $id COMPLETED, 6 generations, $(grep -o -- '--max-hours [0-9.]*' "$out" | head -n1)"
}

# resume: a chain of six jobs (afterany) with a short time limit: the first is stopped by its
# signal, the next ones by --max-hours (60 s limit less a 50 s margin: about 10 s of a run
# that needs about 13 s of evaluations after the first job's few generations — 70 generations
# of about 10 evaluated creatures, the elites being copied, of 20 ms — so the second job cannot
# finish it however fast the machine (at 15 ms a fast machine once finished 63 generations in
# 9.95 s), and four jobs have about three times the time it needs, however slow: 100
# generations of 15 ms once left a sanitizer build 6 short), one completes the run and cancels
# the rest; the history equals a straight run's
check_resume() {
  local total=70
  write_config "$work/resume.ini" $total 20000
  # the straight run, in process, beside the chain (results do not depend on rank count)
  "$cambrian" evolve --config "$work/resume.ini" --out "$work/straight" --quiet \
    > "$work/straight.txt" 2>&1 &
  local straight_pid=$! ids
  ids=$(CAMBRIAN_MARGIN_S=50 bash "$source/jobs/slurm/chain.sh" 6 -J resume --ntasks=2 \
          --time=1 --signal=B:USR1@10 -- --config resume.ini) || fail "chain.sh failed: $ids"
  local -a jobs
  mapfile -t jobs <<< "$ids"
  [ ${#jobs[@]} -eq 6 ] || fail "chain.sh printed '$ids', not six job ids"
  log "resume: chain ${jobs[*]} (afterany)"
  [ "$(job_field "${jobs[1]}" Dependency)" = "afterany:${jobs[0]}(unfulfilled)" ] ||
    fail "job ${jobs[1]} has dependency '$(job_field "${jobs[1]}" Dependency)', not afterany:${jobs[0]}"

  # the first job: stopped by its signal once it is a few generations in
  local j1=${jobs[0]}
  wait_for 60 "job $j1 to reach generation 3" grep -q "^gen 3/$total " "$work/resume-$j1.out"
  scancel --signal=USR1 --batch "$j1" || fail "scancel --signal=USR1 --batch $j1"
  expect_completed "$j1"
  local reached
  reached=$(generations_in "$work/runs/resume")
  grep -q 'evolve.sbatch: got SIGUSR1' "$work/resume-$j1.out" || fail "job $j1: the batch shell did not trap SIGUSR1"
  grep -q 'stopped by SIGUSR1 after' "$work/resume-$j1.out" || fail "job $j1: rank 0 did not stop on SIGUSR1"
  grep -q 'stopped cleanly; the next job' "$work/resume-$j1.out" || fail "job $j1: not reported as stopped cleanly"
  [ "$reached" -ge 3 ] && [ "$reached" -lt $total ] || fail "job $j1 left $reached generations (expected 3..$((total - 1)))"
  [ -f "$work/runs/resume/checkpoint.h5" ] || fail "job $j1 left no checkpoint"
  log "resume: job $j1 stopped by SIGUSR1 after $reached generations, exit 0, checkpoint written"

  # the next jobs: each continues where the last stopped, until one completes the run
  local k j complete="" by_time=0
  for ((k = 1; k < 6; k++)); do
    j=${jobs[k]}
    if [ -n "$complete" ]; then
      wait_for 30 "job $j to be cancelled" job_done "$j"
      [ "$(job_field "$j" JobState)" = CANCELLED ] ||
        fail "job $j ended $(job_field "$j" JobState), expected CANCELLED by job $complete, which completed the run"
      log "resume: job $j cancelled by job $complete (nothing left to do)"
      continue
    fi
    expect_completed "$j" 120
    grep -q "resuming from runs/resume/checkpoint.h5 at generation $reached " "$work/resume-$j.out" ||
      fail "job $j did not resume at generation $reached"
    reached=$(generations_in "$work/runs/resume")
    if grep -q 'the run is complete' "$work/resume-$j.out"; then
      [ "$reached" -eq $total ] || fail "job $j reported a complete run with $reached generations"
      complete=$j
      log "resume: job $j continued and completed the run"
    else
      grep -q 'stopped before the --max-hours' "$work/resume-$j.out" ||
        fail "job $j neither completed the run nor stopped before --max-hours"
      by_time=$((by_time + 1))
      log "resume: job $j continued and stopped before its --max-hours after generation $reached, exit 0"
    fi
  done
  [ -n "$complete" ] || fail "six jobs did not complete the run ($reached of $total generations)"
  [ "$by_time" -ge 1 ] || fail "no job stopped by --max-hours"

  # the chained history is the straight run's
  wait "$straight_pid" || { cat "$work/straight.txt"; fail "the straight run failed"; }
  "$source/analysis/compare_histories.py" "$work/straight/history.h5" \
    "$work/runs/resume/history.h5" || fail "the chained history differs from the straight run's"
  [ "$(grep '^digest ' "$work/straight.txt")" = "$(grep '^digest ' "$work/resume-$complete.out")" ] ||
    fail "digests differ: $(grep '^digest ' "$work/straight.txt") vs $(grep '^digest ' "$work/resume-$complete.out")"
  log "resume: history identical to the straight run's (compare_histories.py), $(grep '^digest ' "$work/straight.txt")"
}

# srun: the same job launched with `srun --mpi=pmix` instead of mpirun; stopped by SIGUSR1
check_srun() {
  write_config "$work/srun.ini" 200 15000
  local id
  id=$(CAMBRIAN_LAUNCHER=srun sbatch --parsable -J srun --ntasks=2 --time=5 \
         --signal=B:USR1@30 "$source/jobs/slurm/evolve.sbatch" --config srun.ini)
  wait_for 60 "job $id to reach generation 3" grep -q '^gen 3/200 ' "$work/srun-$id.out"
  scancel --signal=USR1 --batch "$id" || fail "scancel --signal=USR1 --batch $id"
  expect_completed "$id"
  grep -q 'evolve.sbatch: srun --mpi=pmix' "$work/srun-$id.out" || fail "srun: not launched by srun"
  grep -q 'cambrian evolve: 2 rank(s)' "$work/srun-$id.out" || fail "srun: not 2 ranks"
  grep -q 'stopped by SIGUSR1 after' "$work/srun-$id.out" || fail "srun: rank 0 did not stop on SIGUSR1"
  log "srun: job $id ran 2 ranks under srun --mpi=pmix, stopped by SIGUSR1 after $(generations_in "$work/runs/srun") generations"
}

# islands: jobs/slurm/islands.sbatch with two islands of 3 ranks (one node here, so the count
# is given), stopped by SIGUSR1 and continued by a second job to the end; every island's digest
# is that of a straight run of the same islands outside Slurm
check_islands() {
  write_config "$work/islands.ini" 40 15000
  printf '[islands]\ncount = 2\ninterval = 2\nmigrants = 2\n' >> "$work/islands.ini"
  mpirun -np 2 --oversubscribe "$cambrian" evolve --config "$work/islands.ini" \
    --out "$work/islands_straight" --quiet > "$work/islands_straight.txt" 2>&1 &
  local straight_pid=$! id
  id=$(CAMBRIAN_ISLANDS=2 sbatch --parsable -J islands --nodes=1 --ntasks-per-node=3 --time=5 \
         "$source/jobs/slurm/islands.sbatch" --config islands.ini)
  wait_for 60 "job $id to reach generation 3" grep -q '^gen 3/40 ' "$work/islands-$id.out"
  scancel --signal=USR1 --batch "$id" || fail "scancel --signal=USR1 --batch $id"
  expect_completed "$id"
  grep -q -- '--islands.count 2' "$work/islands-$id.out" || fail "islands: no --islands.count 2 in the launch line"
  grep -q 'cambrian evolve: 2 islands of' "$work/islands-$id.out" || fail "islands: not two islands"
  grep -q 'stopped cleanly; the next job' "$work/islands-$id.out" || fail "islands: job $id did not stop cleanly"
  local id2
  id2=$(CAMBRIAN_ISLANDS=2 sbatch --parsable -J islands --nodes=1 --ntasks-per-node=3 --time=5 \
          "$source/jobs/slurm/islands.sbatch" --config islands.ini)
  expect_completed "$id2" 120
  grep -q 'continuing from runs/islands/island_\*/checkpoint.h5' "$work/islands-$id2.out" ||
    fail "islands: job $id2 did not say it continues"
  grep -q 'the run is complete' "$work/islands-$id2.out" || fail "islands: job $id2 did not complete the run"
  grep -q 'resuming from runs/islands/island_1/checkpoint.h5' "$work/runs/islands/island_1/evolve.log" ||
    fail "islands: island 1 did not resume (its evolve.log)"
  wait "$straight_pid" || { cat "$work/islands_straight.txt"; fail "the straight island run failed"; }
  diff <(grep -e '^island ' -e '^digest ' "$work/islands_straight.txt") \
    <(grep -e '^island ' -e '^digest ' "$work/islands-$id2.out") ||
    fail "islands: the continued islands differ from the straight run's"
  log "islands: job $id stopped by SIGUSR1, job $id2 continued both islands to the straight run's digests"
}

case $what in
  complete) check_complete ;;
  srun) check_srun ;;
  resume) check_resume ;;
  islands) check_islands ;;
  all) check_complete; check_srun; check_resume; check_islands ;;
  *) fail "unknown check '$what' (complete, srun, resume, islands, all)" ;;
esac
log "OK"
