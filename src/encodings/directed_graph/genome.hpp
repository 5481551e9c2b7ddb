// cambrian: the Sims / Minemonics directed-graph genome, the first encoding.
//
// Nodes are classes of body parts, connections are classes of joints. Development (develop.cpp)
// walks the graph from the root node to make a BodyPlan and the controller that drives it. See
// docs/genome.md.
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/encoding.hpp"
#include "cambrian/math.hpp"

#include "brain/chua_oscillators.hpp"
#include "brain/neural_network.hpp"
#include "brain/sine_oscillators.hpp"

#include <boost/container/small_vector.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cambrian::graph {

//---------------------------------------------------------------- enumerations

/// Where a neuron or effector input reads its signal from.
enum class SignalSource : std::uint8_t {
  constant = 0,   ///< the input's weight is the value
  local_sensor,   ///< a sensor of this part (index modulo the part's sensor count)
  local_neuron,   ///< a neuron of this part
  parent_neuron,  ///< a neuron of the parent part instance (constant 0 at the root)
  child_neuron,   ///< a neuron of the child made through connection `slot` (0 if absent)
  brain_neuron,   ///< a neuron of the global brain
  brain_sensor,   ///< a whole-creature sensor (photosensor toward the target)
};

//---------------------------------------------------------------- genes

/// A short list held inside its gene up to N items (a longer one spills to the heap): a genome is
/// copied for every child bred, and one allocation per neuron and per part was most of that
template <class T, std::size_t N>
using InlineList = boost::container::small_vector<T, N>;

/// One weighted input wire. Indices are taken modulo the size of the list they point into at
/// development time, so every genome develops; `slot` is only used by child_neuron.
struct NeuronInput {
  SignalSource source = SignalSource::constant;
  std::uint16_t slot = 0;
  std::uint16_t index = 0;
  double weight = 0;
  friend bool operator==(const NeuronInput&, const NeuronInput&) = default;
};

/// A neuron class: function, inputs (only the first neuronArity() are read) and a parameter
/// (oscillator frequency in Hz, smoothing rate, threshold; meaning per function in docs/genome.md).
struct NeuronGene {
  NeuronFunction function = NeuronFunction::sum;
  InlineList<NeuronInput, 3> inputs;
  double parameter = 0;
  friend bool operator==(const NeuronGene&, const NeuronGene&) = default;
};

/// Drives one degree of freedom of the joint to the parent: torque = strength * clamp(input, -1,
/// 1).
struct EffectorGene {
  NeuronInput input;
  friend bool operator==(const EffectorGene&, const EffectorGene&) = default;
};

/// The kind of a joint controller (genome.joint_controller).
enum class JointControllerKind : std::uint8_t {
  sine,     ///< amplitude * sin(2 pi frequency t + phase) + offset (brain/sine_oscillators.hpp)
  chaotic,  ///< amplitude * z + offset of a Chua circuit (brain/chua_oscillators.hpp)
};

/// Minemonics' per-joint controller: a sine or a chaotic oscillator added to each effector of the
/// joint it drives. A sine reads amplitude, frequency, phase and offset; a chaotic one amplitude,
/// offset, chua_start and chua_speed (the others are kept, unread, so a genome round-trips).
struct JointControllerGene {
  bool enabled = false;
  double amplitude = 0;  ///< effector units (a chaotic one: per unit of z)
  double frequency = 1;  ///< Hz
  double phase = 0;      ///< radians
  double offset = 0;     ///< effector units
  JointControllerKind kind = JointControllerKind::sine;
  ChuaState chua_start{0, 0, 0};  ///< the circuit's state at the start
  double chua_speed = 1;          ///< circuit time runs chua_speed * genome.chua_rate per second
  friend bool operator==(const JointControllerGene&, const JointControllerGene&) = default;
};

/// A class of body parts (a graph node).
struct PartGene {
  PartShape shape = PartShape::box;
  Vec3 dimensions{0.2, 0.2, 0.2};              ///< full box size, metres
  double density = 1000;                       ///< kg / m^3
  JointType joint_type = JointType::revolute;  ///< joint to the parent (ignored at the root)
  Vec3 joint_limit{1, 1, 1};         ///< symmetric limit per degree of freedom, radians (0..pi)
  std::uint8_t recursive_limit = 1;  ///< how many times this node may repeat along a path (>= 1)
  std::vector<NeuronGene> neurons;   ///< local neurons, copied into every instance
  InlineList<EffectorGene, 3> effectors;  ///< one per degree of freedom; extra ones are ignored
  // Minemonics' morphogene (docs/genome.md, "Morphogenes"); the defaults are Sims' boxes
  double friction = 1;      ///< the part's Coulomb coefficient
  double restitution = -1;  ///< bounciness; negative: the world's (physics.restitution)
  /// the joint anchor: the direction from the part's centre to where it meets its parent
  Vec3 anchor{-1, 0, 0};
  double segment_shrink = 1;  ///< multiplies the size of every part branched from this one
  /// the joint's damping per degree of freedom, N m s / rad; negative: physics.joint_damping
  Vec3 joint_damping{-1, -1, -1};
  /// Sims: this part carries three photosensors (read only under genome.photosensors = chosen)
  bool photosensitive = false;
  friend bool operator==(const PartGene&, const PartGene&) = default;
};

