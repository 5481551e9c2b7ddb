#!/usr/bin/env bash
# MPI checks of `cambrian evolve`, run by CTest at several rank counts.
# usage: evolve_check.sh MODE CAMBRIAN MPIEXEC NPFLAG NP WORKDIR
#   same_run:   the run at NP ranks has the digest and individuals table (minus timing and rank
#               columns) of the single-rank in-process run
#   bad_config: impossible settings exit with the config code (3) on every rank, no hang
#   worker_failure: an exception inside a worker's evaluation becomes a failed outcome
#   rank0_idle: rank 0 sleeps while the workers evaluate: its CPU time stays a small part of
#               the run's wall time (a busy-polling rank 0 would use all of it)
set -euo pipefail
mode=$1 cambrian=$2 mpiexec=$3 npflag=$4 np=$5 work=$6
mpirun_() { "$mpiexec" "$npflag" "$np" --oversubscribe "$@"; }
rm -rf "$work" && mkdir -p "$work"
cat > "$work/run.ini" <<INI
[task]
name = synthetic
synthetic_cost_us = 300
synthetic_cost_per_gene_us = 20
synthetic_noise = 0.3
[evolution]
population = 16
generations = 4
selection = tournament
[run]
seed = 5
quiet = true
INI

case $mode in
  same_run)
    "$cambrian" evolve --config "$work/run.ini" --out "$work/one" > "$work/one.txt"
    mpirun_ "$cambrian" evolve --config "$work/run.ini" --out "$work/many" > "$work/many.txt"
    a=$(grep '^digest ' "$work/one.txt"); b=$(grep '^digest ' "$work/many.txt")
    echo "1 rank: $a   $np ranks: $b"
    [ -n "$a" ] && [ "$a" = "$b" ]
    cut -f1-7 "$work/one/individuals.tsv" > "$work/one.cut"
    cut -f1-7 "$work/many/individuals.tsv" > "$work/many.cut"
    diff "$work/one.cut" "$work/many.cut"
    [ "$(wc -l < "$work/many.cut")" -eq 65 ]
    # every worker rank took part (ranks 1..np-1 in column 9)
    workers=$(cut -f9 "$work/many/individuals.tsv" | grep -v -e worker_rank -e '^-1$' | sort -u | wc -l)
    [ "$workers" -eq $((np - 1)) ]
    ;;
  bad_config)
    for bad in "--evolution.population 0" "--evolution.elite_fraction 1.2" \
               "--physics.time_step=-0.01" "--evolution.graft_fraction 0.9" \
               "--evolution.population many" "--evolution.no_such_key 1"; do
      set +e
      # shellcheck disable=SC2086
      mpirun_ "$cambrian" evolve --config "$work/run.ini" --out "$work/bad" $bad \
        > "$work/bad.out" 2> "$work/bad.err"
      rc=$?
      set -e
      echo "$bad -> exit $rc: $(grep -m1 error "$work/bad.err" || true)"
      [ "$rc" -eq 3 ] || [ "$rc" -eq 2 ]
      key=${bad%%[ =]*}; key=${key#--}
      grep -q "${key}" "$work/bad.err"
      [ ! -e "$work/bad/individuals.tsv" ]
    done
    # a bad key inside the file names the file
    printf '[evolution]\npopulation = 0\n' > "$work/zero.ini"
    set +e
    mpirun_ "$cambrian" evolve --config "$work/zero.ini" > /dev/null 2> "$work/zero.err"
    rc=$?
    set -e
    [ "$rc" -eq 3 ] && grep -q "zero.ini" "$work/zero.err" && grep -q "population = 0" "$work/zero.err"
    ;;
  worker_failure)
    mpirun_ "$cambrian" evolve --config "$work/run.ini" --out "$work/fail" --run.fail_every 5 \
      > "$work/fail.out" 2> "$work/fail.err"
    grep -q "creature 5 failed: injected failure" "$work/fail.err"
    grep -q "rank [1-9][0-9]*: creature" "$work/fail.err"
    # every evaluated creature with an id divisible by 5 failed, with fitness 0
    awk -F'\t' 'NR > 1 && $4 != "elite" && $2 % 5 == 0 {
                  n++; if ($6 != "failed" || $5 != 0) bad++ }
                END { exit (n > 0 && bad == 0) ? 0 : 1 }' "$work/fail/individuals.tsv"
    # and the others did not
    awk -F'\t' 'NR > 1 && $4 != "elite" && $2 % 5 != 0 && $6 != "ok" { bad++ }
                END { exit bad ? 1 : 0 }' "$work/fail/individuals.tsv"
    ;;
  rank0_idle)
    mpirun_ "$cambrian" evolve --config "$work/run.ini" --out "$work/idle" \
      --task.synthetic_cost_us 20000 --task.synthetic_cost_per_gene_us 0 \
      --evolution.population 24 --evolution.generations 3 > "$work/idle.txt"
    cpu=$(awk '$1 == "rank0_cpu_seconds" { print $2 }' "$work/idle.txt")
    wall=$(awk '$1 == "wall_seconds" { print $2 }' "$work/idle.txt")
    echo "rank 0 cpu $cpu s of $wall s wall"
    awk -v cpu="$cpu" -v wall="$wall" 'BEGIN { exit (wall > 0 && cpu < 0.25 * wall) ? 0 : 1 }'
    ;;
  *)
    echo "unknown mode $mode" >&2
    exit 2
    ;;
esac
echo "$mode at $np ranks: ok"
