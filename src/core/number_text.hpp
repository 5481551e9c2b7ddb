// cambrian: shortest exact decimal text for doubles, used by the text form and by messages.
#pragma once

#include <charconv>
#include <string>

namespace cambrian {

/// The shortest decimal text that reads back to exactly `value` (std::to_chars).
inline std::string formatNumber(double value) {
  // 32 characters hold any shortest double representation
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace cambrian
