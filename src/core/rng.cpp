#include "cambrian/rng.hpp"

#include <Random123/philox.h>

#include <cmath>

namespace cambrian {

Rng::Rng(std::uint64_t seed, RngPurpose purpose, std::uint64_t generation, std::uint64_t individual)
    : key_{seed, static_cast<std::uint64_t>(purpose)},
      generation_(generation),
      individual_(individual) {}

void Rng::refill() {
  // counter = (generation, individual, block of four draws, 0)
  r123::Philox4x64 philox;
  r123::Philox4x64::ctr_type counter = {{generation_, individual_, block_, 0}};
  r123::Philox4x64::key_type key = {{key_[0], key_[1]}};
  r123::Philox4x64::ctr_type out = philox(counter, key);
  for (int i = 0; i < 4; ++i)
    buffer_[i] = out.v[i];
}

std::uint64_t Rng::below(std::uint64_t n) {
  // rejection sampling removes modulo bias
  std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  std::uint64_t x;
  do {
    x = nextU64();
  } while (x >= limit);
  return x % n;
}

double Rng::normal() {
  if (have_spare_normal_) {
    have_spare_normal_ = false;
    return spare_normal_;
  }
  // Box-Muller on (0, 1] x [0, 1)
  double u1 = 1.0 - uniform();
  double u2 = uniform();
  double radius = std::sqrt(-2.0 * std::log(u1));
  double angle = 2.0 * 3.14159265358979323846 * u2;
  spare_normal_ = radius * std::sin(angle);
  have_spare_normal_ = true;
  return radius * std::cos(angle);
}

}  // namespace cambrian
