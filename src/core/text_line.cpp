// cambrian: one statement of a line-oriented text form.
#include "core/text_line.hpp"

#include "cambrian/error.hpp"

#include <charconv>

namespace cambrian {

std::vector<std::string_view> tokenizeLine(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    char c = line[i];
    if (c == '#')
      break;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
      ++i;
      continue;
    }
    std::size_t start = i;
    while (i < line.size() && line[i] != '#' && line[i] != ' ' && line[i] != '\t' &&
           line[i] != '\r' && line[i] != '\v' && line[i] != '\f') {
      ++i;
    }
    tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

void TextLine::fail(const std::string& what) const {
  std::string prefix = source_ + ":" + std::to_string(number_) + ": ";
  if (!where_.empty())
    prefix += where_ + ": ";
  throw InputError(prefix + what);
}

std::string_view TextLine::next(const std::string& field, const char* kind) {
  if (!more())
    fail("expected " + std::string(kind) + " for '" + field + "', got end of line");
  return tokens_[pos_++];
}

double TextLine::number(const std::string& field) {
  std::string_view token = next(field, "a number");
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+')
    digits.remove_prefix(1);
  double value = 0;
  auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    fail("expected a number for '" + field + "', got '" + std::string(token) + "'");
  }
  return value;
}

Vec3 TextLine::vec3(const std::string& field) {
  Vec3 v;
  for (int k = 0; k < 3; ++k)
    v[k] = number(field);
  return v;
}

long long TextLine::integer(const std::string& field, long long lo, long long hi) {
  std::string_view token = next(field, "an integer");
  long long value = 0;
  auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec != std::errc() || result.ptr != token.data() + token.size() || value < lo ||
      value > hi) {
    fail("expected an integer " + std::to_string(lo) + ".." + std::to_string(hi) + " for '" +
         field + "', got '" + std::string(token) + "'");
  }
  return value;
}

int TextLine::enumeration(const std::string& field, const char* const* names, int count) {
  std::string_view token = next(field, "a name");
  for (int i = 0; i < count; ++i) {
    if (token == names[i])
      return i;
  }
  long long value = 0;
  auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec == std::errc() && result.ptr == token.data() + token.size() && value >= 0 &&
      value <= 255) {
    return static_cast<int>(value);
  }
  std::string known;
  for (int i = 0; i < count; ++i)
    known += (i ? ", " : "") + std::string(names[i]);
  fail("unknown value '" + std::string(token) + "' for '" + field + "' (one of: " + known + ")");
}

void TextLine::expect(std::string_view word, const std::string& field) {
  std::string_view token = next(field, ("'" + std::string(word) + "'").c_str());
  if (token != word) {
    fail("expected '" + std::string(word) + "' in '" + field + "', got '" + std::string(token) +
         "'");
  }
}

void readStatements(const std::string& text, const std::string& source, const char* header,
                    int newest, const std::string& statements, const StatementReader& statement) {
  const std::string expected_header = std::string(header) + " " + std::to_string(newest);
  bool have_header = false, have_end = false;
  std::size_t start = 0;
  int number = 0;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string::npos)
      stop = text.size();
    const std::string_view raw(text.data() + start, stop - start);
    start = stop + 1;
    ++number;
    TextLine line(source, number, tokenizeLine(raw));
    if (!line.more())
      continue;
    const std::string keyword(line.next("statement", "a keyword"));
    if (!have_header) {
      if (keyword != header)
        line.fail("expected the header '" + expected_header + "', got '" + keyword + "'");
      const long long version = line.integer(header, 0, 1LL << 32);
      if (version > newest)
        line.fail("format version " + std::to_string(version) + " is newer than this cambrian (" +
                  std::to_string(newest) + ")");
      if (version < 1)
        line.fail("format version " + std::to_string(version) + " does not exist");
      have_header = true;
    } else if (have_end) {
      line.fail("unexpected '" + keyword + "' after `end`");
    } else if (keyword == "end") {
      have_end = true;
    } else if (!statement(keyword, line)) {
      line.fail("unknown statement '" + keyword + "' (one of: " + statements + ")");
    }
    if (line.more())
      line.fail("unexpected '" + std::string(line.peek()) + "' at the end of the line");
  }
  if (!have_header)
    throw InputError(source + ": empty (expected the header '" + expected_header + "')");
  if (!have_end)
    throw InputError(source + ": no `end` line: the file is cut short");
}

}  // namespace cambrian
