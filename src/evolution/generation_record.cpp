#include "evolution/run_record.hpp"

#include "cambrian/error.hpp"
#include "cambrian/genome.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace cambrian {

IndividualRecord makeIndividualRecord(const Individual& individual) {
  IndividualRecord record;
  record.generation = individual.generation;
  record.id = individual.id;
  record.parents = individual.parents;
  record.origin = individual.origin;
  record.fitness = individual.fitness();
  record.status = individual.outcome.status;
  record.parts = individual.outcome.parts;
  record.eval_seconds = individual.eval_seconds;
  record.worker_rank = individual.worker_rank;
  return record;
}

double GenerationRecord::evaluationsPerSecond() const {
  if (evaluation_span_seconds <= 0)
    return 0;
  return static_cast<double>(evaluations) / evaluation_span_seconds;
}

double GenerationRecord::utilisation() const {
  double available = workers * evaluation_span_seconds;
  if (available <= 0)
    return 0;
  return worker_busy_seconds / available;
}

void RunDigest::bytes(const void* data, std::size_t size) {
  // FNV-1a, byte by byte
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash_ ^= p[i];
    hash_ *= 0x100000001b3ULL;
  }
}

void RunDigest::add(const Individual& individual) {
  // id and fitness as little-endian 64-bit words, then the genome bytes
  unsigned char word[8];
  auto put = [&](std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
      word[i] = static_cast<unsigned char>(v >> (8 * i));
    bytes(word, 8);
  };
  put(individual.id);
  const std::vector<std::uint8_t>& genome = individual.genomeBytes();
  put(genome.size());
  bytes(genome.data(), genome.size());
  double fitness = individual.fitness();
  std::uint64_t bits;
  std::memcpy(&bits, &fitness, sizeof bits);
  put(bits);
}

void RunDigest::add(const Population& population) {
  for (const Individual& individual : population.individuals)
    add(individual);
}

std::string RunDigest::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

std::string individualsTsvHeader() {
  return "generation\tid\tparents\toperator\tfitness\tstatus\tparts\teval_seconds\tworker_rank\n";
}

std::string individualsTsvRow(const IndividualRecord& r) {
  // parents joined by commas
  std::string parents;
  for (std::uint64_t p : r.parents)
    parents += (parents.empty() ? "" : ",") + std::to_string(p);
  if (parents.empty())
    parents = "-";
  char number[64];
  std::ostringstream row;
  row << r.generation << '\t' << r.id << '\t' << parents << '\t' << originName(r.origin) << '\t';
  std::snprintf(number, sizeof number, "%.17g", r.fitness);
  row << number << '\t' << statusName(r.status) << '\t' << r.parts << '\t';
  std::snprintf(number, sizeof number, "%.6f", r.eval_seconds);
  row << number << '\t' << r.worker_rank << '\n';
  return row.str();
}

std::string generationsTsvHeader() {
  return "generation\tbest\tmean\tmedian\tq25\tq75\tworst\tfailed\tbest_id\tevaluations\tworkers\t"
         "rank0_serial_seconds\trank0_cpu_seconds\trank0_dispatch_seconds\tevaluation_span_"
         "seconds\tworker_busy_seconds\t"
         "worker_idle_seconds\twall_seconds\n";
}

std::string generationsTsvRow(const GenerationRecord& r) {
  char line[1024];
  const FitnessStats& s = r.stats;
  std::snprintf(
      line, sizeof line,
      "%llu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%llu\t%zu\t%d\t%.6f\t%.6f\t%.6f\t"
      "%.6f\t%.6f\t%.6f\t%.6f\n",
      static_cast<unsigned long long>(r.generation), s.best, s.mean, s.median, s.q25, s.q75,
      s.worst, s.failed, static_cast<unsigned long long>(s.best_id), r.evaluations, r.workers,
      r.rank0_serial_seconds, r.rank0_cpu_seconds, r.rank0_dispatch_seconds,
      r.evaluation_span_seconds, r.worker_busy_seconds, r.worker_idle_seconds, r.wall_seconds);
  return line;
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
  // temporary file next to the target, then rename over it
  std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw Error(ExitCode::output_file, path + ": cannot open for writing");
    out << text;
    out.flush();
    if (!out)
      throw Error(ExitCode::output_file, path + ": write failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    throw Error(ExitCode::output_file, path + ": cannot rename " + temporary + " into place");
  }
}

}  // namespace cambrian
