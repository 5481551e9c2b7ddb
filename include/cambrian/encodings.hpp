// cambrian: the registered encodings (src/encodings/registry.cpp) and genome files and bytes of
// any of them.
#pragma once

#include "cambrian/encoding.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

/// Every registered encoding (their prototypes, default settings), in registration order.
const std::vector<const Encoding*>& encodings();
/// The encoding named `name`; throws ConfigError naming genome.encoding and the choices.
const Encoding& findEncoding(const std::string& name);
/// The encoding whose byte form starts with `tag`, or null.
const Encoding* encodingForTag(const std::array<char, 4>& tag);
/// The names of every registered encoding ("directed_graph").
std::vector<std::string> encodingNames();

/// Decodes the byte form of any registered encoding (found by its tag); the bytes are kept as
/// they are. Throws InputError naming the problem for bytes no encoding reads.
Genotype decodeGenome(const std::uint8_t* bytes, std::size_t size);
inline Genotype decodeGenome(const std::vector<std::uint8_t>& bytes) {
  return decodeGenome(bytes.data(), bytes.size());
}

/// Reads a genome file of any encoding, text or binary (told apart by the tag); errors name the
/// file.
Genotype readGenomeFile(const std::string& path);
/// Writes the text form of `genome` atomically (temporary file, rename); Error(output_file)
/// naming the path when it cannot.
void writeGenomeFile(const std::string& path, const Genotype& genome);

}  // namespace cambrian
