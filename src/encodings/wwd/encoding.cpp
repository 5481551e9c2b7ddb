// cambrian: the wwd encoding's settings, its genotype operations and its byte and text forms.
#include "encodings/wwd/encoding.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "core/bytes.hpp"
#include "core/settings.hpp"
#include "core/text_line.hpp"
#include "encodings/wwd/operators.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

namespace cambrian::wwd {

namespace {

// the encoding every wwd genotype refers to
const WwdEncoding& prototype() {
  static const WwdEncoding encoding;
  return encoding;
}

constexpr std::uint32_t kBytesVersion = 1;
constexpr long long kTextVersion = 1;
// genes a line of the text form holds
constexpr std::size_t kGenesPerLine = 20;

}  // namespace

Genotype makeGenotype(Dna dna) {
  return Genotype(prototype(), std::make_shared<DnaData>(std::move(dna)));
}

const Dna& dnaOf(const Genotype& genotype) {
  if (!genotype)
    throw GenomeError("wwd: no genome");
  return genotype.as<DnaData>().dna;
}

std::unique_ptr<Encoding> WwdEncoding::clone() const {
  return std::make_unique<WwdEncoding>(*this);
}

void WwdEncoding::declareSettings(SettingsSchema& s) {
  GrammarSettings& g = grammar;
  s.describeSection("wwd", "[wwd] Walking with Dinosaurs' DNA (genome.encoding = wwd)");
  s.add("wwd.max_boxes", g.max_boxes,
        "the most boxes a creature has; joints past it are not read (the seed's 15)")
      .require([&g] { return g.max_boxes >= 1 && g.max_boxes <= 1000; }, "must be in 1..1000");
  s.add("wwd.min_side", g.min_side, "the shortest side of a box, m (the seed's 0.05)")
      .require([&g] { return g.min_side > 0 && std::isfinite(g.min_side); },
               "must be > 0 and finite");
  s.add("wwd.max_side", g.max_side, "the longest side of a box, m (the seed's 10)")
      .require([&g] { return g.max_side >= g.min_side && std::isfinite(g.max_side); },
               "must be finite and >= wwd.min_side");
  s.add("wwd.max_joint_limit", g.max_joint_limit,
        "the widest a joint turns each way about each axis, degrees (the seed's 85)")
      .require([&g] { return g.max_joint_limit >= 0 && g.max_joint_limit <= 90; },
               "must be in [0, 90]");
  s.add("wwd.main_net_size", g.main_net_size,
        "the most probable nodes per layer of the main net (the seed's 5)")
      .require([&g] { return g.main_net_size >= 1 && g.main_net_size <= 30; }, "must be in 1..30");
  s.add("wwd.subnet_size", g.subnet_size,
        "the most probable nodes per layer of a joint's subnet (3: a joint uses at most 3 outputs)")
      .require([&g] { return g.subnet_size >= 1 && g.subnet_size <= 30; }, "must be in 1..30");
  s.add("wwd.max_weight", g.max_weight,
        "weights and constant values span -max_weight .. max_weight")
      .require([&g] { return g.max_weight >= 0 && std::isfinite(g.max_weight); },
               "must be >= 0 and finite");
  s.add("wwd.density", body.density, "the boxes' density, kg/m^3")
      .require([this] { return body.density > 0 && std::isfinite(body.density); },
               "must be > 0 and finite");
  s.add("wwd.friction", body.friction, "the boxes' Coulomb friction coefficient")
      .require([this] { return body.friction >= 0 && std::isfinite(body.friction); },
               "must be >= 0 and finite");
  s.add("wwd.strength_per_area", body.strength_per_area,
        "muscle torque per m^2 of a joint's cross-section (the smaller of the two faces), N m")
      .require(
          [this] { return body.strength_per_area >= 0 && std::isfinite(body.strength_per_area); },
          "must be >= 0 and finite");
  s.add("wwd.mutation_rate", mutation_rate,
        "the chance each gene is drawn anew by a mutation (0: 1/n for a DNA of n genes, the "
        "seed's)")
      .require([this] { return mutation_rate >= 0 && mutation_rate <= 1; }, "must be in [0, 1]");
  s.add("wwd.max_genes", max_genes, "the longest DNA a genome may have, genes")
      .require([this] { return max_genes >= 1; }, "must be >= 1");
}

Genotype WwdEncoding::random(std::uint64_t seed, std::uint64_t generation,
                             std::uint64_t individual) const {
  Rng rng(seed, RngPurpose::random_genome, generation, individual);
  return makeGenotype(randomDna(grammar, rng));
}

void WwdEncoding::validate(const Genotype& genome) const {
  requireOwn(genome);
  const Dna& dna = dnaOf(genome);
  if (dna.size() > max_genes)
    throw GenomeError("wwd DNA: " + std::to_string(dna.size()) +
                      " genes, more than wwd.max_genes = " + std::to_string(max_genes));
  for (std::size_t i = 0; i < dna.size(); ++i) {
    if (dna[i] >= kGeneValues)
      throw GenomeError("wwd DNA: gene " + std::to_string(i) + " is " + std::to_string(dna[i]) +
                        " (genes are 0.." + std::to_string(kGeneValues - 1) + ")");
  }
}

GenomeSize WwdEncoding::size(const Genotype& genome) const {
  const CreatureGenes genes = readCreature(dnaOf(genome), grammar);
  GenomeSize size;
  size.genes = genes.boxes.size();
  size.links = genes.joints.size();
  for (const BoxGenes& box : genes.boxes)
    size.total_part_size += (box.size.x + box.size.y + box.size.z) / 3;
  return size;
}

Creature WwdEncoding::develop(const Genotype& genome) const {
  requireOwn(genome);
  return developCreature(readCreature(dnaOf(genome), grammar), body);
}

bool WwdEncoding::supports(Variation variation) const {
  return variation == Variation::mutation || variation == Variation::crossover;
}

Genotype WwdEncoding::mutate(const Genotype& parent, double parameter_rate, Rng& rng) const {
  const Dna& dna = dnaOf(parent);
  if (parameter_rate <= 0 || dna.empty())
    return parent;
  const double own = mutation_rate > 0 ? mutation_rate : 1.0 / static_cast<double>(dna.size());
  return makeGenotype(mutateDna(dna, std::min(1.0, own * parameter_rate), rng));
}

Genotype WwdEncoding::combine(Variation variation, const Genotype& a, const Genotype& b,
                              Rng& rng) const {
  if (variation != Variation::crossover)
    throw GenomeError(std::string("wwd: no ") + variationName(variation) +
                      " (Walking with Dinosaurs has mutation and the Mtree crossover)");
  Dna child = crossDna(dnaOf(a), dnaOf(b), grammar, rng);
  if (child.size() > max_genes)
    return a;
  return makeGenotype(std::move(child));
}

std::vector<std::uint8_t> WwdEncoding::toBytes(const GenomeData& data) const {
  const auto* dna = dynamic_cast<const DnaData*>(&data);
  if (!dna)
    throw GenomeError("wwd: asked to write a genome of another encoding");
  std::vector<std::uint8_t> out;
  ByteWriter w(out);
  w.raw(kDnaTag.data(), kDnaTag.size());
  w.u32(kBytesVersion);
  w.u32(static_cast<std::uint32_t>(dna->dna.size()));
  for (Gene gene : dna->dna)
    w.u16(gene);
  return out;
}

Genotype WwdEncoding::fromBytes(const std::uint8_t* bytes, std::size_t size) const {
  ByteReader r(bytes, size, "wwd DNA bytes");
  if (size < kDnaTag.size() || std::memcmp(bytes, kDnaTag.data(), kDnaTag.size()) != 0)
    r.fail("not wwd DNA (bad magic)");
  for (std::size_t i = 0; i < kDnaTag.size(); ++i)
    r.u8();
  r.context("header version");
  const std::uint32_t version = r.u32();
  if (version != kBytesVersion)
    r.fail("format version " + std::to_string(version) + " is not one this cambrian reads (1)");
  r.context("gene count");
  const std::size_t count = r.count(2);
  Dna dna(count);
  r.context("genes");
  for (std::size_t i = 0; i < count; ++i) {
    dna[i] = r.u16();
    if (dna[i] >= kGeneValues)
      r.fail("gene " + std::to_string(i) + " is " + std::to_string(dna[i]) + " (genes are 0.." +
             std::to_string(kGeneValues - 1) + ")");
  }
  r.expectEnd();
  return Genotype(prototype(), std::make_shared<DnaData>(std::move(dna)),
                  std::vector<std::uint8_t>(bytes, bytes + size));
}

std::string WwdEncoding::toText(const Genotype& genome) const {
  const Dna& dna = dnaOf(genome);
  std::string text = std::string(kDnaTextHeader) + " " + std::to_string(kTextVersion) + "\n";
  text += "# Walking with Dinosaurs DNA: " + std::to_string(dna.size()) + " genes, each 0.." +
          std::to_string(kGeneValues - 1) + ", read by the grammar of " + "docs/wwd.md\n";
  for (std::size_t i = 0; i < dna.size(); i += kGenesPerLine) {
    text += "dna";
    for (std::size_t k = i; k < dna.size() && k < i + kGenesPerLine; ++k)
      text += " " + std::to_string(dna[k]);
    text += "\n";
  }
  text += "end\n";
  return text;
}

Genotype WwdEncoding::fromText(const std::string& text, const std::string& source) const {
  Dna dna;
  readStatements(
      text, source, kDnaTextHeader, kTextVersion, "dna, end",
      [&](const std::string& keyword, TextLine& line) {
        if (keyword != "dna")
          return false;
        while (line.more()) {
          if (dna.size() >= max_genes)
            line.fail("more than wwd.max_genes = " + std::to_string(max_genes) + " genes");
          dna.push_back(static_cast<Gene>(
              line.integer("gene " + std::to_string(dna.size()), 0, kGeneValues - 1)));
        }
        return true;
      });
  return makeGenotype(std::move(dna));
}

}  // namespace cambrian::wwd
