// cambrian: Walking with Dinosaurs (Rasmussen and Lund) behind the Encoding interface: the
// genome is the DNA string, read by the grammar into boxes, joints and the layered network.
#pragma once

#include "cambrian/encoding.hpp"

#include "encodings/wwd/develop.hpp"
#include "encodings/wwd/grammar.hpp"

namespace cambrian::wwd {

/// A DNA string as GenomeData.
struct DnaData : GenomeData {
  explicit DnaData(Dna d) : dna(std::move(d)) {}
  Dna dna;
};

/// The first four bytes of the byte form.
constexpr std::array<char, 4> kDnaTag = {'C', 'M', 'B', 'W'};
/// The first word of the text form.
constexpr const char* kDnaTextHeader = "cambrian-wwd";

/// `dna` as a genotype of the wwd encoding.
Genotype makeGenotype(Dna dna);
/// The DNA of a wwd genotype; throws GenomeError for another encoding's.
const Dna& dnaOf(const Genotype& genotype);

/// See the file comment. Random genomes are the grammar read over random genes; mutation draws
/// genes anew with chance 1/n, crossover swaps Mtree points.
class WwdEncoding : public Encoding {
 public:
  /// The registered name.
  static constexpr const char* kName = "wwd";

  std::unique_ptr<Encoding> clone() const override;
  std::string name() const override { return kName; }
  std::array<char, 4> tag() const override { return kDnaTag; }
  std::string textHeader() const override { return kDnaTextHeader; }
  void declareSettings(SettingsSchema& schema) override;

  Genotype random(std::uint64_t seed, std::uint64_t generation,
                  std::uint64_t individual) const override;
  void validate(const Genotype& genome) const override;
  GenomeSize size(const Genotype& genome) const override;
  Creature develop(const Genotype& genome) const override;

  bool supports(Variation variation) const override;
  /// Each gene drawn anew with chance `parameter_rate` x (wwd.mutation_rate, or 1/n), at most 1;
  /// `parameter_rate` <= 0: the parent unchanged.
  Genotype mutate(const Genotype& parent, double parameter_rate, Rng& rng) const override;
  bool scalesOwnMutation() const override { return true; }
  Genotype combine(Variation variation, const Genotype& a, const Genotype& b,
                   Rng& rng) const override;

  std::vector<std::uint8_t> toBytes(const GenomeData& data) const override;
  Genotype fromBytes(const std::uint8_t* bytes, std::size_t size) const override;
  std::string toText(const Genotype& genome) const override;
  Genotype fromText(const std::string& text, const std::string& source) const override;

  GrammarSettings grammar;
  BodySettings body;
  double mutation_rate = 0;          ///< per gene; 0: 1 / the DNA's length (the seed's)
  std::uint64_t max_genes = 100000;  ///< the longest DNA a genome may have
};

}  // namespace cambrian::wwd
