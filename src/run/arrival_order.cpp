// cambrian: reading a steady-state run's order of results from its history.
#include "run/arrival_order.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "store/history.hpp"

namespace cambrian {

ArrivalRecord readArrivalRecord(const std::string& path, const HistoryAttributes& this_run) {
  const std::string where = "run.arrival_order = " + path;
  ArrivalRecord record;
  record.path = path;
  std::vector<Individual> rows;
  try {
    HistoryReader reader(path);
    const HistoryAttributes& recorded = reader.attributes();
    // a record of this run's settings only (the run-only ones aside)
    if (iniValues(recorded.config_text)["evolution.mode"] != "steady_state")
      throw Error(ExitCode::config,
                  where + ": not a steady-state run (its evolution.mode is not steady_state)");
    if (recorded.seed != this_run.seed || recorded.config_hash != this_run.config_hash)
      throw Error(ExitCode::config,
                  where + ": recorded by a run of other settings (seed " +
                      std::to_string(recorded.seed) + ", settings hash " + recorded.config_hash +
                      "; this run: seed " + std::to_string(this_run.seed) + ", settings hash " +
                      this_run.config_hash + "): only the same settings repeat its order");
    rows = reader.individuals();
  } catch (const InputError& e) {
    throw Error(ExitCode::input_file, where + ": " + e.what());
  }
  record.order.reserve(rows.size());
  for (const Individual& row : rows) {
    record.order.push_back(row.id);
    record.bred_after.emplace(row.id, row.bred_after);
  }
  return record;
}

}  // namespace cambrian
