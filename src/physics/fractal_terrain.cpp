// cambrian: fractal gradient-noise terrain.
#include "physics/fractal_terrain.hpp"

#include "cambrian/rng.hpp"

#include <array>
#include <cmath>
#include <numeric>

namespace cambrian {

namespace {

constexpr int kCells = 256;  // gradient table size: the noise repeats every 256 cells

// Perlin's tables: a permutation of the cells and a unit gradient per cell, from one seed
struct GradientTable {
  std::array<int, 2 * kCells> permutation{};
  std::array<std::array<double, 2>, kCells> gradient{};
  double origin_x = 0, origin_y = 0;  // where the grid's centre lies in noise space

  explicit GradientTable(std::uint64_t seed) {
    Rng rng(seed, RngPurpose::terrain);
    for (auto& g : gradient) {
      double angle = rng.uniform(0, 2 * M_PI);
      g = {std::cos(angle), std::sin(angle)};
    }
    std::array<int, kCells> order{};
    std::iota(order.begin(), order.end(), 0);
    for (int i = kCells - 1; i > 0; --i)
      std::swap(order[i], order[rng.below(std::uint64_t(i) + 1)]);
    for (int i = 0; i < 2 * kCells; ++i)
      permutation[i] = order[i % kCells];
    origin_x = rng.uniform(0, kCells);
    origin_y = rng.uniform(0, kCells);
  }

  // Perlin's s-curve, lerp and corner dot products
  double noise(double x, double y) const {
    const double fx = std::floor(x), fy = std::floor(y);
    const double rx = x - fx, ry = y - fy;
    const int bx = static_cast<int>(static_cast<long long>(fx) & (kCells - 1));
    const int by = static_cast<int>(static_cast<long long>(fy) & (kCells - 1));
    auto corner = [&](int cx, int cy, double dx, double dy) {
      const auto& g =
          gradient[permutation[permutation[(bx + cx) & (kCells - 1)] + ((by + cy) & (kCells - 1))]];
      return g[0] * dx + g[1] * dy;
    };
    auto curve = [](double t) { return t * t * (3 - 2 * t); };
    auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
    const double sx = curve(rx), sy = curve(ry);
    const double low = lerp(sx, corner(0, 0, rx, ry), corner(1, 0, rx - 1, ry));
    const double high = lerp(sx, corner(0, 1, rx, ry - 1), corner(1, 1, rx - 1, ry - 1));
    return lerp(sy, low, high);
  }
};

}  // namespace

double gradientNoise(std::uint64_t seed, double x, double y) {
  return GradientTable(seed).noise(x, y);
}

std::vector<double> fractalHeights(const FractalTerrain& terrain, int samples, double spacing) {
  const GradientTable table(terrain.seed);
  const double half = (samples - 1) / 2.0;
  auto at = [&](double x, double y) {
    double sum = 0, scale = 1, px = x / terrain.cycle, py = y / terrain.cycle;
    for (int octave = 0; octave < terrain.octaves; ++octave) {
      sum += table.noise(table.origin_x + px, table.origin_y + py) / scale;
      scale *= terrain.alpha;
      px *= terrain.beta;
      py *= terrain.beta;
    }
    return sum * terrain.height;
  };
  std::vector<double> heights(static_cast<std::size_t>(samples) * samples);
  for (int r = 0; r < samples; ++r)
    for (int c = 0; c < samples; ++c)
      heights[static_cast<std::size_t>(r) * samples + c] =
          at((c - half) * spacing, (r - half) * spacing);
  const double origin = at(0, 0);
  for (double& h : heights)
    h -= origin;
  return heights;
}

}  // namespace cambrian
