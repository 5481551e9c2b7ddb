#!/usr/bin/env bash
# Runs every command the README shows, so none of them can rot.
# usage: readme_check.sh SOURCE_DIR CAMBRIAN WORKDIR
#   Commands run in WORKDIR (jobs/ and analysis/ linked from the source tree), with the
#   README's binary path replaced by CAMBRIAN and evolutions shrunk to a few tiny generations.
#   `bash jobs/test.sh` is what CI runs; `bash jobs/demo.sh` runs here with the built binary;
#   the chain line runs with --dry-run (its sbatch commands counted); the sbatch line is run by
#   the jobs tests (tests/jobs) against a one-node Slurm, and is checked here to name a script
#   that exists and parses.
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
      # with its progress lines (an ETA each) and the closing list of what it wrote
      read -r -a demo_args <<< "${shrink% --quiet}"
      CAMBRIAN=$cambrian DEMO_OUT=$work/runs/demo bash jobs/demo.sh "${demo_args[@]}" \
        > "$work/demo.out" 2>&1 || { cat "$work/demo.out"; echo "README demo failed" >&2; exit 1; }
      for expected in "gen 2/2 .* eta 0:00:00" "fitness plot:  $work/runs/demo/fitness.png" \
                      "best creature: $work/runs/demo/best.gif"; do
        grep -q -- "$expected" "$work/demo.out" || {
          cat "$work/demo.out"; echo "README demo: no line matching '$expected'" >&2; exit 1; }
      done
      ran=$((ran + 1))
      continue ;;
    "bash jobs/slurm/chain.sh "*)
      # the chain as written, dry: one sbatch line per job, each after the one before
      read -r -a words <<< "$command"
      jobs_in_chain=${words[2]}
      bash "${words[1]}" "$jobs_in_chain" --dry-run "${words[@]:3}" > "$work/chain.out"
      submitted=$(grep -c 'evolve.sbatch' "$work/chain.out" || true)
      chained=$(grep -c 'dependency=afterany' "$work/chain.out" || true)
      if [ "$submitted" -ne "$jobs_in_chain" ] || [ "$chained" -ne $((jobs_in_chain - 1)) ]; then
        cat "$work/chain.out"
        echo "README chain: $submitted jobs, $chained chained, from: $command" >&2
        exit 1
      fi
      ran=$((ran + 1))
      continue ;;
    sbatch*)
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
