#!/usr/bin/env bash
# Runs jobs/pbs/evolve.pbs the way a PBS/Torque node would (a PBS script is a shell script),
# with a faked PBS environment (PBS_O_WORKDIR, PBS_JOBID, PBS_JOBNAME, PBS_NODEFILE and the
# walltime) and mpirun, on tiny synthetic experiments:
#   complete: the job runs to the end from another directory, with --max-hours from
#             PBS_WALLTIME (Torque) and, in a second job, from a fake `qstat -f` (PBS Pro)
#   resume:   a job stopped by SIGTERM (what PBS sends at the walltime) checkpoints and exits
#             0; the same script run again continues, and the history is identical
#             (analysis/compare_histories.py) to a straight run
# Run by CTest (label pbs).
# usage: pbs_check.sh CAMBRIAN SOURCE_DIR WORK_DIR [complete|resume|all]
set -euo pipefail

if [ "${1:-}" = --help ] || [ $# -lt 3 ]; then
  sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = --help ] && exit 0 || exit 2
fi
cambrian=$(realpath "$1") source=$(realpath "$2") work=$3 what=${4:-all}
script=$source/jobs/pbs/evolve.pbs

fail() { echo "pbs_check: FAIL: $*" >&2; exit 1; }
log() { echo "pbs_check: $*"; }

# a clean work directory, a node file with two slots and a fake qstat for PBS Pro
rm -rf "$work" && mkdir -p "$work/bin"
work=$(realpath "$work")
printf 'localhost\nlocalhost\n' > "$work/nodefile"
cat > "$work/bin/qstat" <<'EOF'
#!/usr/bin/env bash
# fake PBS Pro qstat -f JOBID: the walltime of a 15 minute job
set -euo pipefail
echo "Job Id: $2"
echo "    Resource_List.walltime = 00:15:00"
EOF
chmod +x "$work/bin/qstat"
bash -n "$script" || fail "bash -n $script"

# the job environment PBS would give, Open MPI as root
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export CAMBRIAN_EXE=$cambrian PBS_O_WORKDIR=$work PBS_NODEFILE=$work/nodefile

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
seed = 13
EOF
}
generations_in() { [ -f "$1/generations.tsv" ] && echo $(($(wc -l < "$1/generations.tsv") - 1)) || echo 0; }

# run_job NAME LOG [ENV...]: the script as PBS runs it (from $HOME), in the background
run_job() {
  local name=$1 out=$2
  shift 2
  (cd / && env PBS_JOBID="$name.fake-server" PBS_JOBNAME="$name" "$@" \
     bash "$script" > "$out" 2>&1) &
  job_pid=$!
}

check_complete() {
  write_config "$work/tiny.ini" 5 1000
  # Torque: PBS_WALLTIME in seconds
  run_job torque "$work/torque.o1" PBS_WALLTIME=600 CAMBRIAN_CONFIG=tiny.ini
  wait "$job_pid" || { cat "$work/torque.o1"; fail "torque job failed"; }
  # (599 s and a margin of 299 s when a second ticks between the job's start and the script's look
  # at the clock: the run still gets 300 s)
  grep -Eq 'time left (600 s, --max-hours 0.083333 \(margin 300 s|599 s, --max-hours 0.083333 \(margin 299 s)\)' \
    "$work/torque.o1" ||
    { cat "$work/torque.o1"; fail "torque: --max-hours not 300 s from PBS_WALLTIME=600"; }
  grep -q -- '-np 2 --hostfile' "$work/torque.o1" || fail "torque: ranks not taken from PBS_NODEFILE"
  [ "$(generations_in "$work/runs/torque")" -eq 5 ] || fail "torque: not 5 generations in runs/torque"
  log "complete: Torque-style job ran 5 generations in runs/torque with --max-hours 0.083333"

  # PBS Pro: the walltime from qstat -f, the config as an argument
  run_job pbspro "$work/pbspro.o2" PATH="$work/bin:$PATH" CAMBRIAN_ARGS="--config tiny.ini"
  wait "$job_pid" || { cat "$work/pbspro.o2"; fail "pbspro job failed"; }
  # (899 s when a second ticks between the job's start and the script's look at the clock)
  grep -Eq 'time left (900 s, --max-hours 0.166667|899 s, --max-hours 0.166389) \(margin 300 s\)' \
    "$work/pbspro.o2" ||
    { cat "$work/pbspro.o2"; fail "pbspro: --max-hours not 600 s from qstat's walltime 00:15:00"; }
  [ "$(generations_in "$work/runs/pbspro")" -eq 5 ] || fail "pbspro: not 5 generations"
  log "complete: PBS Pro-style job took the walltime from qstat -f"
}

