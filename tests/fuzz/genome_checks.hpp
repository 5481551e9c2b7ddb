// Fuzz targets: what must hold for any genome a reader accepted. Written again it gives the same
// bytes, its text form reads back to the same genome (fromText(toText(g)) == g), and when it
// validates under the default limits it develops into a creature (a NaN's payload is the one
// thing the text form does not keep: docs/genome.md). Only cambrian::Error may stop
// these.
#pragma once

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace cambrian::fuzz {

/// Aborts (a finding) naming `what` unless `holds`.
inline void require(bool holds, const char* what) {
  if (!holds) {
    std::fprintf(stderr, "fuzz: broken property: %s\n", what);
    std::abort();
  }
}

/// The offset of the first byte where `a` and `b` differ (the shorter size when one is a prefix).
inline std::size_t firstDifference(const std::vector<std::uint8_t>& a,
                                   const std::vector<std::uint8_t>& b) {
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i])
    ++i;
  return i;
}

/// The checks above on an accepted genome.
inline void checkAcceptedGenome(const Genotype& genome) {
  const Encoding& encoding = genome.encoding();
  std::vector<std::uint8_t> written = encoding.toBytes(genome.data());
  if (written != genome.bytes()) {
    std::fprintf(stderr, "fuzz: read %zu bytes, written again %zu, first difference at byte %zu\n",
                 genome.bytes().size(), written.size(), firstDifference(written, genome.bytes()));
  }
  require(written == genome.bytes(), "written again, the same bytes");
  std::string text = encoding.toText(genome);
  Genotype again = encoding.fromText(text, "text form");
  if (!(again == genome) && text.find("nan") == std::string::npos) {
    std::fprintf(stderr,
                 "fuzz: the text form:\n%s\nfuzz: read back it differs at byte %zu, and is:\n%s\n",
                 text.c_str(), firstDifference(again.bytes(), genome.bytes()),
                 encoding.toText(again).c_str());
  }
  // a NaN is written "nan" (its payload lost; never valid): then the text itself must be stable
  if (text.find("nan") == std::string::npos)
    require(again == genome, "text form reads back to the same genome");
  else
    require(encoding.toText(again) == text, "text form with a NaN reads back to the same text");
  encoding.size(genome);
  try {
    encoding.validate(genome);
  } catch (const Error&) {
    return;  // a genome outside the limits is refused before development
  }
  encoding.develop(genome);
}

}  // namespace cambrian::fuzz
