// cambrian: the directed-graph encoding's settings and its genotype operations.
#include "encodings/directed_graph/encoding.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "encodings/directed_graph/gene_ranges.hpp"
#include "encodings/directed_graph/graph.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace cambrian::graph {

namespace {

// the encoding whose prototype every directed-graph genotype refers to
const DirectedGraphEncoding& prototype() {
  static const DirectedGraphEncoding encoding;
  return encoding;
}

}  // namespace

Genotype makeGenotype(Genome genome) {
  return Genotype(prototype(), std::make_shared<GraphGenomeData>(std::move(genome)));
}

const Genome& graphGenome(const Genotype& genotype) {
  if (!genotype)
    throw GenomeError("directed_graph: no genome");
  return genotype.as<GraphGenomeData>().genome;
}

std::unique_ptr<Encoding> DirectedGraphEncoding::clone() const {
  return std::make_unique<DirectedGraphEncoding>(*this);
}

void DirectedGraphEncoding::declareSettings(SettingsSchema& s) {
  // [genome]: the limits, with the ranges each must keep
  GenomeLimits& g = limits;
  s.describeSection("genome", "[genome] the genome encoding and its limits");
  s.add("genome.max_nodes", g.max_nodes, "maximum genes (graph nodes) per genome")
      .require([&g] { return g.max_nodes >= 1 && g.max_nodes <= 1000; }, "must be in 1..1000");
  s.add("genome.max_connections", g.max_connections, "maximum connections per genome")
      .require([&g] { return g.max_connections >= 0 && g.max_connections <= 4000; },
               "must be in 0..4000");
  s.add("genome.max_parts", g.max_parts, "maximum body parts after development")
      .require([&g] { return g.max_parts >= 1 && g.max_parts <= 1000; }, "must be in 1..1000");
  s.add("genome.max_recursive_limit", g.max_recursive_limit, "largest recursive limit of a node")
      .require([&g] { return g.max_recursive_limit >= 1 && g.max_recursive_limit <= 64; },
               "must be in 1..64");
  s.add("genome.max_neurons_per_node", g.max_neurons_per_node, "local neurons per node")
      .require([&g] { return g.max_neurons_per_node >= 0 && g.max_neurons_per_node <= 64; },
               "must be in 0..64");
  s.add("genome.max_brain_neurons", g.max_brain_neurons, "global (brain) neurons")
      .require([&g] { return g.max_brain_neurons >= 0 && g.max_brain_neurons <= 256; },
               "must be in 0..256");
  s.add("genome.max_inputs", g.max_inputs,
        "input wires stored per neuron (a neuron reads at most 3)")
      .require([&g] { return g.max_inputs >= 0 && g.max_inputs <= 3; }, "must be in 0..3");
  s.add("genome.min_part_size", g.min_part_size, "smallest box side, m")
      .require([&g] { return g.min_part_size > 0 && std::isfinite(g.min_part_size); },
               "must be > 0 and finite");
  s.add("genome.max_part_size", g.max_part_size, "largest box side, m")
      .require(
          [&g] { return g.max_part_size >= g.min_part_size && std::isfinite(g.max_part_size); },
          "must be >= genome.min_part_size and finite");
  s.add("genome.min_density", g.min_density, "smallest part density, kg/m^3")
      .require([&g] { return g.min_density > 0 && std::isfinite(g.min_density); },
               "must be > 0 and finite");
  s.add("genome.max_density", g.max_density, "largest part density, kg/m^3")
      .require([&g] { return g.max_density >= g.min_density && std::isfinite(g.max_density); },
               "must be >= genome.min_density and finite");
  s.add("genome.max_weight", g.max_weight, "largest |weight| of a neuron or effector input")
      .require([&g] { return g.max_weight >= 0 && std::isfinite(g.max_weight); },
               "must be >= 0 and finite");
  s.add("genome.min_scale", g.min_scale, "smallest size multiplier of a connection")
      .require([&g] { return g.min_scale > 0 && std::isfinite(g.min_scale); },
               "must be > 0 and finite");
  s.add("genome.max_scale", g.max_scale, "largest size multiplier of a connection")
      .require([&g] { return g.max_scale >= g.min_scale && std::isfinite(g.max_scale); },
               "must be >= genome.min_scale and finite");
  s.add("genome.max_frequency", g.max_frequency, "highest joint oscillator frequency, Hz")
      .require([&g] { return g.max_frequency >= 0 && std::isfinite(g.max_frequency); },
               "must be >= 0 and finite");
  s.add("genome.joint_types", joint_type_names,
        "the joint types genomes may use: rigid revolute universal spherical (Chaumont et al.: "
        "rigid revolute, one degree of freedom at most)")
      .require([this] { return parseJointTypes(); },
               "must name one or more of rigid, revolute, universal, spherical, each once");
  s.addChoice("genome.contact_sensors", g.contact_sensors,
              {{"part", ContactSensors::per_part}, {"face", ContactSensors::per_face}},
              "each part's contact sensors: part (one, 1 touched / 0) | face (six, one per face, "
              "1 touched / -1: Sims, Chaumont et al.)");
  s.addChoice("genome.neuron_set", g.neuron_set,
              {{"sims", NeuronSet::sims}, {"chaumont", NeuronSet::chaumont}},
              "the neuron functions genomes use: sims (Sims' and cambrian's first 24) | chaumont "
              "(Chaumont et al.'s cst sum mul sumT div mem wav, every signal within +-1)");

  s.addChoice("genome.strength_section", g.strength_section,
              {{"smaller", StrengthSection::smaller}, {"larger", StrengthSection::larger}},
              "which of the two faces meeting at a joint its strength is proportional to: "
              "smaller | larger (Chaumont et al.'s 'cross section of the bigger block', after "
              "Sims)");
  s.addChoice("genome.photosensors", g.photosensors,
              {{"root", Photosensors::root},
               {"every_part", Photosensors::every_part},
               {"chosen", Photosensors::chosen}},
              "the parts with photosensors: root (three for the whole creature) | every_part "
              "(three more on each part, in its own frame, read by its neurons as local sensors) "
              "| chosen (three more on each part whose gene is photosensitive, a flag random "
              "genomes draw and mutation flips: Sims' photosensors 'relative to the orientation "
              "of the photosensitive part')");
  s.add("genome.catapult", g.catapult,
        "Chaumont et al.'s catapults: the root part is an arm holding a projectile it lets go of "
        "after genome.release_delay controller steps, or earlier on the network's signal");
  s.add("genome.projectile_mutation", g.projectile_mutation,
        "catapults: mutation may change the projectile's size and shape (Chaumont et al.: in "
        "some runs)");
  s.add("genome.projectile_density_mutation", g.projectile_density_mutation,
        "catapults, with genome.projectile_mutation: mutation may change the projectile's "
        "density too (not in Chaumont et al., who mutate 'the size and shape')");
  s.add("genome.projectile_min_side", g.projectile_min_side,
        "catapults: the least side of a projectile, m (its own range, not the parts')")
      .require([&g] { return g.projectile_min_side > 0; }, "must be positive");
  s.add("genome.projectile_max_side", g.projectile_max_side,
        "catapults: the greatest side of a projectile, m")
      .require([&g] { return g.projectile_max_side >= g.projectile_min_side; },
               "must be at least genome.projectile_min_side");
  s.add("genome.projectile_side", g.projectile_side,
        "catapults: side of a random genome's cubic projectile, m")
      .require(
          [&g] {
            return g.projectile_side >= g.projectile_min_side &&
                   g.projectile_side <= g.projectile_max_side;
          },
          "must lie within genome.projectile_min_side and genome.projectile_max_side");
  s.add("genome.projectile_density", g.projectile_density,
        "catapults: density of a random genome's projectile, kg/m^3")
      .require(
          [&g] {
            return g.projectile_density >= g.min_density && g.projectile_density <= g.max_density;
          },
          "must lie within genome.min_density and genome.max_density");
  s.add("genome.release_delay", g.release_delay,
        "catapults: controller steps until the arm lets go of the projectile at the latest "
        "(Chaumont et al.: 30)")
      .require([&g] { return g.release_delay >= 3 && g.release_delay <= 257; },
               "must be in [3, 257]");

  // Minemonics' joint controllers: sine or chaotic (a Chua circuit per joint)
  s.addChoice("genome.joint_controller", g.joint_controller,
              {{"sine", JointControllerKind::sine}, {"chaotic", JointControllerKind::chaotic}},
              "the kind of joint controller random connections get: sine (amplitude sin(2 pi f t "
              "+ phase) + offset) | chaotic (amplitude z + offset of a Chua circuit, Minemonics' "
              "chaotic controller)");
  s.add("genome.joint_controller_chance", g.joint_controller_chance,
        "the chance a random connection's joint controller is on (Minemonics: every joint, 1)")
      .require([&g] { return g.joint_controller_chance >= 0 && g.joint_controller_chance <= 1; },
               "must be in [0, 1]");
  s.add("genome.chua_rate", g.chua.rate,
        "chaotic controllers: circuit time per simulated second at speed 1 (Minemonics: 0.001 "
        "per physics step of 1/240 s, 0.24)")
      .require([&g] { return g.chua.rate > 0 && g.chua.rate <= 100; }, "must be in (0, 100]");
  s.add("genome.chua_limiter", g.chua.limited,
        "chaotic controllers: the limiter on dx/dt, (tanh(softness (limit - x)) + 1) / 2 "
        "(in Minemonics' code, commented out)");
  s.add("genome.chua_limit", g.chua.limit, "chaotic controllers: the limiter's x (Minemonics: 2)")
      .require([&g] { return std::isfinite(g.chua.limit); }, "must be finite");
  s.add("genome.chua_limit_softness", g.chua.limit_softness,
        "chaotic controllers: how sharply the limiter holds x below the limit (Minemonics: 7)")
      .require([&g] { return g.chua.limit_softness > 0 && std::isfinite(g.chua.limit_softness); },
               "must be > 0 and finite");

  s.add("genome.morphogenes", g.morphogenes,
        "Minemonics' morphogenes: random genes and mutation draw the part's shape (box or "
        "capsule), friction, restitution, joint anchor, segment shrink and joint damping and the "
        "connection's "
        "flip and mirror flags; off, they keep Sims' defaults");
  s.add("genome.min_friction", g.min_friction, "smallest friction of a part")
      .require([&g] { return g.min_friction >= 0 && std::isfinite(g.min_friction); },
               "must be >= 0 and finite");
  s.add("genome.max_friction", g.max_friction,
        "largest friction of a part (Minemonics' code starts every limb at 10)")
      .require([&g] { return g.max_friction >= g.min_friction && std::isfinite(g.max_friction); },
               "must be >= genome.min_friction and finite");
  s.add("genome.min_restitution", g.min_restitution, "smallest restitution of a part")
      .require([&g] { return g.min_restitution >= 0 && g.min_restitution <= 1; },
               "must be in [0, 1]");
  s.add("genome.max_restitution", g.max_restitution,
        "largest restitution of a part (Minemonics' code starts every limb at 0.2)")
      .require([&g] { return g.max_restitution >= g.min_restitution && g.max_restitution <= 1; },
               "must be in [genome.min_restitution, 1]");
  s.add("genome.min_shrink", g.min_shrink,
        "smallest segment shrink, the size multiplier of every part branched from a part "
        "(Minemonics: 1 - 0.66)")
      .require([&g] { return g.min_shrink > 0 && g.min_shrink <= 1; }, "must be in (0, 1]");
  s.add("genome.max_shrink", g.max_shrink, "largest segment shrink (Minemonics: 1 + 2)")
      .require([&g] { return g.max_shrink >= 1 && std::isfinite(g.max_shrink); },
               "must be >= 1 and finite");
  s.add("genome.min_joint_damping", g.min_joint_damping,
        "smallest damping of a joint's own, N m s / rad (Minemonics: 0.001)")
      .require([&g] { return g.min_joint_damping >= 0 && std::isfinite(g.min_joint_damping); },
               "must be >= 0 and finite");
  s.add("genome.max_joint_damping", g.max_joint_damping,
        "largest damping of a joint's own, N m s / rad (Minemonics: 0.5)")
      .require(
          [&g] {
            return g.max_joint_damping >= g.min_joint_damping && std::isfinite(g.max_joint_damping);
          },
          "must be >= genome.min_joint_damping and finite");

  // [evolution]: the structural mutation rates of the graph (their historic keys)
  MutationSettings& m = mutation;
  auto probability = [&s](const char* key, double& rate, const char* help) {
    s.add(key, rate, help).require([&rate] { return rate >= 0 && rate <= 1; }, "must be in [0, 1]");
  };
  s.add("evolution.mutation_perturbation", m.perturbation,
        "perturbation scale, fraction of each parameter's range")
      .require([&m] { return m.perturbation > 0 && m.perturbation <= 10; }, "must be in (0, 10]");
  probability("evolution.add_node_rate", m.add_node_rate, "chance a mutation adds a node");
  probability("evolution.remove_node_rate", m.remove_node_rate, "chance a mutation removes a node");
  probability("evolution.add_connection_rate", m.add_connection_rate,
              "chance a mutation adds a connection");
  probability("evolution.remove_connection_rate", m.remove_connection_rate,
              "chance a mutation removes a connection");
  probability("evolution.repoint_rate", m.repoint_rate, "chance each connection is re-pointed");
  probability("evolution.add_neuron_rate", m.add_neuron_rate, "chance a mutation adds a neuron");
  probability("evolution.remove_neuron_rate", m.remove_neuron_rate,
              "chance a mutation removes a neuron");
  s.addChoice("evolution.graft_into", graft_into,
              {{"root", GraftInto::root}, {"any_node", GraftInto::any_node}},
              "the second parent's node a graft leads into: root (its whole body) | any_node "
              "(drawn uniformly, as Sims grafts)");

  // the reaper's operators (evolution.scheme = reaper; Minemonics' numbers)
  ReaperOperatorSettings& r = reaper;
  probability("evolution.gene_specification_chance", r.gene_specification_chance,
              "reaper: chance each gene is re-drawn by a gene specification (Minemonics: 0.2)");
  probability("evolution.gene_split_chance", r.gene_split_chance,
              "reaper: chance each gene is split in two by a gene split (Minemonics: 0.2)");
  probability("evolution.branch_specification_chance", r.branch_specification_chance,
              "reaper: chance each gene has one connection re-drawn by a branch specification "
              "(Minemonics: 0.2)");
  probability("evolution.grow_stub_chance", r.grow_stub_chance,
              "reaper: chance each gene grows new connections by a grow stub (Minemonics: 0.6)");
  s.add("evolution.grow_stub_max", r.grow_stub_max,
        "reaper: most connections a gene grows by a grow stub (Minemonics: 0..2)")
      .require([&r] { return r.grow_stub_max >= 0 && r.grow_stub_max <= 16; }, "must be in 0..16");
  s.add("evolution.graft_depth_min", r.graft_depth_min,
        "reaper: fewest levels of genes a feature graft copies (Minemonics: 5)")
      .require([&r] { return r.graft_depth_min >= 1 && r.graft_depth_min <= 64; },
               "must be in 1..64");
  s.add("evolution.graft_depth_max", r.graft_depth_max,
        "reaper: most levels of genes a feature graft copies (Minemonics: 10)")
      .require([&r] { return r.graft_depth_max >= r.graft_depth_min && r.graft_depth_max <= 64; },
               "must be in evolution.graft_depth_min..64");
  s.add("evolution.segment_branch_redraws", r.segment_branch_redraws,
        "reaper: connections a segment crossover re-draws after joining the two segments "
        "(Minemonics: 10)")
      .require([&r] { return r.segment_branch_redraws >= 0 && r.segment_branch_redraws <= 1000; },
               "must be in 0..1000");
  s.add("evolution.keep_unconnected", m.keep_unconnected,
        "keep nodes unreachable from the root (Chaumont) instead of collecting them");
}

