// cambrian: genotypes — a genome of any encoding with its byte form made once.
#include "cambrian/encoding.hpp"
#include "cambrian/error.hpp"

#include <iterator>
#include <typeinfo>

namespace cambrian {

struct Genotype::State {
  const Encoding* encoding = nullptr;
  std::shared_ptr<const GenomeData> data;
  mutable std::vector<std::uint8_t> bytes;   // empty until bytes() (a byte form is never empty)
  mutable std::function<Genotype()> recipe;  // a deferred genome's, until it is made
};

Genotype Genotype::deferred(const Encoding& encoding, std::function<Genotype()> make) {
  Genotype genotype;
  genotype.state_ = std::make_shared<State>();
  genotype.state_->encoding = &encoding;
  genotype.state_->recipe = std::move(make);
  return genotype;
}

bool Genotype::made() const {
  return state_ && !state_->recipe;
}

void Genotype::make() const {
  // the recipe's genome becomes this handle's (and every copy's): data and any byte form
  Genotype genome = state_->recipe();
  if (!genome || genome.state_->encoding->tag() != state_->encoding->tag())
    throw Error(ExitCode::failure, "genotype: a deferred genome was made of another encoding");
  genome.data();
  state_->encoding = genome.state_->encoding;
  state_->data = genome.state_->data;
  state_->bytes = genome.state_->bytes;
  state_->recipe = nullptr;
}

Genotype::Genotype(const Encoding& encoding, std::shared_ptr<const GenomeData> data)
    : state_(std::make_shared<State>()) {
  state_->encoding = &encoding;
  state_->data = std::move(data);
}

Genotype::Genotype(const Encoding& encoding, std::shared_ptr<const GenomeData> data,
                   std::vector<std::uint8_t> bytes)
    : Genotype(encoding, std::move(data)) {
  state_->bytes = std::move(bytes);
}

const Encoding& Genotype::encoding() const {
  if (!state_)
    throw Error(ExitCode::failure, "genotype: empty (no genome)");
  return *state_->encoding;
}

const GenomeData& Genotype::data() const {
  if (state_ && state_->recipe)
    make();
  if (state_ && !state_->data && !state_->bytes.empty())
    state_->data =
        state_->encoding->fromBytes(state_->bytes.data(), state_->bytes.size()).state_->data;
  if (!state_ || !state_->data)
    throw Error(ExitCode::failure, "genotype: empty (no genome)");
  return *state_->data;
}

const std::vector<std::uint8_t>& Genotype::bytes() const {
  if (state_->recipe)
    make();
  if (state_->bytes.empty()) {
    state_->bytes = encoding().toBytes(data());
    state_->bytes.shrink_to_fit();  // kept for the genome's life: no growth slack
  }
  return state_->bytes;
}

void Genotype::dropDecoded() const {
  if (state_ && !state_->recipe && !state_->bytes.empty())
    state_->data.reset();
}

bool operator==(const Genotype& a, const Genotype& b) {
  if (!a || !b)
    return !a && !b;
  return a.state_ == b.state_ || a.bytes() == b.bytes();
}

void Genotype::wrongType() const {
  throw GenomeError("genome of encoding " + encoding().name() + " is not the type asked for (" +
                    typeid(data()).name() + ")");
}

const char* variationName(Variation variation) {
  static constexpr const char* kNames[kVariationKinds] = {"mutation",
                                                          "crossover",
                                                          "graft",
                                                          "gene_specification",
                                                          "gene_split",
                                                          "gene_purge",
                                                          "branch_specification",
                                                          "grow_stub",
                                                          "graft_feature",
                                                          "segment_crossover"};
  const auto index = static_cast<std::size_t>(variation);
  return index < std::size(kNames) ? kNames[index] : "unknown";
}

Genotype Encoding::vary(Variation variation, const Genotype&, Rng&) const {
  throw GenomeError("the encoding " + name() + " has no variation " + variationName(variation));
}

void Encoding::requireOwn(const Genotype& genome) const {
  if (!genome)
    throw GenomeError(name() + ": no genome");
  if (genome.encoding().name() != name())
    throw GenomeError("a genome of encoding " + genome.encoding().name() + " given to encoding " +
                      name() + " (genome.encoding)");
}

}  // namespace cambrian
