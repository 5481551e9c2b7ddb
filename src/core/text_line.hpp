// cambrian: one statement of a line-oriented text form (genomes, organisms), split into tokens,
// with strict number parsing and messages that name the source, the line and the field.
#pragma once

#include "cambrian/math.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace cambrian {

/// Whitespace-separated tokens of one line, stopping at '#'.
std::vector<std::string_view> tokenizeLine(std::string_view line);

/// The statement being parsed: one line's tokens, read in order, and its place for messages.
/// Every failure throws InputError "SOURCE:LINE: [WHERE: ]WHAT".
class TextLine {
 public:
  TextLine(const std::string& source, int number, std::vector<std::string_view> tokens)
      : source_(source), number_(number), tokens_(std::move(tokens)) {}

  /// Names the item being read ("node 2"), put before each message.
  void context(std::string where) { where_ = std::move(where); }
  bool more() const { return pos_ < tokens_.size(); }
  std::string_view peek() const { return tokens_[pos_]; }
  int number() const { return number_; }

  [[noreturn]] void fail(const std::string& what) const;
  /// The next token, which `field` needs (`kind` says what it should be).
  std::string_view next(const std::string& field, const char* kind);
  /// A finite or infinite decimal number (a leading '+' allowed).
  double number(const std::string& field);
  /// Three numbers.
  Vec3 vec3(const std::string& field);
  /// An integer in lo..hi.
  long long integer(const std::string& field, long long lo, long long hi);
  /// An enumeration by name (or by its number, 0..255), listing the names on error.
  int enumeration(const std::string& field, const char* const* names, int count);
  /// The word `word`.
  void expect(std::string_view word, const std::string& field);

 private:
  const std::string& source_;
  int number_;
  std::vector<std::string_view> tokens_;
  std::size_t pos_ = 0;
  std::string where_;
};

/// Reads a text form of statements: the header "HEADER VERSION" (version 1..`newest`), then one
/// statement a line, each handed to `statement` with its keyword read, until `end`. Blank and
/// comment lines are skipped; a token left on a line, a statement after `end`, a missing header
/// or a missing `end` (a file cut short) throw InputError naming `source` and the line.
/// `statements` lists the keywords for the unknown-statement message ("dna, end").
using StatementReader = std::function<bool(const std::string& keyword, TextLine& line)>;
void readStatements(const std::string& text, const std::string& source, const char* header,
                    int newest, const std::string& statements, const StatementReader& statement);

}  // namespace cambrian
