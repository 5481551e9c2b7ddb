// cambrian: hex forms of FNV-1a hashes.
#include "core/hash.hpp"

#include <cstdio>

namespace cambrian {

std::string hex16(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string hashText(const std::string& text) {
  Fnv1a hash;
  hash.add(text.data(), text.size());
  return hex16(hash.value());
}

}  // namespace cambrian
