// test helper: where to cut a text file to make truncated copies of it
#pragma once

#include <cstddef>
#include <set>
#include <string>

namespace cambrian::test {

/// Every line boundary and every 37th byte of `whole`, short of the whole file and of the whole
/// file but its final newline: each cut loses at least the last character of the last line.
inline std::set<std::size_t> truncationPoints(const std::string& whole) {
  std::set<std::size_t> cuts;
  for (std::size_t at = 0; at + 1 < whole.size(); at += 37)
    cuts.insert(at);
  for (std::size_t at = 0; at + 1 < whole.size(); ++at) {
    if (whole[at] == '\n')
      cuts.insert(at + 1);
  }
  cuts.erase(whole.size());
  cuts.erase(whole.size() - 1);
  return cuts;
}

}  // namespace cambrian::test
