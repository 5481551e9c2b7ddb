// cambrian: hills — a fractal heightfield (Minemonics' hill environment: gradient noise summed
// over octaves) with the plane's friction and restitution; a flat plane under its lowest point
// catches what leaves the terrain.
#pragma once

#include "physics/environment.hpp"
#include "physics/fractal_terrain.hpp"

#include <memory>
#include <vector>

namespace cambrian {

/// Hills: environment.hill_size x hill_size m of fractal terrain (FractalTerrain) sampled every
/// hill_spacing m, centred on the start, the start at z = 0; physics.ground_friction and
/// physics.restitution; the light 10 m along +x, on the ground there.
class HillsEnvironment : public EnvironmentKind {
 public:
  std::unique_ptr<EnvironmentKind> clone() const override;
  std::string name() const override { return "hills"; }
  void declareSettings(SettingsSchema& schema) override;
  Environment build(const PhysicsSettings& physics) const override;

  double size = 64;        ///< m, side of the square terrain
  double spacing = 0.5;    ///< m between samples
  FractalTerrain terrain;  ///< the shape

  /// Samples per side: size / spacing rounded to an even number of squares, plus one.
  int samples() const;

 private:
  // the last terrain made, for the settings it was made with (every evaluation of a run)
  struct Made {
    double size, spacing;
    FractalTerrain terrain;
    std::shared_ptr<const std::vector<double>> heights;
  };
  mutable std::shared_ptr<const Made> made_;
};

}  // namespace cambrian
