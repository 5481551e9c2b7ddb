// cambrian: random genes, shared by randomGenome and the mutation operators.
#pragma once

#include "cambrian/rng.hpp"

#include "encodings/directed_graph/genome.hpp"

namespace cambrian::graph {

/// A random input wire: any source, small slot and index, |weight| <= min(2, max_weight).
NeuronInput randomNeuronInput(const GenomeLimits& limits, Rng& rng);

/// A random neuron of any function with min(arity, max_inputs) random inputs.
NeuronGene randomNeuronGene(const GenomeLimits& limits, Rng& rng);

/// A random part gene of moderate size: any joint type, 0..3 neurons (within limits), one
/// effector per degree of freedom, usually wired to one of its neurons.
PartGene randomPartGene(const GenomeLimits& limits, Rng& rng);

/// A random connection from -> to: position anywhere, moderate orientation and scale,
/// reflection sometimes, terminal-only and joint controller sometimes.
ConnectionGene randomConnectionGene(std::uint16_t from, std::uint16_t to,
                                    const GenomeLimits& limits, Rng& rng);

/// A random joint controller, on, of limits.joint_controller's kind: a sine of moderate amplitude
/// and frequency; or a chaotic one started in Minemonics' box (each of x y z in +-0.5) at a speed
/// half the time below 1, half above (Minemonics' 0.001..1 and 1..10).
JointControllerGene randomJointController(const GenomeLimits& limits, Rng& rng);

/// A catapult's projectile (GenomeLimits::catapult): held anywhere on the arm, with a random
/// release wire; a cube of limits.projectile_side and projectile_density, or with
/// projectile_mutation a random block within the projectile's size range (and a random density
/// with projectile_density_mutation).
ProjectileGene randomProjectileGene(const GenomeLimits& limits, Rng& rng);

}  // namespace cambrian::graph
