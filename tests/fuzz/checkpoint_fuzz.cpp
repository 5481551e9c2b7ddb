// Fuzz target: checkpoint files (damaged checkpoint.h5), read by readCheckpoint as a resumed run
// reads them, in this process (readCheckpointHere: the fuzzer looks for faults in cambrian's own
// reading). A file refused ends in cambrian::Error (the checkpoint exit code).
#include "cambrian/error.hpp"

#include "fuzz/fuzz_file.hpp"
#include "store/checkpoint.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static cambrian::fuzz::FuzzFile file("checkpoint.h5");
  const std::string& path = file.write(data, size);
  try {
    cambrian::readCheckpointHere(path);
  } catch (const cambrian::Error&) {
  }
  return 0;
}
