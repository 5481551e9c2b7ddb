// cambrian: the springy encoding's settings and its genotype operations.
#include "encodings/springy/encoding.hpp"

#include "cambrian/error.hpp"
#include "cambrian/rng.hpp"

#include "core/settings.hpp"
#include "core/small_file.hpp"
#include "encodings/springy/organism_forms.hpp"
#include "encodings/springy/rules.hpp"

#include <cmath>
#include <tuple>
#include <utility>

namespace cambrian::springy {

namespace {

// the encoding every springy genotype refers to
const SpringyEncoding& prototype() {
  static const SpringyEncoding encoding;
  return encoding;
}

// the largest organism file read, bytes
constexpr std::size_t kMaxOrganismFile = 1 << 22;

}  // namespace

Organism builtInPyramid() {
  Organism o;
  // (the file's six digits)
  const std::pair<const char*, Vec3> nodes[] = {{"a", {0, 0, 0.1}},
                                                {"b", {1, 0, 0.1}},
                                                {"c", {0.5, 0.866025, 0.1}},
                                                {"top", {0.5, 0.288675, 0.9}}};
  for (const auto& [name, position] : nodes) {
    Node node;
    node.name = name;
    node.position = position;
    o.nodes.push_back(node);
  }
  const std::tuple<const char*, int, int, TubeKind> tubes[] = {
      {"ab", 0, 1, TubeKind::rod},     {"bc", 1, 2, TubeKind::rod},
      {"ca", 2, 0, TubeKind::rod},     {"m_a", 3, 0, TubeKind::muscle},
      {"m_b", 3, 1, TubeKind::muscle}, {"m_c", 3, 2, TubeKind::muscle}};
  for (const auto& [name, a, b, kind] : tubes) {
    Tube tube;
    tube.name = name;
    tube.a = a;
    tube.b = b;
    tube.kind = kind;
    if (kind == TubeKind::muscle)
      tube.muscle.rest_length = initialLength(o, tube);
    o.tubes.push_back(tube);
  }
  return o;
}

Genotype makeGenotype(Organism organism) {
  return Genotype(prototype(), std::make_shared<OrganismData>(std::move(organism)));
}

const Organism& organismOf(const Genotype& genotype) {
  if (!genotype)
    throw GenomeError("springy: no genome");
  return genotype.as<OrganismData>().organism;
}

std::unique_ptr<Encoding> SpringyEncoding::clone() const {
  return std::make_unique<SpringyEncoding>(*this);
}

std::array<char, 4> SpringyEncoding::tag() const {
  return kOrganismTag;
}

std::string SpringyEncoding::textHeader() const {
  return kOrganismTextHeader;
}

void SpringyEncoding::readTemplate() {
  // the organism file of springy.organism, read when the key is set and checked by the rules
  // with its muscles as written (muscles without parameters rest at their initial lengths)
  organism_template = builtInPyramid();
  if (organism_path.empty())
    return;
  const SmallFile file = readSmallFile(organism_path, kMaxOrganismFile);
  if (!file.problem.empty())
    throw ConfigError("springy.organism = " + organism_path + ": " + file.problem);
  Organism organism = parseOrganismText(file.bytes, organism_path);
  try {
    checkOrganism(organism, operators.limits);
  } catch (const Error& e) {
    throw ConfigError("springy.organism = " + organism_path + ": " + e.what());
  }
  organism_template = std::move(organism);
}

void SpringyEncoding::declareSettings(SettingsSchema& s) {
  MuscleOperatorSettings& o = operators;
  s.describeSection("springy", "[springy] the springy organisms (genome.encoding = springy)");
  s.add("springy.organism", organism_path,
        "the organism file whose morphology a springy run evolves (jobs/creatures/springy/); its "
        "muscles' parameters are drawn anew for every random genome (empty: a built-in copy of "
        "jobs/creatures/springy/pyramid.organism)");
  s.add("springy.max_length", o.limits.max_length,
        "the longest a muscle may become, m (the thesis' C_max, 2)")
      .require([&o] { return o.limits.max_length > 0 && std::isfinite(o.limits.max_length); },
               "must be > 0 and finite");
  s.add("springy.max_frequency", o.limits.max_frequency,
        "the highest muscle frequency, Hz (the thesis' f_max, 2)")
      .require([&o] { return o.limits.max_frequency > 0 && std::isfinite(o.limits.max_frequency); },
               "must be > 0 and finite");
  s.add("springy.evolve_frequency", o.evolve_frequency,
        "false: every muscle has springy.frozen_frequency, never drawn or mutated (the thesis' "
        "'Evolve frequency = no')");
  s.add("springy.frozen_frequency", o.frozen_frequency,
        "the one frequency of every muscle when frequencies do not evolve, Hz (Exp. 6: 1)")
      .require(
          [&o] { return o.frozen_frequency >= 0 && o.frozen_frequency <= o.limits.max_frequency; },
          "must be in [0, springy.max_frequency]");
  s.addChoice("springy.mutation", o.mutation,
              {{"atomic", MuscleMutation::atomic},
               {"quantity", MuscleMutation::quantity},
               {"parametric", MuscleMutation::parametric}},
              "the muscle mutation: atomic (each muscle drawn anew with springy.atomic_"
              "probability) | quantity (springy.quantity muscles drawn anew) | parametric (n "
              "parameters drawn anew: (L_r, A) as one, f, the first move)");
  s.add("springy.atomic_probability", o.atomic_probability,
        "atomic mutation: the chance each muscle is drawn anew (Exp. 1: 0.33)")
      .require([&o] { return o.atomic_probability >= 0 && o.atomic_probability <= 1; },
               "must be in [0, 1]");
  s.add("springy.quantity", o.quantity, "quantity mutation: muscles drawn anew (Exp. 2: 1)")
      .require([&o] { return o.quantity >= 1; }, "must be >= 1");
  s.add("springy.geometric_count", o.geometric_count,
        "parametric mutation: the number of parameters from a geometric distribution (Exp. "
        "4-6), else springy.parametric_count (Exp. 3)");
  s.add("springy.geometric_p", o.geometric_p,
        "parametric mutation: the geometric distribution's parameter (0.5)")
      .require([&o] { return o.geometric_p > 0 && o.geometric_p <= 1; }, "must be in (0, 1]");
  s.add("springy.parametric_count", o.parametric_count,
        "parametric mutation without the geometric count: parameters drawn anew")
      .require([&o] { return o.parametric_count >= 1; }, "must be >= 1");
  s.add("springy.flip_first_move", o.flip_first_move,
        "a mutated first move flips instead of being drawn again (added in Exp. 4)");
  s.add("springy.crossover_mother_share", o.crossover_mother_share,
        "uniform muscle crossover: the chance a muscle comes from the first parent (negative: "
        "drawn in [0, 1) for each crossover)")
      .require([&o] { return o.crossover_mother_share <= 1; }, "must be <= 1");
  s.add("springy.muscle_force", body.muscle_force,
        "the most a muscle's slider pushes or pulls, N (the thesis' 'slider max force', 200)")
      .require([this] { return body.muscle_force > 0 && std::isfinite(body.muscle_force); },
               "must be > 0 and finite");
  s.add("springy.friction", body.friction,
        "the Coulomb friction of nodes and tubes (the thesis' 'mu 1000')")
      .require([this] { return body.friction >= 0 && std::isfinite(body.friction); },
               "must be >= 0 and finite");
  s.addCheck([this] { readTemplate(); });
}

Genotype SpringyEncoding::random(std::uint64_t seed, std::uint64_t generation,
                                 std::uint64_t individual) const {
  Rng rng(seed, RngPurpose::random_genome, generation, individual);
  return makeGenotype(randomControl(organism_template, operators, rng));
}

void SpringyEncoding::validate(const Genotype& genome) const {
  requireOwn(genome);
  const Organism& organism = organismOf(genome);
  checkOrganism(organism, operators.limits);
  if (!operators.evolve_frequency) {
    for (const Tube& tube : organism.tubes) {
      if (tube.kind == TubeKind::muscle && tube.muscle.amplitude > 0 &&
          tube.muscle.frequency != operators.frozen_frequency)
        throw GenomeError("springy organism: muscle " + tube.name + " has frequency " +
                          std::to_string(tube.muscle.frequency) +
                          " Hz, but frequencies are frozen at springy.frozen_frequency");
    }
  }
}

GenomeSize SpringyEncoding::size(const Genotype& genome) const {
  const Organism& organism = organismOf(genome);
  GenomeSize size;
  size.genes = organism.nodes.size();
  size.links = organism.tubes.size();
  for (const Node& node : organism.nodes)
    size.total_part_size += node.diameter;
  return size;
}

Creature SpringyEncoding::develop(const Genotype& genome) const {
  requireOwn(genome);
  return developOrganism(organismOf(genome), body);
}

bool SpringyEncoding::supports(Variation variation) const {
  return variation == Variation::mutation || variation == Variation::crossover;
}

Genotype SpringyEncoding::mutate(const Genotype& parent, double, Rng& rng) const {
  // the thesis' mutations have their own rates (springy.mutation and its keys)
  return makeGenotype(mutateMuscles(organismOf(parent), operators, rng));
}

Genotype SpringyEncoding::combine(Variation variation, const Genotype& a, const Genotype& b,
                                  Rng& rng) const {
  if (variation != Variation::crossover)
    throw GenomeError(std::string("springy: no ") + variationName(variation) +
                      " (the springy organisms have mutation and crossover)");
  return makeGenotype(crossMuscles(organismOf(a), organismOf(b), operators, rng));
}

std::vector<std::uint8_t> SpringyEncoding::toBytes(const GenomeData& data) const {
  const auto* organism = dynamic_cast<const OrganismData*>(&data);
  if (!organism)
    throw GenomeError("springy: asked to write a genome of another encoding");
  return organismToBytes(organism->organism);
}

Genotype SpringyEncoding::fromBytes(const std::uint8_t* bytes, std::size_t size) const {
  Organism organism = organismFromBytes(bytes, size);
  return Genotype(prototype(), std::make_shared<OrganismData>(std::move(organism)),
                  std::vector<std::uint8_t>(bytes, bytes + size));
}

std::string SpringyEncoding::toText(const Genotype& genome) const {
  return organismToText(organismOf(genome));
}

Genotype SpringyEncoding::fromText(const std::string& text, const std::string& source) const {
  return makeGenotype(parseOrganismText(text, source));
}

}  // namespace cambrian::springy
