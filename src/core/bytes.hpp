// cambrian: the little-endian byte writer and reader every byte form uses (genomes, messages,
// outcomes). Reading past the end or leaving bytes unread throws InputError naming what was being
// read and where.
#pragma once

#include "cambrian/math.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

/// Appends little-endian values to a byte vector.
class ByteWriter {
 public:
  /// Appends to `out` (kept by reference).
  explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void u8(std::uint8_t v) { out_.push_back(v); }
  void u16(std::uint16_t v) { unsignedLe<2>(v); }
  void u32(std::uint32_t v) { unsignedLe<4>(v); }
  void u64(std::uint64_t v) { unsignedLe<8>(v); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  /// A double as its IEEE 754 bits.
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void vec3(const Vec3& v);
  /// Raw bytes, no length.
  void raw(const void* data, std::size_t size);
  /// A u64 length, then the bytes.
  void blob(const void* data, std::size_t size);
  /// A u64 length, then the characters.
  void text(const std::string& s) { blob(s.data(), s.size()); }

 private:
  // little-endian whatever the host, a byte at a time: inline, each append a compare and a store
  // (a range insert is a call and a copy: a genome is thousands of these)
  template <int Bytes>
  void unsignedLe(std::uint64_t v) {
    for (int i = 0; i < Bytes; ++i)
      out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::vector<std::uint8_t>& out_;
};

/// Reads what ByteWriter wrote, with bounds checks. Errors read "WHAT: truncated in CONTEXT
/// (offset N of M)".
class ByteReader {
 public:
  /// Reads `size` bytes at `bytes`; `what` names the form in messages ("genome bytes").
  ByteReader(const std::uint8_t* bytes, std::size_t size, std::string what);
  /// Names what is read next, for messages ("node 2 neurons").
  void context(std::string what) { context_ = std::move(what); }
  std::size_t remaining() const { return size_ - offset_; }
  std::size_t offset() const { return offset_; }
  std::size_t size() const { return size_; }
  /// The form's name given at construction.
  const std::string& what() const { return what_; }

  std::uint8_t u8() { return static_cast<std::uint8_t>(unsignedLe(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(unsignedLe(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsignedLe(4)); }
  std::uint64_t u64() { return unsignedLe(8); }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64();
  Vec3 vec3();
  /// A byte that must be 0 or 1, named `field` in the message otherwise.
  bool flag(const char* field);
  /// A byte in 0..max; throws InputError naming `field` and its value otherwise.
  std::uint8_t upTo(const char* field, std::uint8_t max);
  /// A u32 count of elements of at least `element_bytes` each that must fit in what is left.
  std::size_t count(std::size_t element_bytes);
  /// A u64 length and that many bytes.
  std::vector<std::uint8_t> blob();
  /// A u64 length and that many characters.
  std::string text();
  /// Throws unless every byte has been read.
  void expectEnd() const;
  /// Throws InputError "WHAT: MESSAGE (offset N of M)".
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::uint64_t unsignedLe(int bytes);
  void need(std::uint64_t bytes);
  const std::uint8_t* bytes_;
  std::size_t size_;
  std::size_t offset_ = 0;
  std::string what_;
  std::string context_ = "header";
};

}  // namespace cambrian
