// cambrian: the springy organisms (Krčah 2008) behind the Encoding interface: an organism file
// gives the morphology of a run, the genomes are organisms of that morphology whose muscles
// evolve.
#pragma once

#include "cambrian/encoding.hpp"

#include "encodings/springy/develop.hpp"
#include "encodings/springy/muscle_operators.hpp"
#include "encodings/springy/organism.hpp"

namespace cambrian::springy {

/// An organism as GenomeData.
struct OrganismData : GenomeData {
  explicit OrganismData(Organism o) : organism(std::move(o)) {}
  Organism organism;
};

/// The morphology of a run that names no organism file: the Pyramid of
/// jobs/creatures/springy/pyramid.organism, its muscles resting at their initial lengths.
Organism builtInPyramid();

/// `organism` as a genotype of the springy encoding.
Genotype makeGenotype(Organism organism);
/// The organism of a springy genotype; throws GenomeError for another encoding's.
const Organism& organismOf(const Genotype& genotype);

/// See the file comment. Random genomes are the template organism (springy.organism) with every
/// muscle drawn anew; mutation and crossover are the thesis' muscle operators.
class SpringyEncoding : public Encoding {
 public:
  /// The registered name.
  static constexpr const char* kName = "springy";

  std::unique_ptr<Encoding> clone() const override;
  std::string name() const override { return kName; }
  std::array<char, 4> tag() const override;
  std::string textHeader() const override;
  void declareSettings(SettingsSchema& schema) override;

  Genotype random(std::uint64_t seed, std::uint64_t generation,
                  std::uint64_t individual) const override;
  void validate(const Genotype& genome) const override;
  GenomeSize size(const Genotype& genome) const override;
  Creature develop(const Genotype& genome) const override;

  bool supports(Variation variation) const override;
  Genotype mutate(const Genotype& parent, double parameter_rate, Rng& rng) const override;
  Genotype combine(Variation variation, const Genotype& a, const Genotype& b,
                   Rng& rng) const override;

  std::vector<std::uint8_t> toBytes(const GenomeData& data) const override;
  Genotype fromBytes(const std::uint8_t* bytes, std::size_t size) const override;
  std::string toText(const Genotype& genome) const override;
  Genotype fromText(const std::string& text, const std::string& source) const override;

  /// springy.organism: the organism file whose morphology the run evolves ("": none)
  std::string organism_path;
  /// The organism read from organism_path, or without one the built-in Pyramid.
  Organism organism_template = builtInPyramid();
  MuscleOperatorSettings operators;
  BodySettings body;

 private:
  void readTemplate();
};

}  // namespace cambrian::springy
