#!/usr/bin/env bash
# Rank 0's instructions per creature, by part: callgrind on rank 0 of a synthetic run (300
# directed-graph genomes of about 5 KB, 100 us creatures asleep, 3 ranks), counted per evaluation
# for breeding, the byte form, the history append, the run digest and the whole process (start-up
# included). Instructions, not seconds: the same on a busy host, so two builds compare exactly.
# Needs valgrind (Debian package valgrind; not installed by jobs/setup/install-deps.sh).
# Figures and their reading: docs/performance.md ("Rank 0's instructions per creature").
# usage: jobs/bench/rank0_instructions.sh [path/to/cambrian] [generations (20)]
#          [genome: graph|springy]
set -euo pipefail
cd "$(dirname "$0")/../.."
cambrian=$(realpath "${1:-build/release/src/app/cambrian}")
generations=${2:-20}
genome=${3:-graph}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
extra=()
[ "$genome" = springy ] && extra=(--genome.encoding springy
  --springy.organism jobs/creatures/springy/snake.organism --evolution.graft_fraction 0
  --evolution.crossover_fraction 0.5 --evolution.mutation_fraction 0.5)

# rank 0 under callgrind, the workers as they are
cat > "$work/rank0.sh" << EOF
#!/usr/bin/env bash
if [ "\$OMPI_COMM_WORLD_RANK" = 0 ]; then
  exec valgrind --tool=callgrind --callgrind-out-file="$work/rank0.out" "\$@" 2> /dev/null
fi
exec "\$@"
EOF
chmod +x "$work/rank0.sh"
mpirun -np 3 --oversubscribe "$work/rank0.sh" "$cambrian" evolve \
  --config jobs/experiments/synthetic.ini --task.synthetic_distribution fixed \
  --task.synthetic_cost_us 100 --task.synthetic_work sleep --evolution.generations "$generations" \
  --quiet --out "$work/run" ${extra[@]+"${extra[@]}"} > "$work/run.txt"
evaluations=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  { e += $col["evaluations"] } END { print e }' "$work/run/generations.tsv")
echo "$(grep '^digest' "$work/run.txt"), $evaluations evaluations, $generations generations"

# inclusive instructions of a function (its first line in callgrind_annotate's inclusive list)
callgrind_annotate --inclusive=yes "$work/rank0.out" > "$work/inclusive.txt" 2> /dev/null
total=$(grep -m1 'PROGRAM TOTALS' "$work/inclusive.txt" | awk '{ gsub(",", "", $1); print $1 }')
inclusive() {
  grep -m1 -F "$1" "$work/inclusive.txt" | awk '{ gsub(",", "", $1); print $1 }'
}
printf "%-34s %16s %18s\n" part instructions "per evaluation"
row() { awk -v n="$2" -v e="$evaluations" -v p="$1" 'BEGIN {
  printf "%-34s %16.0f %18.0f\n", p, n, n / e }'; }
row "rank 0, all (start-up included)" "$total"
row "breeding (Genotype::make)" "$(inclusive 'cambrian::Genotype::make() const [')"
row "byte form (Encoding::toBytes)" \
  "$(inclusive 'Encoding::toBytes(cambrian::GenomeData const&) const [')"
row "history append" \
  "$(inclusive 'cambrian::HistoryWriter::appendGeneration(std::vector<cambrian::Individual')"
row "run digest (RunDigest::add)" \
  "$(inclusive 'cambrian::RunDigest::add(cambrian::Population const&) [')"
