// cambrian: the one hash function of the project — FNV-1a 64-bit, for run digests, settings
// hashes and checkpoint state hashes. Byte by byte, so equal on every machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace cambrian {

/// FNV-1a 64-bit over bytes fed in order.
class Fnv1a {
 public:
  /// The offset basis (a hash over nothing).
  static constexpr std::uint64_t kBasis = 0xcbf29ce484222325ULL;
  /// A hash over nothing yet.
  Fnv1a() = default;
  /// A hash that continues from `value` (a value() saved earlier).
  explicit Fnv1a(std::uint64_t value) : hash_(value) {}
  /// Feeds `size` bytes.
  void add(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= p[i];
      hash_ *= 0x100000001b3ULL;
    }
  }
  /// Feeds a 64-bit word as 8 little-endian bytes.
  void addWord(std::uint64_t v) {
    unsigned char word[8];
    for (int i = 0; i < 8; ++i)
      word[i] = static_cast<unsigned char>(v >> (8 * i));
    add(word, 8);
  }
  /// The hash so far.
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = kBasis;
};

/// 16 lower-case hex digits of a 64-bit value.
std::string hex16(std::uint64_t value);

/// The FNV-1a hash of `text` as 16 lower-case hex digits.
std::string hashText(const std::string& text);

}  // namespace cambrian
