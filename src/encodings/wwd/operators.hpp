// cambrian: Walking with Dinosaurs' operators on the DNA: mutation (each gene drawn anew with
// chance 1/n) and the Mtree crossover (a whole joint subtree or a whole net of one parent put in
// place of one of the same kind in the other, a copied body part turned half about its joint).
#pragma once

#include "encodings/wwd/grammar.hpp"

namespace cambrian {
class Rng;
}

namespace cambrian::wwd {

/// Each gene of `dna` drawn anew (uniform over the gene values) with chance `rate`; a rate <= 0
/// is the seed's 1 / n, n the DNA's length.
Dna mutateDna(const Dna& dna, double rate, Rng& rng);

/// What a crossover moved, for tests and statistics.
struct CrossoverPoint {
  enum class Kind : std::uint8_t { none, joint, subnet, main_net } kind = Kind::none;
  GeneSpan receiver, donor;  ///< the spans replaced and copied
};

/// A child of `receiver` with one Mtree point replaced by one of the same kind of `donor`: a
/// joint and the boxes built on it (its screw turned half: the seed's 180 degree rotation), a
/// joint's subnet, or the main net (main net for main net only: its layer sizes are chosen
/// around another most probable size, so a main net read as a subnet reads otherwise). Points are
/// drawn uniformly among the receiver's, then among the donor's of that kind; the donor's genes
/// read past its end are copied as the zeros read there. Without a point of the kind in the donor,
/// the child is the receiver. `point`, when given, says what moved.
Dna crossDna(const Dna& receiver, const Dna& donor, const GrammarSettings& settings, Rng& rng,
             CrossoverPoint* point = nullptr);

/// The gene turning a screw gene by half a turn.
Gene halfTurn(Gene screw);

}  // namespace cambrian::wwd
