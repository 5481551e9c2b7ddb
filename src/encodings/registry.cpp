// cambrian: the registered encodings — one line each — and genome bytes of any of them.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"
#include "encodings/springy/encoding.hpp"
#include "encodings/wwd/encoding.hpp"

#include <cstring>

namespace cambrian {

const std::vector<const Encoding*>& encodings() {
  static const graph::DirectedGraphEncoding directed_graph;
  static const springy::SpringyEncoding springy;
  static const wwd::WwdEncoding wwd;
  static const std::vector<const Encoding*> registered = {
      &directed_graph,  // Sims 1994, Chaumont et al. 2007
      &springy,         // Krčah 2008
      &wwd,             // Rasmussen and Lund, Walking with Dinosaurs
  };
  return registered;
}

const Encoding& findEncoding(const std::string& name) {
  for (const Encoding* encoding : encodings()) {
    if (encoding->name() == name)
      return *encoding;
  }
  std::string names;
  for (const std::string& known : encodingNames())
    names += (names.empty() ? "" : ", ") + known;
  throw ConfigError("genome.encoding = " + name + ": must be one of " + names);
}

const Encoding* encodingForTag(const std::array<char, 4>& tag) {
  for (const Encoding* encoding : encodings()) {
    if (encoding->tag() == tag)
      return encoding;
  }
  return nullptr;
}

std::vector<std::string> encodingNames() {
  std::vector<std::string> names;
  for (const Encoding* encoding : encodings())
    names.push_back(encoding->name());
  return names;
}

Genotype decodeGenome(const std::uint8_t* bytes, std::size_t size) {
  std::array<char, 4> tag{};
  if (size >= tag.size())
    std::memcpy(tag.data(), bytes, tag.size());
  const Encoding* encoding = size >= tag.size() ? encodingForTag(tag) : nullptr;
  if (!encoding)
    throw InputError(
        "genome bytes: not a cambrian genome (bad magic: no registered encoding starts so)");
  return encoding->fromBytes(bytes, size);
}

}  // namespace cambrian