/// A class of joints (a graph edge) from node `from` to node `to`.
struct ConnectionGene {
  std::uint16_t from = 0;
  std::uint16_t to = 0;
  Vec3 position{1, 0, 0};  ///< attachment on the parent, each in [-1, 1], projected on its surface
  Vec3 orientation{0, 0, 0};    ///< Euler angles (roll, pitch, yaw) of the child, radians
  double scale = 1;             ///< child size multiplier, compounding along the path
  std::uint8_t reflection = 0;  ///< bit 0: mirror x, bit 1: mirror y, bit 2: mirror z
  bool terminal_only = false;   ///< only applied when the recursive limit of `from` is reached
  bool flip = false;    ///< Minemonics: a second copy turned a half turn about the parent's x axis
  bool mirror = false;  ///< Minemonics: a second copy mirrored through the parent's centre
  JointControllerGene controller;
  friend bool operator==(const ConnectionGene&, const ConnectionGene&) = default;
};

/// Chaumont et al.'s catapult (genome.catapult): the block the root part, the arm, holds and
/// throws, and the one evolvable wire of the arm's release mechanism (their Figure 4).
struct ProjectileGene {
  Vec3 dimensions{0.2, 0.2, 0.2};  ///< full box size, m
  double density = 1000;           ///< kg / m^3
  Vec3 position{0, 0, 1};  ///< where the arm holds it, each in [-1, 1], pushed to its surface
  NeuronInput trigger;     ///< the network's signal into the mechanism, read as at the root
  friend bool operator==(const ProjectileGene&, const ProjectileGene&) = default;
};

/// The whole genome. Node 0 is the root.
struct Genome {
  std::vector<PartGene> nodes;
  std::vector<ConnectionGene> connections;
  std::vector<NeuronGene> brain;  ///< global neurons, instantiated once per creature
  /// a catapult's projectile and release wire (genome.catapult); none in every other genome
  std::optional<ProjectileGene> projectile;
  friend bool operator==(const Genome&, const Genome&) = default;
};

/// The neuron functions genomes may use (genome.neuron_set).
enum class NeuronSet : std::uint8_t {
  sims,      ///< Sims' functions and the others cambrian had first (constant .. oscillate_saw)
  chaumont,  ///< Chaumont et al.'s Table I: cst sum mul sumT div mem wav, signals within +-1
};

/// The contact sensors development gives each part (genome.contact_sensors).
enum class ContactSensors : std::uint8_t {
  per_part,  ///< one: 1 when anything touches the part, else 0
  per_face,  ///< six, one per face: 1 when touched, else -1 (Sims; Chaumont et al.'s sen)
};

/// Where development puts photosensors (genome.photosensors).
enum class Photosensors : std::uint8_t {
  root,        ///< three for the whole creature, on the root (read through brain_sensor)
  every_part,  ///< those, and three more on every part, read like its other local sensors
  chosen,      ///< those, and three more on each part whose gene is photosensitive (Sims)
};

/// Which of the two faces meeting at a joint gives its strength (genome.strength_section).
enum class StrengthSection : std::uint8_t {
  smaller,  ///< the smaller of the two faces meeting at the joint (cambrian's first choice)
  larger,   ///< the larger: Chaumont et al.'s "cross section of the bigger block", after Sims
};

