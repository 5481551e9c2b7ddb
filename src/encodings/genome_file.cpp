// cambrian: genome files of any registered encoding — binary told apart by the encoding tag,
// text by its first word; written as text, atomically.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "core/small_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>

namespace cambrian {

namespace {

// a genome file: text or bytes of at most a few megabytes
constexpr std::size_t kGenomeFileLimit = 64u << 20;

// the first word of a text form, comments (from '#') and blank lines skipped
std::string firstWord(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string word;
    if (words >> word)
      return word;
  }
  return "";
}

}  // namespace

Genotype readGenomeFile(const std::string& path) {
  // whole file into memory, bounded
  SmallFile file = readSmallFile(path, kGenomeFileLimit);
  if (!file.problem.empty())
    throw InputError(path + ": the genome file " + file.problem);
  const std::string& content = file.bytes;

  // binary when it starts with an encoding's tag; errors name the path
  std::array<char, 4> tag{};
  if (content.size() >= tag.size()) {
    std::memcpy(tag.data(), content.data(), tag.size());
    if (const Encoding* encoding = encodingForTag(tag)) {
      try {
        return encoding->fromBytes(reinterpret_cast<const std::uint8_t*>(content.data()),
                                   content.size());
      } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
      }
    }
  }

  // text: the encoding whose text form starts with the first word (else the first encoding's
  // reader, which says what it expected)
  std::string word = firstWord(content);
  for (const Encoding* encoding : encodings()) {
    if (encoding->textHeader() == word)
      return encoding->fromText(content, path);
  }
  return encodings().front()->fromText(content, path);
}

void writeGenomeFile(const std::string& path, const Genotype& genome) {
  // write a temporary file next to the target (same folder, so rename is atomic)
  std::string temporary = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error(ExitCode::output_file,
                  temporary + ": cannot create genome file: " + std::strerror(errno));
    }
    out << genome.encoding().toText(genome);
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
