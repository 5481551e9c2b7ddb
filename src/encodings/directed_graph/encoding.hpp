// cambrian: the directed-graph encoding (Sims 1994, Chaumont et al. 2007) behind the Encoding
// interface: its settings, and genomes wrapped as genotypes.
#pragma once

#include "cambrian/encoding.hpp"

#include "encodings/directed_graph/genome.hpp"
#include "encodings/directed_graph/operators.hpp"
#include "encodings/directed_graph/reaper_operators.hpp"

namespace cambrian::graph {

/// A directed-graph genome as GenomeData.
struct GraphGenomeData : GenomeData {
  explicit GraphGenomeData(Genome g) : genome(std::move(g)) {}
  Genome genome;
};

/// `genome` as a genotype of the directed-graph encoding.
Genotype makeGenotype(Genome genome);

/// Sims' directed graph: nodes are part classes, connections joint classes; mutation,
/// crossover and grafting, and Minemonics' reaper's operators; development into boxes, the nested
/// network and joint oscillators.
class DirectedGraphEncoding : public Encoding {
 public:
  /// The registered name.
  static constexpr const char* kName = "directed_graph";

  std::unique_ptr<Encoding> clone() const override;
  std::string name() const override { return kName; }
  std::array<char, 4> tag() const override { return kGenomeTag; }
  std::string textHeader() const override { return "cambrian-genome"; }
  void declareSettings(SettingsSchema& schema) override;

  Genotype random(std::uint64_t seed, std::uint64_t generation,
                  std::uint64_t individual) const override;
  void validate(const Genotype& genome) const override;
  GenomeSize size(const Genotype& genome) const override;
  Creature develop(const Genotype& genome) const override;

  bool supports(Variation) const override { return true; }
  Genotype mutate(const Genotype& parent, double parameter_rate, Rng& rng) const override;
  Genotype combine(Variation variation, const Genotype& a, const Genotype& b,
                   Rng& rng) const override;
  Genotype vary(Variation variation, const Genotype& parent, Rng& rng) const override;
  Genotype tidy(const Genotype& genome) const override;

  std::vector<std::uint8_t> toBytes(const GenomeData& data) const override;
  Genotype fromBytes(const std::uint8_t* bytes, std::size_t size) const override;
  std::string toText(const Genotype& genome) const override;
  Genotype fromText(const std::string& text, const std::string& source) const override;

  /// The limits genomes are made, checked and developed under ([genome] keys).
  GenomeLimits limits;
  /// Sets limits.joint_types from joint_type_names; false (and unchanged) for an unknown or
  /// repeated name or none.
  bool parseJointTypes();
  /// genome.joint_types: the names of the allowed joint types, separated by spaces
  /// (GenomeLimits::joint_types)
  std::string joint_type_names = "rigid revolute universal spherical";
  /// The structural mutation rates ([evolution] keys; parameter_rate comes with each call).
  MutationSettings mutation;
  /// Where grafting attaches the second parent (evolution.graft_into).
  GraftInto graft_into = GraftInto::root;
  /// The reaper's operators' chances and sizes ([evolution] keys).
  ReaperOperatorSettings reaper;
};

}  // namespace cambrian::graph
