// cambrian: a steady-state run's recorded order of results — read from its history so that a
// later run (run.arrival_order) repeats it bit for bit at any rank count.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace cambrian {

struct HistoryAttributes;

/// What a steady-state history records: the ids in the order their results were taken in (its
/// rows), and how many results were in when each was bred.
struct ArrivalRecord {
  std::string path;                                             ///< the history it was read from
  std::vector<std::uint64_t> order;                             ///< ids, in the order taken in
  std::unordered_map<std::uint64_t, std::uint64_t> bred_after;  ///< id -> bred_after

  /// The id taken in as the `taken`-th result (from 0); false past the record.
  bool idAt(std::uint64_t taken, std::uint64_t& id) const {
    if (taken >= order.size())
      return false;
    id = order[taken];
    return true;
  }
  /// When the individual `id` was bred; false when the record does not hold it.
  bool bredAfter(std::uint64_t id, std::uint64_t& after) const {
    auto it = bred_after.find(id);
    if (it == bred_after.end())
      return false;
    after = it->second;
    return true;
  }
};

/// Reads the record of `path` (a history.h5). It must be of a run with the same settings hash and
/// seed as `this_run`, and of evolution.mode = steady_state: else Error(config) naming the file
/// and what differs. An unreadable file is Error(input_file) naming it.
ArrivalRecord readArrivalRecord(const std::string& path, const HistoryAttributes& this_run);

}  // namespace cambrian