# resume: SIGTERM to the job script (PBS at the walltime) stops the run cleanly; run again, it
# continues to the end and equals a straight run
check_resume() {
  write_config "$work/resume.ini" 40 15000
  "$cambrian" evolve --config "$work/resume.ini" --out "$work/straight" --quiet \
    > "$work/straight.txt" 2>&1 || { cat "$work/straight.txt"; fail "the straight run failed"; }

  # the first job, stopped by SIGTERM once a few generations are done
  export CAMBRIAN_CONFIG=resume.ini PBS_WALLTIME=3600
  (cd / && exec env PBS_JOBID=1.fake-server PBS_JOBNAME=resume bash "$script" \
     > "$work/resume.o1" 2>&1) &
  local pid=$! start=$SECONDS
  until grep -q '^gen 3/40 ' "$work/resume.o1"; do
    [ $((SECONDS - start)) -lt 60 ] || { kill "$pid"; fail "job 1 did not reach generation 3 in 60 s"; }
    kill -0 "$pid" 2> /dev/null || { cat "$work/resume.o1"; fail "job 1 ended early"; }
    sleep 0.2
  done
  kill -TERM "$pid"
  wait "$pid" || { cat "$work/resume.o1"; fail "job 1 did not exit 0 after SIGTERM"; }
  grep -q 'evolve.pbs: got SIGTERM' "$work/resume.o1" || fail "job 1: SIGTERM not trapped"
  grep -q 'stopped by SIGUSR1 after' "$work/resume.o1" || fail "job 1: rank 0 did not stop on the forwarded SIGUSR1"
  local done1
  done1=$(generations_in "$work/runs/resume")
  [ "$done1" -ge 3 ] && [ "$done1" -lt 40 ] || fail "job 1 left $done1 generations (expected 3..39)"
  log "resume: job 1 stopped by SIGTERM after $done1 generations, exit 0"

  # the second job: the same script again continues and completes the run
  (cd / && exec env PBS_JOBID=2.fake-server PBS_JOBNAME=resume bash "$script" \
     > "$work/resume.o2" 2>&1) || { cat "$work/resume.o2"; fail "job 2 failed"; }
  grep -q "continuing from runs/resume/checkpoint.h5" "$work/resume.o2" || fail "job 2 did not see the checkpoint"
  grep -q "resuming from runs/resume/checkpoint.h5 at generation $done1 " "$work/resume.o2" ||
    fail "job 2 did not resume at generation $done1"
  grep -q 'the run is complete' "$work/resume.o2" || fail "job 2 did not complete the run"
  "$source/analysis/compare_histories.py" "$work/straight/history.h5" "$work/runs/resume/history.h5" ||
    fail "the resumed history differs from the straight run's"

  # a third job finds the finished run and exits 0 without a generation
  (cd / && exec env PBS_JOBID=3.fake-server PBS_JOBNAME=resume bash "$script" \
     > "$work/resume.o3" 2>&1) || { cat "$work/resume.o3"; fail "job 3 failed"; }
  grep -q '^gen ' "$work/resume.o3" && fail "job 3 ran a generation of a finished run"
  grep -q 'the run is complete' "$work/resume.o3" || fail "job 3 did not report the run complete"
  log "resume: job 2 continued at generation $done1, history identical to the straight run's; job 3 found it complete"
}

case $what in
  complete) check_complete ;;
  resume) check_resume ;;
  all) check_complete; check_resume ;;
  *) fail "unknown check '$what' (complete, resume, all)" ;;
esac
log "OK"