bool DirectedGraphEncoding::parseJointTypes() {
  std::uint8_t mask = 0;
  std::istringstream names(joint_type_names);
  for (std::string name; names >> name;) {
    const auto* end = std::end(kJointNames);
    const auto* found = std::find(std::begin(kJointNames), end, name);
    if (found == end)
      return false;
    const auto bit = static_cast<std::uint8_t>(1u << (found - std::begin(kJointNames)));
    if (mask & bit)
      return false;
    mask |= bit;
  }
  if (mask == 0)
    return false;
  limits.joint_types = mask;
  return true;
}

Genotype DirectedGraphEncoding::random(std::uint64_t seed, std::uint64_t generation,
                                       std::uint64_t individual) const {
  return makeGenotype(randomGenome(limits, seed, generation, individual));
}

void DirectedGraphEncoding::validate(const Genotype& genome) const {
  requireOwn(genome);
  validateGenome(graphGenome(genome), limits);
}

GenomeSize DirectedGraphEncoding::size(const Genotype& genotype) const {
  const Genome& genome = graphGenome(genotype);
  GenomeSize size;
  size.genes = genome.nodes.size();
  size.links = genome.connections.size();
  // the mean box side per node, summed in node order
  for (const PartGene& node : genome.nodes) {
    double side = (node.dimensions.x + node.dimensions.y + node.dimensions.z) / 3;
    if (std::isfinite(side))
      size.total_part_size += std::max(0.0, side);
  }
  return size;
}

