#!/usr/bin/env bash
# Runs every command the README shows, so none of them can rot.
# usage: readme_check.sh SOURCE_DIR CAMBRIAN WORKDIR
#   Commands run in WORKDIR (jobs/ and analysis/ linked from the source tree), with the
#   README's binary path replaced by CAMBRIAN and evolutions shrunk to a few tiny generations.
#   `bash jobs/test.sh` is what CI runs; `bash jobs/demo.sh` runs here with the built binary;
#   the Slurm lines are run by the jobs tests (tests/jobs) against a one-node Slurm, and are
#   checked here to name scripts that exist and parse.
set -euo pipefail
source_dir=$1 cambrian=$2 work=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 MPLBACKEND=Agg
rm -rf "$work" && mkdir -p "$work"
ln -s "$source_dir/jobs" "$work/jobs"
ln -s "$source_dir/analysis" "$work/analysis"
cd "$work"
shrink="--evolution.population 6 --evolution.generations 2 --task.evaluation_time 0.5 --quiet"

# the README's code lines (indented by four spaces)
mapfile -t commands < <(grep -E '^    [^ ]' "$source_dir/README.md" | sed 's/^    //')
[ "${#commands[@]}" -ge 10 ] || { echo "README: only ${#commands[@]} command lines found" >&2; exit 1; }
ran=0
for command in "${commands[@]}"; do
  case $command in
    "bash jobs/test.sh")
      grep -q "jobs/test.sh" "$source_dir/.ci/run" || { echo ".ci/run does not run jobs/test.sh" >&2; exit 1; }
      continue ;;
    "bash jobs/demo.sh")
      command="CAMBRIAN=$cambrian DEMO_OUT=$work/runs/demo bash jobs/demo.sh $shrink" ;;
    sbatch*|"bash jobs/slurm/"*)
      for script in $(grep -oE 'jobs/slurm/[a-z_.]+' <<< "$command"); do
        bash -n "$source_dir/$script"
      done
      continue ;;
  esac
  # the built binary, room for more ranks than cores, tiny evolutions
  command=${command//build\/release\/src\/app\/cambrian/$cambrian}
  command=${command//mpirun -np/mpirun --oversubscribe -np}
  if grep -q " evolve " <<< "$command"; then
    command="$command $shrink"
  fi
  echo "+ $command"
  bash -c "$command" > "$work/last.out" 2>&1 || {
    cat "$work/last.out"
    echo "README command failed: $command" >&2
    exit 1
  }
  ran=$((ran + 1))
done
echo "ran $ran README commands"
[ -s runs/walk/best.gif ] && [ -s runs/demo/best.gif ] && [ -s runs/walk/fitness.png ]
