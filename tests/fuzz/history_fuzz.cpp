// Fuzz target: history files (damaged history.h5), read by HistoryReader as replay and resume
// read them: attributes, measure columns, every individual (genomes decoded) and generation row.
// It reads in this process (no child first: the fuzzer looks for faults in cambrian's own
// reading). A file refused ends in cambrian::Error.
#include "cambrian/error.hpp"

#include "fuzz/fuzz_file.hpp"
#include "store/history.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static cambrian::fuzz::FuzzFile file("history.h5");
  const std::string& path = file.write(data, size);
  try {
    cambrian::HistoryReader reader(path, cambrian::HistoryReadMode::this_process_only);
    reader.measures();
    reader.individuals();
    reader.generations();
  } catch (const cambrian::Error&) {
  }
  return 0;
}