Creature DirectedGraphEncoding::develop(const Genotype& genome) const {
  requireOwn(genome);
  return graph::develop(graphGenome(genome), limits);
}

Genotype DirectedGraphEncoding::mutate(const Genotype& parent, double parameter_rate,
                                       Rng& rng) const {
  MutationSettings settings = mutation;
  settings.parameter_rate = parameter_rate;
  return makeGenotype(graph::mutate(graphGenome(parent), limits, settings, rng));
}

Genotype DirectedGraphEncoding::combine(Variation variation, const Genotype& a, const Genotype& b,
                                        Rng& rng) const {
  const Genome& first = graphGenome(a);
  const Genome& second = graphGenome(b);
  if (variation == Variation::graft)
    return makeGenotype(graft(first, second, limits, rng, graft_into));
  if (variation == Variation::graft_feature)
    return makeGenotype(graftFeature(first, second, limits, reaper, rng));
  if (variation == Variation::segment_crossover)
    return makeGenotype(crossSegments(first, second, limits, reaper, rng));
  if (variation != Variation::crossover)
    throw GenomeError(std::string("directed_graph: ") + variationName(variation) +
                      " takes one parent");
  return makeGenotype(crossover(first, second, limits, rng));
}

Genotype DirectedGraphEncoding::vary(Variation variation, const Genotype& parent, Rng& rng) const {
  const Genome& genome = graphGenome(parent);
  switch (variation) {
    case Variation::gene_specification:
      return makeGenotype(specifyGenes(genome, limits, reaper, rng));
    case Variation::gene_split:
      return makeGenotype(splitGenes(genome, limits, reaper, rng));
    case Variation::gene_purge:
      return makeGenotype(purgeGene(genome, limits, rng));
    case Variation::branch_specification:
      return makeGenotype(specifyBranches(genome, limits, reaper, rng));
    case Variation::grow_stub:
      return makeGenotype(growStubs(genome, limits, reaper, rng));
    default:
      return Encoding::vary(variation, parent, rng);
  }
}

