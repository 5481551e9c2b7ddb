// cambrian: little-endian byte writing and checked reading.
#include "core/bytes.hpp"

#include "cambrian/error.hpp"

#include <bit>

namespace cambrian {

void ByteWriter::vec3(const Vec3& v) {
  f64(v.x);
  f64(v.y);
  f64(v.z);
}

void ByteWriter::raw(const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  out_.insert(out_.end(), p, p + size);
}

void ByteWriter::blob(const void* data, std::size_t size) {
  u64(size);
  raw(data, size);
}

ByteReader::ByteReader(const std::uint8_t* bytes, std::size_t size, std::string what)
    : bytes_(bytes), size_(size), what_(std::move(what)) {
  if (bytes == nullptr && size > 0)
    throw InputError(what_ + ": null buffer");
}

void ByteReader::fail(const std::string& message) const {
  throw InputError(what_ + ": " + message + " (offset " + std::to_string(offset_) + " of " +
                   std::to_string(size_) + ")");
}

void ByteReader::need(std::uint64_t bytes) {
  if (bytes > remaining())
    fail("truncated in " + context_);
}

std::uint64_t ByteReader::unsignedLe(int bytes) {
  need(static_cast<std::uint64_t>(bytes));
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i)
    v |= static_cast<std::uint64_t>(bytes_[offset_ + i]) << (8 * i);
  offset_ += static_cast<std::size_t>(bytes);
  return v;
}

double ByteReader::f64() {
  return std::bit_cast<double>(unsignedLe(8));
}

Vec3 ByteReader::vec3() {
  Vec3 v;
  v.x = f64();
  v.y = f64();
  v.z = f64();
  return v;
}

bool ByteReader::flag(const char* field) {
  return upTo(field, 1) == 1;
}

std::uint8_t ByteReader::upTo(const char* field, std::uint8_t max) {
  std::uint8_t v = u8();
  if (v > max) {
    --offset_;
    fail(context_ + " " + field + " is " + std::to_string(v) + ", expected " +
         (max == 1 ? std::string("0 or 1") : "0 to " + std::to_string(max)));
  }
  return v;
}

std::size_t ByteReader::count(std::size_t element_bytes) {
  std::uint32_t n = u32();
  if (static_cast<std::uint64_t>(n) * element_bytes > remaining()) {
    throw InputError(what_ + ": truncated in " + context_ + " (offset " +
                     std::to_string(offset_ - 4) + " of " + std::to_string(size_) + ": count " +
                     std::to_string(n) + " needs at least " +
                     std::to_string(static_cast<std::uint64_t>(n) * element_bytes) +
                     " more bytes, " + std::to_string(remaining()) + " left)");
  }
  return n;
}

std::vector<std::uint8_t> ByteReader::blob() {
  std::uint64_t size = u64();
  need(size);
  std::vector<std::uint8_t> out(bytes_ + offset_, bytes_ + offset_ + size);
  offset_ += static_cast<std::size_t>(size);
  return out;
}

std::string ByteReader::text() {
  std::vector<std::uint8_t> raw = blob();
  return std::string(raw.begin(), raw.end());
}

void ByteReader::expectEnd() const {
  if (offset_ == size_)
    return;
  fail(std::to_string(size_ - offset_) + " unexpected bytes after the end");
}

}  // namespace cambrian
