// cambrian: genome files on disk: text or binary when reading, text (atomically) when writing.
#include "cambrian/error.hpp"
#include "cambrian/genome.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace cambrian {

Genome readGenomeFile(const std::string& path) {
  // whole file into memory
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open genome file");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    throw InputError(path + ": cannot read genome file");

  // binary when it starts with the magic, text otherwise; errors name the path
  if (content.size() >= 4 && content.compare(0, 4, "CMBG") == 0) {
    try {
      return deserializeGenome(reinterpret_cast<const std::uint8_t*>(content.data()),
                               content.size());
    } catch (const InputError& e) {
      throw InputError(path + ": " + e.what());
    }
  }
  return parseGenomeText(content, path);
}

void writeGenomeFile(const std::string& path, const Genome& genome) {
  // write a temporary file next to the target (same folder, so rename is atomic)
  std::string temporary = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error(ExitCode::output_file,
                  temporary + ": cannot create genome file: " + std::strerror(errno));
    }
    out << genomeToText(genome);
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw Error(ExitCode::output_file, temporary + ": cannot write genome file");
    }
  }

  // then replace the target in one step
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    int error = errno;
    std::remove(temporary.c_str());
    throw Error(ExitCode::output_file,
                path + ": cannot replace genome file: " + std::strerror(error));
  }
}

}  // namespace cambrian