Genotype DirectedGraphEncoding::tidy(const Genotype& genome) const {
  // Chaumont keeps unreachable nodes; otherwise they are collected
  if (mutation.keep_unconnected)
    return genome;
  const Genome& graph = graphGenome(genome);
  if (removesNothing(graph, reachableNodes(graph)))
    return genome;  // nothing to collect: the same genome, not a copy
  return makeGenotype(removeUnreachableNodes(graph));
}

std::vector<std::uint8_t> DirectedGraphEncoding::toBytes(const GenomeData& data) const {
  const auto* graph = dynamic_cast<const GraphGenomeData*>(&data);
  if (!graph)
    throw GenomeError("directed_graph: asked to write a genome of another encoding");
  return serializeGenome(graph->genome);
}

Genotype DirectedGraphEncoding::fromBytes(const std::uint8_t* bytes, std::size_t size) const {
  Genome genome = deserializeGenome(bytes, size);
  return Genotype(prototype(), std::make_shared<GraphGenomeData>(std::move(genome)),
                  std::vector<std::uint8_t>(bytes, bytes + size));
}

std::string DirectedGraphEncoding::toText(const Genotype& genome) const {
  return genomeToText(graphGenome(genome));
}

Genotype DirectedGraphEncoding::fromText(const std::string& text, const std::string& source) const {
  return makeGenotype(parseGenomeText(text, source));
}

}  // namespace cambrian::graph
