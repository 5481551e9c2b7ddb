// cambrian: a springy organism's two written forms — the text a person reads and writes by hand
// (docs/springy.md gives its grammar) and the byte form the runs carry.
#pragma once

#include "encodings/springy/organism.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cambrian::springy {

/// The first four bytes of the byte form.
constexpr std::array<char, 4> kOrganismTag = {'C', 'M', 'B', 'S'};
/// The byte form's version.
constexpr std::uint32_t kOrganismBytesVersion = 1;
/// The text form's first word and version.
constexpr const char* kOrganismTextHeader = "cambrian-springy";
constexpr int kOrganismTextVersion = 1;

/// The text form: exact (parseOrganismText(organismToText(o)) == o).
std::string organismToText(const Organism& organism);
/// Reads the text form; throws InputError naming `source`, the line and the field. A muscle
/// written without its parameters rests at its initial length and does not move.
Organism parseOrganismText(const std::string& text, const std::string& source);

/// The byte form: tag, version, then the fields little-endian.
std::vector<std::uint8_t> organismToBytes(const Organism& organism);
/// Reads the byte form; throws InputError naming the field on bad or truncated bytes.
Organism organismFromBytes(const std::uint8_t* bytes, std::size_t size);

/// Whether `name` can name a node or tube in the text form: not empty, no space, '#' or control
/// character (bytes of UTF-8 letters are fine).
bool isWritableName(const std::string& name);

}  // namespace cambrian::springy
