// cambrian: hills as fractal gradient noise (Perlin's 1985 noise summed over octaves), the
// generator Minemonics draws its hill environment with: each octave beta times finer and alpha
// times lower than the one before.
#pragma once

#include <cstdint>
#include <vector>

namespace cambrian {

/// The shape of a fractal terrain.
struct FractalTerrain {
  double cycle = 20;   ///< m: the coarsest octave's noise period (one gradient cell)
  double height = 1;   ///< m: the coarsest octave's amplitude scale (noise in about [-0.7, 0.7])
  double alpha = 3.3;  ///< each octave's amplitude divided by this (Minemonics: 3.3)
  double beta = 2.2;   ///< each octave's frequency multiplied by this (Minemonics: 2.2)
  int octaves = 10;    ///< octaves summed (Minemonics: 10)
  std::uint64_t seed = 1;  ///< the gradients' and the origin's random stream
  friend bool operator==(const FractalTerrain&, const FractalTerrain&) = default;
};

/// Heights of `terrain` on a square grid of `samples` x `samples` points `spacing` m apart,
/// centred on the origin, row after row (Heightfield's layout), shifted so that the origin's
/// sample is at z = 0. The same terrain and grid give the same bits on every machine.
std::vector<double> fractalHeights(const FractalTerrain& terrain, int samples, double spacing);

/// One octave of 2D gradient noise at (x, y) (in gradient cells) with the gradient table and
/// permutation drawn from `seed`; 0 at every integer point. For tests.
double gradientNoise(std::uint64_t seed, double x, double y);

}  // namespace cambrian
