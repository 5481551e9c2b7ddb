// cambrian: individuals.tsv and generations.tsv.
#include "run/tables.hpp"

#include "cambrian/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cambrian {

namespace {

// %.17g, the text that reads back to the same double
std::string exact(double value) {
  char number[64];
  std::snprintf(number, sizeof number, "%.17g", value);
  return number;
}

}  // namespace

std::string individualsTsvHeader(const std::vector<MeasureInfo>& measures) {
  std::string header =
      "generation\tid\tparents\toperator\tfitness\tstatus\tparts\teval_seconds\tworker_rank";
  for (const MeasureInfo& measure : measures)
    header += "\t" + measure.name;
  return header + "\n";
}

std::string individualsTsvRow(const Individual& r, const std::vector<MeasureInfo>& measures) {
  // parents joined by commas
  std::string parents;
  for (std::uint64_t p : r.parents)
    parents += (parents.empty() ? "" : ",") + std::to_string(p);
  if (parents.empty())
    parents = "-";
  char number[64];
  std::ostringstream row;
  row << r.generation << '\t' << r.id << '\t' << parents << '\t' << originName(r.origin) << '\t'
      << exact(r.fitness()) << '\t' << statusName(r.outcome.status) << '\t' << r.outcome.parts
      << '\t';
  std::snprintf(number, sizeof number, "%.6f", r.eval_seconds);
  row << number << '\t' << r.worker_rank;
  for (const MeasureInfo& measure : measures) {
    double value = r.outcome.measure(measure.name);
    row << '\t' << (std::isnan(value) ? std::string("nan") : exact(value));
  }
  row << '\n';
  return row.str();
}

std::string generationsTsvHeader() {
  return "generation\tbest\tmean\tmedian\tq25\tq75\tworst\tfailed\tbest_id\tevaluations\tworkers\t"
         "rank0_serial_seconds\trank0_cpu_seconds\trank0_dispatch_seconds\tevaluation_span_"
         "seconds\tworker_busy_seconds\t"
         "worker_idle_seconds\twall_seconds\tepoch\tfitness_deviation\tmutation_multiplier\n";
}

std::string generationsTsvRow(const GenerationRecord& r) {
  char line[1024];
  const FitnessStats& s = r.stats;
  std::snprintf(
      line, sizeof line,
      "%llu\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%zu\t%llu\t%llu\t%d\t%.6f\t%.6f\t%.6f\t"
      "%.6f\t%.6f\t%.6f\t%.6f\t%llu\t%.17g\t%.17g\n",
      static_cast<unsigned long long>(r.generation), s.best, s.mean, s.median, s.q25, s.q75,
      s.worst, s.failed, static_cast<unsigned long long>(s.best_id),
      static_cast<unsigned long long>(r.evaluations), r.workers, r.rank0_serial_seconds,
      r.rank0_cpu_seconds, r.rank0_dispatch_seconds, r.evaluation_span_seconds,
      r.worker_busy_seconds, r.worker_idle_seconds, r.wall_seconds,
      static_cast<unsigned long long>(r.epoch), r.fitness_deviation, r.mutation_multiplier);
  return line;
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
  // temporary file next to the target, then rename over it
  std::string temporary = path + ".tmp";
  auto fail = [&](const std::string& what) {
    std::string reason = std::strerror(errno);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(ExitCode::output_file, path + ": " + what + ": " + reason);
  };
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      fail("cannot open " + temporary + " for writing");
    out << text;
    out.close();
    if (!out)
      fail("cannot write " + temporary);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    fail("cannot rename " + temporary + " into place");
}

}  // namespace cambrian
