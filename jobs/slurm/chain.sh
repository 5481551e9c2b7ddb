#!/usr/bin/env bash
# Submits a series of N Slurm jobs of jobs/slurm/evolve.sbatch, each starting after the one
# before it ends (--dependency=afterany), so an evolution longer than one allocation runs as a
# series: every job continues from the checkpoint the previous one left in runs/<job name>/.
#
#   jobs/slurm/chain.sh N [SBATCH OPTIONS] [-- EVOLVE.SBATCH ARGUMENTS]
#   jobs/slurm/chain.sh 4 -J walk1 --time=12:00:00 -- --config jobs/experiments/walk.ini
#
# All jobs get the same job name (-J/--job-name, default: the config file's base name), which
# is what ties them to one output directory. Prints one job id per line. The job that completes
# the evolution cancels the chain's pending jobs (evolve.sbatch; CAMBRIAN_KEEP_CHAIN=1 keeps
# them: each then starts, finds the finished run, runs no generation and exits 0 in seconds).
# Options of this script: --dry-run prints the sbatch commands instead; --after JOBID makes
# the first job wait for an existing job too; -h/--help. N is at most 50. A --fresh among
# the batch script's arguments goes to the first job only.
# Environment: SBATCH (the sbatch command, default sbatch), EVOLVE_SCRIPT (default:
# evolve.sbatch beside this script), and CAMBRIAN_* (passed on to the jobs, see evolve.sbatch).
set -euo pipefail

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }

# arguments: N, options for sbatch, then -- and the batch script's arguments
if [ $# -lt 1 ] || [ "$1" = -h ] || [ "$1" = --help ]; then
  usage; [ $# -ge 1 ] && exit 0 || exit 2
fi
count=$1; shift
if ! [[ $count =~ ^[0-9]+$ ]] || [ "$count" -lt 1 ] || [ "$count" -gt 50 ]; then
  echo "chain.sh: N must be a number from 1 to 50, not '$count'" >&2
  exit 2
fi
sbatch_args=() script_args=() dry_run="" after="" name=""
while [ $# -gt 0 ]; do
  case $1 in
    --) shift; script_args=("$@"); break ;;
    --dry-run) dry_run=1; shift ;;
    --after) after=${2:?--after needs a job id}; shift 2 ;;
    -J|--job-name) name=${2:?$1 needs a name}; shift 2 ;;
    --job-name=*) name=${1#--job-name=}; shift ;;
    -d|--dependency|--dependency=*)
      echo "chain.sh: the chain sets --dependency itself (use --after JOBID)" >&2; exit 2 ;;
    -h|--help) usage; exit 0 ;;
    *) sbatch_args+=("$1"); shift ;;
  esac
done

# the job name: given, or the config file's base name
if [ -z "$name" ]; then
  config=${CAMBRIAN_CONFIG:-jobs/experiments/walk.ini}
  for ((i = 0; i < ${#script_args[@]}; i++)); do
    case ${script_args[i]} in
      --config) config=${script_args[i + 1]:-$config} ;;
      --config=*) config=${script_args[i]#--config=} ;;
      -*) ;;
      *) [ "$i" -eq 0 ] && config=${script_args[i]} ;;
    esac
  done
  name=$(basename "$config" .ini)
fi

sbatch_cmd=${SBATCH:-sbatch}
script=${EVOLVE_SCRIPT:-$(cd "$(dirname "$0")" && pwd)/evolve.sbatch}
[ -f "$script" ] || { echo "chain.sh: batch script '$script' not found" >&2; exit 2; }

# --fresh belongs to the first job only: the later ones continue what it started
later_args=()
for a in "${script_args[@]}"; do [ "$a" = --fresh ] || later_args+=("$a"); done

# submit the jobs, each depending on the one before
previous=$after
for ((k = 1; k <= count; k++)); do
  dep=()
  [ -n "$previous" ] && dep=(--dependency="afterany:$previous")
  args=("${script_args[@]}")
  [ "$k" -eq 1 ] || args=("${later_args[@]}")
  cmd=("$sbatch_cmd" --parsable --job-name="$name" "${dep[@]}" "${sbatch_args[@]}" "$script"
       "${args[@]}")
  if [ -n "$dry_run" ]; then
    echo "${cmd[*]}"
    previous="JOB$k"
    continue
  fi
  id=$("${cmd[@]}")
  id=${id%%;*}
  [[ $id =~ ^[0-9]+$ ]] || { echo "chain.sh: sbatch answered '$id' for job $k" >&2; exit 1; }
  echo "$id"
  previous=$id
done