/// Limits that keep creatures finite. Defaults follow Chaumont et al. and Sims.
struct GenomeLimits {
  int max_nodes = 20;           ///< genes (graph nodes)
  int max_connections = 40;     ///< connections in the graph
  int max_parts = 30;           ///< part instances after development
  int max_recursive_limit = 8;  ///< per node
  int max_neurons_per_node = 6;
  int max_brain_neurons = 8;
  int max_inputs = 3;                            ///< inputs stored per neuron
  double min_part_size = 0.05;                   ///< metres, any box side after development
  double max_part_size = 1.5;                    ///< metres, any box side after development
  double min_density = 200, max_density = 3000;  ///< kg / m^3
  double max_weight = 5;                         ///< |weight| of an input
  double max_scale = 2, min_scale = 0.5;
  double max_frequency = 4;  ///< Hz, oscillators and joint controllers
  /// Bit t set: JointType t may appear (genome.joint_types); Chaumont et al. allow only the
  /// one-degree-of-freedom types. Random genomes and every operator keep to it.
  std::uint8_t joint_types = 0xF;
  /// The neuron functions random genomes and mutation draw from and validation accepts; the
  /// chaumont set also bounds every signal of the network to +-1.
  NeuronSet neuron_set = NeuronSet::sims;
  /// Each part's contact sensors.
  ContactSensors contact_sensors = ContactSensors::per_part;
  /// The cross-section each joint's strength is proportional to (physics.strength_per_area).
  StrengthSection strength_section = StrengthSection::smaller;
  /// The parts with photosensors.
  Photosensors photosensors = Photosensors::root;
  /// Chaumont et al.'s catapults: every genome carries a ProjectileGene; the root is the arm
  /// that holds the projectile and lets go of it after `release_delay` controller steps, or
  /// earlier when the network's signal says so.
  bool catapult = false;
  /// Mutation may change the projectile's size and shape (Chaumont et al.: in some runs).
  bool projectile_mutation = false;
  /// With projectile_mutation, mutation may change its density too (not in Chaumont et al.).
  bool projectile_density_mutation = false;
  double projectile_side = 0.2;       ///< m, the side of a random genome's cubic projectile
  double projectile_density = 1000;   ///< kg / m^3, a random genome's projectile
  double projectile_min_side = 0.05;  ///< m, any side of a projectile, its own range
  double projectile_max_side = 1.5;   ///< m
  int release_delay = 30;             ///< controller steps until the projectile is let go at last
  /// The kind of joint controller random connections get (Minemonics: one kind per run).
  JointControllerKind joint_controller = JointControllerKind::sine;
  /// The chance a random connection has its joint controller on (Minemonics: every joint).
  double joint_controller_chance = 0.25;
  /// Every chaotic joint controller's circuit: the Chua constants, the limiter and the rate.
  ChuaCircuit chua;
  /// Minemonics' morphogenes: random genes and mutation draw shapes (box or capsule), friction,
  /// restitution, joint anchors, segment shrink, joint damping and the flip and mirror flags;
  /// without it they keep their defaults (any genome may still carry them).
  bool morphogenes = false;
  double min_friction = 0.2, max_friction = 2;      ///< a part's friction
  double min_restitution = 0, max_restitution = 1;  ///< a part's restitution, when not the world's
  double min_shrink = 0.34, max_shrink = 3;  ///< segment shrink (Minemonics: 1 - 0.66 .. 1 + 2)
  /// a joint's own damping, N m s / rad (Minemonics: 0.001 .. 0.5)
  double min_joint_damping = 0.001, max_joint_damping = 0.5;
};

//---------------------------------------------------------------- operations

/// A random genome within `limits`, drawn from `rng`-compatible stream (seed, generation,
/// individual).
Genome randomGenome(const GenomeLimits& limits, std::uint64_t seed, std::uint64_t generation = 0,
                    std::uint64_t individual = 0);

/// Checks structure and ranges; throws GenomeError naming the gene and field.
void validateGenome(const Genome& genome, const GenomeLimits& limits);

/// Current version of the byte format (2: a catapult's projectile after the brain; 3: chaotic
/// joint controllers; 4: morphogene fields after the projectile; 5: each node's photosensitive
/// flag after those). Readers accept this and older versions; a genome is written in the oldest
/// version that carries it (1 without a projectile, a chaotic controller, a morphogene field or a
/// photosensitive node).
constexpr std::uint32_t kGenomeFormatVersion = 5;

/// The tag that starts the byte form.
constexpr std::array<char, 4> kGenomeTag = {'C', 'M', 'B', 'G'};

/// Versioned little-endian byte serialization (what MPI messages and HDF5 files carry).
std::vector<std::uint8_t> serializeGenome(const Genome& genome);
/// Inverse of serializeGenome; throws InputError naming the field on truncated or bad bytes.
Genome deserializeGenome(const std::uint8_t* bytes, std::size_t size);

/// Current version of the text form ("cambrian-genome 2"). Version 2 ends with an `end`
/// statement, so a truncated file is detected; version 1 (no `end`) is still read.
constexpr int kGenomeTextVersion = 2;

/// Readable text form (docs/genome.md), version kGenomeTextVersion; exact:
/// parseGenomeText(genomeToText(g)) == g.
std::string genomeToText(const Genome& genome);
/// Parses the text form (versions 1 and 2); throws InputError naming `source`, the line and the
/// field, and for a version-2 text without its final `end`, that it may be truncated.
Genome parseGenomeText(const std::string& text, const std::string& source = "<text>");

/// The axis of the parent's face a connection at `position` attaches to: the index of the
/// largest |position_k|, ties to the lowest k.
int dominantAxis(Vec3 position);

/// Develops a genome (embryogenesis): walks the graph from node 0 with recursive limits,
/// reflections and scaling; instantiates sensors, neurons and effectors and wires them as
/// Sims describes. Deterministic. Sizes are clamped to limits; development stops at
/// limits.max_parts parts (breadth-first), setting `truncated`. The controller is the nested
/// network, plus the joint oscillators when any connection enables one.
Creature develop(const Genome& genome, const GenomeLimits& limits);

/// Whether any gene holds a morphogene field (a capsule among them) other than its default, bit
/// for bit (a -0 counts), so that the forms that leave defaults out lose nothing.
bool hasMorphogeneFields(const Genome& genome);
/// Whether `a` and `b` have the same bits.
inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
/// Whether every component of `a` and `b` has the same bits.
inline bool sameBits(Vec3 a, Vec3 b) {
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

/// The directed-graph genome held by a genotype (GenomeError when it is of another encoding).
const Genome& graphGenome(const Genotype& genotype);

}  // namespace cambrian::graph
