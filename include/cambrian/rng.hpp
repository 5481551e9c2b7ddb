// cambrian: the counter-based random generator every random decision goes through.
#pragma once

#include <array>
#include <cstdint>

namespace cambrian {

/// What a stream of random numbers is for; part of the generator's key, so streams never overlap.
enum class RngPurpose : std::uint64_t {
  random_genome = 1,   ///< random creature generation
  initial_population,  ///< seeding and mutating the first generation
  selection,           ///< parent selection
  variation,           ///< mutation, crossover, grafting
  evaluation,          ///< noise inside an evaluation (synthetic task, perturbations)
  terrain,             ///< an environment's terrain (hills)
  migration,           ///< the island model: random topologies, island seeds
  test = 99,           ///< tests only
};

/// Philox4x64-10 (Random123) keyed by (run seed, purpose) and counted by
/// (generation, individual, draw). Same inputs, same numbers: on every machine, rank and order.
/// Distributions are our own (no std:: distributions), so results are portable.
class Rng {
 public:
  Rng(std::uint64_t seed, RngPurpose purpose, std::uint64_t generation = 0,
      std::uint64_t individual = 0);

  /// Next raw 64-bit value (one Philox block yields four; inline: breeding draws thousands).
  std::uint64_t nextU64() {
    const std::uint64_t slot = draw_ % 4;
    if (slot == 0) {
      block_ = draw_ / 4;
      refill();
    }
    ++draw_;
    return buffer_[slot];
  }
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(nextU64() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n); n must be > 0. Unbiased (rejection).
  std::uint64_t below(std::uint64_t n);
  /// Uniform integer in [lo, hi] inclusive.
  int between(int lo, int hi) { return lo + static_cast<int>(below(std::uint64_t(hi - lo) + 1)); }
  /// True with probability p.
  bool bernoulli(double p) { return uniform() < p; }
  /// Standard normal (Box-Muller, our own implementation).
  double normal();
  /// How many 64-bit values this stream has handed out.
  std::uint64_t draws() const { return draw_; }

 private:
  void refill();
  std::array<std::uint64_t, 2> key_;
  std::uint64_t generation_, individual_;
  std::uint64_t block_ = 0;  // which 4-word block is buffered
  std::uint64_t draw_ = 0;
  std::array<std::uint64_t, 4> buffer_{};
  bool have_spare_normal_ = false;
  double spare_normal_ = 0;
};

}  // namespace cambrian
