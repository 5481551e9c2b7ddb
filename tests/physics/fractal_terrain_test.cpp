// Tests of the fractal terrain: Perlin's gradient noise is 0 on the lattice, bounded and seeded;
// the octave sum is what its definition says; the origin's sample is at z = 0.
#include "physics/fractal_terrain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace cambrian {
namespace {

TEST(FractalTerrain, NoiseIsZeroOnTheLatticeAndBoundedBetween) {
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      EXPECT_EQ(gradientNoise(7, x, y), 0.0);
  // a 2D gradient noise of unit gradients never exceeds sqrt(2) / 2 in magnitude
  double largest = 0;
  for (int i = 0; i < 4000; ++i) {
    double x = 0.37 * i, y = 0.113 * i * i / 100.0;
    largest = std::max(largest, std::abs(gradientNoise(7, x, y)));
  }
  EXPECT_LE(largest, std::sqrt(2.0) / 2);
  EXPECT_GT(largest, 0.2);  // not flat
}

TEST(FractalTerrain, TheSameSeedGivesTheSameHeightsAnotherSeedOthers) {
  FractalTerrain terrain;
  const auto a = fractalHeights(terrain, 33, 0.5);
  EXPECT_EQ(a, fractalHeights(terrain, 33, 0.5));
  terrain.seed = 2;
  EXPECT_NE(a, fractalHeights(terrain, 33, 0.5));
}

TEST(FractalTerrain, TheOriginIsAtZeroAndHeightsScaleWithHeight) {
  FractalTerrain terrain;
  const int n = 41;
  const auto unit = fractalHeights(terrain, n, 0.5);
  EXPECT_EQ(unit[(n / 2) * n + n / 2], 0.0);  // the middle sample lies at the origin
  terrain.height = 3;
  const auto tall = fractalHeights(terrain, n, 0.5);
  for (std::size_t i = 0; i < unit.size(); ++i)
    EXPECT_NEAR(tall[i], 3 * unit[i], 1e-12);
  // each octave is at most sqrt(2)/2 high, so the sum of octaves k (each alpha^-k) is bounded
  double bound = 0;
  for (int k = 0; k < terrain.octaves; ++k)
    bound += std::pow(terrain.alpha, -k);
  bound *= 2 * std::sqrt(2.0) / 2 * terrain.height;  // minus the origin's, as high again
  for (double h : tall)
    EXPECT_LE(std::abs(h), bound);
}

TEST(FractalTerrain, OneOctaveIsOneNoiseOfTheCycle) {
  // one octave: height x (noise(origin + p / cycle) - noise(origin)); a cycle apart along a row,
  // samples of a cycle-periodic lattice differ, but halving the cycle doubles the hills' pace
  FractalTerrain terrain;
  terrain.octaves = 1;
  terrain.cycle = 4;
  const auto coarse = fractalHeights(terrain, 17, 0.5);  // 8 m across, two cycles
  terrain.cycle = 2;
  const auto fine = fractalHeights(terrain, 33, 0.25);  // 8 m across at half the spacing
  // the fine grid's sample (c, r) lies at half the coarse grid's (c, r) position: with half the
  // cycle it sees the same noise point
  for (int r = 0; r < 17; ++r)
    for (int c = 0; c < 17; ++c)
      EXPECT_NEAR(fine[(r + 8) * 33 + (c + 8)], coarse[r * 17 + c], 1e-12);
}

TEST(FractalTerrain, HigherOctavesAddSmallerFinerHills) {
  FractalTerrain terrain;
  terrain.octaves = 1;
  const auto smooth = fractalHeights(terrain, 65, 0.25);
  terrain.octaves = 10;
  const auto rough = fractalHeights(terrain, 65, 0.25);
  // neighbouring samples differ more with finer octaves, and the sum stays near the first
  double smooth_steps = 0, rough_steps = 0, apart = 0;
  for (int r = 0; r < 65; ++r)
    for (int c = 1; c < 65; ++c) {
      smooth_steps += std::abs(smooth[r * 65 + c] - smooth[r * 65 + c - 1]);
      rough_steps += std::abs(rough[r * 65 + c] - rough[r * 65 + c - 1]);
    }
  for (std::size_t i = 0; i < smooth.size(); ++i)
    apart = std::max(apart, std::abs(rough[i] - smooth[i]));
  EXPECT_GT(rough_steps, smooth_steps);
  EXPECT_LT(apart, terrain.height * 2 * std::sqrt(2.0) / 2 / (terrain.alpha - 1));
}

}  // namespace
}  // namespace cambrian
