#!/usr/bin/env bash
# Checks the job scripts without a batch system: every script parses (bash -n) and answers
# --help; evolve.sbatch turns each form of Slurm's time-left string (squeue %L, faked) into the
# right --max-hours and builds the launch line it should (mpirun faked: it prints its
# arguments); chain.sh --dry-run links N submissions with afterany and one job name.
# Run by CTest (label jobs).
# usage: scripts_check.sh SOURCE_DIR WORK_DIR
set -euo pipefail

if [ "${1:-}" = --help ] || [ $# -ne 2 ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = --help ] && exit 0 || exit 2
fi
source=$(realpath "$1") work=$2
fail() { echo "scripts_check: FAIL: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work/bin"
work=$(realpath "$work")

# every job script parses and prints its usage
for f in "$source"/jobs/slurm/* "$source"/jobs/pbs/* "$source"/jobs/fuzz/*.sh "$source"/tests/jobs/*.sh; do
  bash -n "$f" || fail "bash -n $f"
done
for f in jobs/slurm/evolve.sbatch jobs/slurm/chain.sh jobs/pbs/evolve.pbs jobs/fuzz/nightly.sh; do
  bash "$source/$f" --help > "$work/help.txt" || fail "$f --help exited non-zero"
  grep -q -i 'usage\|sbatch\|qsub' "$work/help.txt" || fail "$f --help printed no usage"
done

# fakes: squeue prints $FAKE_LEFT, mpirun prints its arguments, cambrian is any executable
cat > "$work/bin/squeue" <<'EOF'
#!/usr/bin/env bash
# fake squeue -h -j ID -o %L
set -euo pipefail
echo "$FAKE_LEFT"
EOF
cat > "$work/bin/mpirun" <<'EOF'
#!/usr/bin/env bash
# fake mpirun: prints what it was asked to run
set -euo pipefail
echo "fake-mpirun $*"
EOF
printf '#!/usr/bin/env bash\nexit 0\n' > "$work/bin/cambrian"
chmod +x "$work/bin"/*
printf '[run]\nseed = 1\n' > "$work/x.ini"

# sbatch_with LEFT [ARGS...]: evolve.sbatch inside a fake job with LEFT time left
sbatch_with() {
  local left=$1
  shift
  (cd "$work" && env PATH="$work/bin:$PATH" FAKE_LEFT="$left" SLURM_JOB_ID=42 \
     SLURM_JOB_NAME=fake CAMBRIAN_EXE="$work/bin/cambrian" bash "$source/jobs/slurm/evolve.sbatch" \
     "$@")
}
# expect_hours LEFT HOURS [MARGIN]: the --max-hours that LEFT gives
expect_hours() {
  local out
  out=$(CAMBRIAN_MARGIN_S=${3:-} sbatch_with "$1" x.ini)
  grep -q -- "--max-hours $2\( \|$\)" <<< "$out" ||
    fail "time left '$1' (margin '${3:-default}'): expected --max-hours $2, got: $out"
  echo "time left $1 -> --max-hours $2"
}
expect_hours 1-00:00:00 22.800000          # 86400 s less 5 % (4320 s)
expect_hours 2:00:00 1.900000              # 7200 s less 5 % (360 s)
expect_hours 20:00 0.250000                # 1200 s less the 300 s minimum margin
expect_hours 10:00 0.083333                # 600 s: the margin is at most half
expect_hours 3:00 0.025000                 # 180 s: the margin is at most half
expect_hours 45 0.006389                   # 45 s: seconds only, 23 s kept (margin 22 s)
expect_hours 1-02:03:04 26.023333 100      # 93784 s less an explicit margin of 100 s
out=$(sbatch_with UNLIMITED x.ini)
grep -q -- '--max-hours' <<< "$out" && fail "UNLIMITED should give no --max-hours: $out"
echo "time left UNLIMITED -> no --max-hours"

# the launch line: output directory by job name, extra options passed on, srun when asked
out=$(sbatch_with 10:00 --config x.ini --fresh --seed 5)
grep -q "fake-mpirun $work/bin/cambrian evolve --config x.ini --out runs/fake --max-hours 0.083333 --fresh --seed 5" <<< "$out" ||
  fail "unexpected launch line: $out"
out=$(CAMBRIAN_ARGS="--out elsewhere --seed 9" sbatch_with 10:00 x.ini)
grep -q -- "--config x.ini --out elsewhere --max-hours 0.083333 --seed 9" <<< "$out" ||
  fail "CAMBRIAN_ARGS not applied: $out"
out=$(sbatch_with 10:00 x.ini --max-hours 2)
[ "$(echo "$out" | grep -c -- '--max-hours')" -eq 2 ] && grep -q -- 'runs/fake --max-hours 2$' <<< "$out" ||
  fail "an explicit --max-hours should replace the script's: $out"
printf '#!/usr/bin/env bash\necho "fake-srun $*"\n' > "$work/bin/srun" && chmod +x "$work/bin/srun"
out=$(CAMBRIAN_LAUNCHER=srun sbatch_with 10:00 x.ini)
grep -q "fake-srun --mpi=pmix --kill-on-bad-exit=1 $work/bin/cambrian evolve" <<< "$out" ||
  fail "srun launch line: $out"
# islands: a count, one per node (Slurm's node count, the node file's hosts), an explicit
# --islands.count wins, a bad value is exit 3; islands.sbatch and islands.pbs ask for one per node
out=$(CAMBRIAN_ISLANDS=3 sbatch_with 10:00 x.ini)
grep -q -- "--max-hours 0.083333 --islands.count 3$" <<< "$out" || fail "CAMBRIAN_ISLANDS=3: $out"
out=$(CAMBRIAN_ISLANDS=nodes SLURM_JOB_NUM_NODES=4 sbatch_with 10:00 x.ini --seed 2)
grep -q -- "--islands.count 4 --seed 2$" <<< "$out" || fail "CAMBRIAN_ISLANDS=nodes (4 nodes): $out"
out=$(CAMBRIAN_ISLANDS=nodes sbatch_with 10:00 x.ini --islands.count 2)
grep -q -- "--max-hours 0.083333 --islands.count 2$" <<< "$out" ||
  fail "an explicit --islands.count should replace the script's: $out"
CAMBRIAN_ISLANDS=many sbatch_with 10:00 x.ini > /dev/null 2>&1 && fail "CAMBRIAN_ISLANDS=many accepted"
out=$(cd "$work" && env PATH="$work/bin:$PATH" FAKE_LEFT=10:00 SLURM_JOB_ID=42 SLURM_JOB_NAME=fake \
  SLURM_JOB_NUM_NODES=3 SLURM_SUBMIT_DIR="$source" CAMBRIAN_EXE="$work/bin/cambrian" \
  bash "$source/jobs/slurm/islands.sbatch" x.ini)
grep -q -- "--islands.count 3$" <<< "$out" || fail "islands.sbatch on 3 nodes: $out"
printf 'n1\nn1\nn2\nn2\nn3\nn3\n' > "$work/nodefile"
out=$(cd "$work" && env PATH="$work/bin:$PATH" PBS_O_WORKDIR="$work" PBS_NODEFILE="$work/nodefile" \
  PBS_JOBNAME=fake CAMBRIAN_EXE="$work/bin/cambrian" CAMBRIAN_ISLANDS=nodes \
  bash "$source/jobs/pbs/evolve.pbs" --config x.ini)
grep -q -- "fake-mpirun -np 6 --hostfile $work/nodefile $work/bin/cambrian evolve --config x.ini --out runs/fake --islands.count 3$" <<< "$out" ||
  fail "evolve.pbs, one island per node of 3: $out"
set +e
(cd "$work" && CAMBRIAN_EXE="$work/bin/cambrian" bash "$source/jobs/slurm/evolve.sbatch" missing.ini) > /dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 3 ] || fail "a missing config file should exit 3, not $rc"
echo "launch lines as expected"

# chain.sh --dry-run: N sbatch lines, each after the one before, one job name
out=$(bash "$source/jobs/slurm/chain.sh" 3 --dry-run --time=1:00:00 -- --config jobs/experiments/walk.ini)
echo "$out"
[ "$(echo "$out" | grep -c '^sbatch --parsable --job-name=walk ')" -eq 3 ] || fail "chain: not 3 sbatch lines named walk"
echo "$out" | sed -n 1p | grep -q -- '--dependency' && fail "chain: the first job depends on something"
echo "$out" | sed -n 2p | grep -q -- '--dependency=afterany:JOB1 --time=1:00:00 ' || fail "chain: job 2 not after job 1"
echo "$out" | sed -n 3p | grep -q -- '--dependency=afterany:JOB2 ' || fail "chain: job 3 not after job 2"
out=$(bash "$source/jobs/slurm/chain.sh" 2 --dry-run -J mine --after 77)
echo "$out" | sed -n 1p | grep -q -- '--job-name=mine --dependency=afterany:77 ' || fail "chain: --after: $out"
out=$(bash "$source/jobs/slurm/chain.sh" 3 --dry-run -J f -- x.ini --fresh --seed 2)
[ "$(echo "$out" | grep -c -- ' x.ini --fresh --seed 2$')" -eq 1 ] &&
  [ "$(echo "$out" | grep -c -- ' x.ini --seed 2$')" -eq 2 ] || fail "chain: --fresh not on the first job only: $out"
for bad in 0 51 x; do
  bash "$source/jobs/slurm/chain.sh" "$bad" --dry-run > /dev/null 2>&1 && fail "chain accepted N=$bad"
done
bash "$source/jobs/slurm/chain.sh" 2 --dry-run -d afterok:1 > /dev/null 2>&1 && fail "chain accepted -d"
echo "chain.sh as expected"
echo "scripts_check: OK"
