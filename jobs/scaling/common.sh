#!/usr/bin/env bash
# Shared part of jobs/scaling/strong.sh and weak.sh: options, the binary, one run per point and
# repeat (runs/scaling/<name>/w<W>/r<R>/), then analysis/scaling.py and analysis/scaling_model.py.
# Sourced with MODE=strong or MODE=weak set; not run on its own.
set -euo pipefail

usage() {
  cat <<USAGE
usage: jobs/scaling/$MODE.sh [options]
$( [ "$MODE" = strong ] && echo "Strong scaling: one population for every worker count." \
                        || echo "Weak scaling: population = --per-worker × workers." )
Runs \`mpirun -np W+1 cambrian evolve\` (rank 0 plus W workers) for each worker count and repeat,
one output directory (with history.h5) per run: OUT_ROOT/NAME/w<W>/r<R>/, then
analysis/scaling.py (--mode $MODE) and analysis/scaling_model.py on the sweep.

options:
  --workers "1 2"     worker counts (default "1 2"; e.g. "1 2 4 8 16")
  --repeats R         runs per worker count (default 3)
  --generations G     generations per run (default 5)
  --population P      strong: population of every run (default 300)
  --per-worker N      weak: creatures per worker (default 100)
  --task T            synthetic (default) or walk
  --cost-us US        synthetic task: microseconds of work per evaluation (default 10000)
  --config FILE       experiment file (default jobs/experiments/synthetic.ini or walk.ini)
  --seed S            run seed, the same for every run (default 1)
  --name NAME         sweep name (default $MODE-<task>)
  --out-root DIR      where sweeps go (default runs/scaling)
  --binary PATH       cambrian binary (default build/release/src/app/cambrian, built with the
                      release preset when missing)
  --mpirun CMD        MPI launcher (default mpirun)
  --oversubscribe     pass --oversubscribe to mpirun (more ranks than cores)
  --force             replace an existing sweep directory of the same name
  --no-analysis       only run, do not call the analysis scripts
  -h, --help          this text
  -- OPTIONS          the rest goes to every \`cambrian evolve\` (e.g. -- --run.dispatch_order shuffled)
exit codes: 0 ok, 2 usage, otherwise the failing run's exit code (docs/exit-codes.md)
USAGE
}

# defaults (small: this must finish on a 2-core machine)
workers="1 2" repeats=3 generations=5 population=300 per_worker=100 task=synthetic cost_us=10000
config="" seed=1 name="" out_root=runs/scaling binary="" launcher=mpirun oversubscribe="" force=0 analysis=1
evolve_extra=()
die_usage() { echo "$MODE.sh: error: $*" >&2; echo "try: jobs/scaling/$MODE.sh --help" >&2; exit 2; }
need() { if [ $# -lt 2 ] || [ -z "$2" ]; then die_usage "$1 needs a value"; fi; }

# options
while [ $# -gt 0 ]; do
  case $1 in
    --workers) need "$@"; workers=$2; shift 2 ;;
    --repeats) need "$@"; repeats=$2; shift 2 ;;
    --generations) need "$@"; generations=$2; shift 2 ;;
    --population) need "$@"; population=$2; shift 2 ;;
    --per-worker) need "$@"; per_worker=$2; shift 2 ;;
    --task) need "$@"; task=$2; shift 2 ;;
    --cost-us) need "$@"; cost_us=$2; shift 2 ;;
    --config) need "$@"; config=$2; shift 2 ;;
    --seed) need "$@"; seed=$2; shift 2 ;;
    --name) need "$@"; name=$2; shift 2 ;;
    --out-root) need "$@"; out_root=$2; shift 2 ;;
    --binary) need "$@"; binary=$2; shift 2 ;;
    --mpirun) need "$@"; launcher=$2; shift 2 ;;
    --oversubscribe) oversubscribe=--oversubscribe; shift ;;
    --force) force=1; shift ;;
    --no-analysis) analysis=0; shift ;;
    -h|--help) usage; exit 0 ;;
    --) shift; evolve_extra=("$@"); break ;;
    *) die_usage "unknown option '$1'" ;;
  esac
done

# check the values
is_count() { [[ $1 =~ ^[1-9][0-9]*$ ]]; }
for w in $workers; do is_count "$w" || die_usage "--workers: '$w' is not a positive whole number"; done
[ -n "${workers// /}" ] || die_usage "--workers is empty"
for v in "$repeats" "$generations" "$population" "$per_worker"; do
  is_count "$v" || die_usage "'$v' is not a positive whole number"
done
[[ $cost_us =~ ^[0-9]+$ ]] || die_usage "--cost-us: '$cost_us' is not a whole number"
case $task in
  synthetic) config=${config:-jobs/experiments/synthetic.ini}; task_options=(--task.synthetic_cost_us "$cost_us") ;;
  walk) config=${config:-jobs/experiments/walk.ini}; task_options=() ;;
  *) die_usage "--task must be synthetic or walk, not '$task'" ;;
esac
[ -f "$config" ] || die_usage "--config: no such file '$config'"
name=${name:-$MODE-$task}
sweep=$out_root/$name

# the binary: build the release preset when it is missing
if [ -z "$binary" ]; then
  binary=build/release/src/app/cambrian
  if [ ! -x "$binary" ]; then
    echo "building $binary (cmake --preset release)"
    cmake --preset release > /dev/null
    cmake --build --preset release --target cambrian -j "${CAMBRIAN_JOBS:-2}"
  fi
fi
[ -x "$binary" ] || die_usage "--binary: '$binary' is not an executable"

# a fresh sweep directory
if [ -e "$sweep" ]; then
  [ "$force" = 1 ] || die_usage "$sweep exists (use --force to replace it, or another --name)"
  rm -rf "$sweep"
fi
mkdir -p "$sweep"
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
{
  echo "mode $MODE  task $task  config $config  workers '$workers'  repeats $repeats  generations $generations  evolve options '${evolve_extra[*]}'"
  echo "binary $binary  host $(hostname)  cores $(nproc)  load $(cut -d' ' -f1-3 /proc/loadavg)  date $(date -u +%FT%TZ)"
} | tee "$sweep/sweep.txt"

# one run per worker count and repeat
for w in $workers; do
  if [ "$MODE" = strong ]; then pop=$population; else pop=$((per_worker * w)); fi
  for r in $(seq 1 "$repeats"); do
    out=$sweep/w$w/r$r
    mkdir -p "$out"
    echo "w$w r$r: mpirun -np $((w + 1)) (population $pop)"
    rc=0
    # shellcheck disable=SC2086
    "$launcher" -np $((w + 1)) $oversubscribe "$binary" evolve --config "$config" \
      "${task_options[@]}" --evolution.population "$pop" --evolution.generations "$generations" \
      --seed "$seed" --quiet --out "$out" "${evolve_extra[@]}" > "$out/run.log" 2>&1 || rc=$?
    if [ "$rc" -ne 0 ]; then
      echo "$MODE.sh: run w$w r$r failed with exit code $rc; see $out/run.log" >&2
      tail -5 "$out/run.log" >&2
      exit "$rc"
    fi
    grep -E '^(digest|wall_seconds)' "$out/run.log" | tr '\n' ' '; echo
  done
done

# the analysis of the sweep
if [ "$analysis" = 1 ]; then
  python=/usr/bin/python3
  $python analysis/scaling.py "$sweep" --mode "$MODE" --output "$sweep/scaling.png" \
    --table "$sweep/scaling.tsv" --markdown "$sweep/scaling.md"
  $python analysis/scaling_model.py --sweep "$sweep" --mode "$MODE" --output "$sweep/model.png" --table "$sweep/model.tsv"
fi
echo "sweep in $sweep"
