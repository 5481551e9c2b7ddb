// cambrian: the hills environment.
#include "physics/hills_environment.hpp"

#include "core/settings.hpp"

#include <cmath>

namespace cambrian {

std::unique_ptr<EnvironmentKind> HillsEnvironment::clone() const {
  return std::make_unique<HillsEnvironment>(*this);
}

void HillsEnvironment::declareSettings(SettingsSchema& s) {
  auto positive = [](const double& value) {
    return [&value] { return value > 0 && std::isfinite(value); };
  };
  s.add("environment.hill_size", size,
        "hills: side of the square terrain, m (centred on the start)")
      .require(positive(size), "must be > 0 and finite");
  s.add("environment.hill_spacing", spacing, "hills: m between the terrain's height samples")
      .require([this] { return spacing > 0 && std::isfinite(spacing) && size / spacing <= 4096; },
               "must be > 0, finite and at most 4096 samples along hill_size");
  s.add("environment.hill_cycle", terrain.cycle,
        "hills: m, the period of the coarsest noise octave (the hills' width)")
      .require(positive(terrain.cycle), "must be > 0 and finite");
  s.add("environment.hill_height", terrain.height,
        "hills: m, the coarsest octave's amplitude (the noise spans about +-0.7 of it)")
      .require([this] { return terrain.height >= 0 && std::isfinite(terrain.height); },
               "must be >= 0 and finite");
  s.add("environment.hill_alpha", terrain.alpha,
        "hills: each octave's amplitude divided by this (Minemonics 3.3)")
      .require([this] { return terrain.alpha >= 1 && std::isfinite(terrain.alpha); },
               "must be >= 1 and finite");
  s.add("environment.hill_beta", terrain.beta,
        "hills: each octave's frequency multiplied by this (Minemonics 2.2)")
      .require([this] { return terrain.beta >= 1 && std::isfinite(terrain.beta); },
               "must be >= 1 and finite");
  s.add("environment.hill_octaves", terrain.octaves, "hills: noise octaves summed (Minemonics 10)")
      .require([this] { return terrain.octaves >= 1 && terrain.octaves <= 30; },
               "must be in 1..30");
  s.addSeed(
      "environment.hill_seed", terrain.seed,
      "hills: the terrain's random seed (every creature of a run stands on the same terrain)");
}

int HillsEnvironment::samples() const {
  return 2 * std::max(1, static_cast<int>(std::lround(size / (2 * spacing)))) + 1;
}

Environment HillsEnvironment::build(const PhysicsSettings& physics) const {
  const int n = samples();
  const Made* made = made_.get();
  if (!made || made->size != size || made->spacing != spacing || made->terrain != terrain) {
    auto heights = std::make_shared<const std::vector<double>>(fractalHeights(terrain, n, spacing));
    made_ = std::make_shared<const Made>(Made{size, spacing, terrain, std::move(heights)});
  }
  Environment environment;
  environment.ground.kind = Ground::Kind::heightfield;
  environment.ground.friction = physics.ground_friction;
  environment.ground.restitution = physics.restitution;
  environment.ground.heightfield.samples = n;
  environment.ground.heightfield.spacing = spacing;
  environment.ground.heightfield.heights = made_->heights;
  // the light 10 m ahead, on the ground there as on the plane
  environment.light = {10, 0, environment.ground.heightAt(10, 0)};
  return environment;
}

}  // namespace cambrian
