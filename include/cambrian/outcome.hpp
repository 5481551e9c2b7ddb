// cambrian: what one evaluation of one creature returns.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cambrian {

/// Why an evaluation ended. Anything but `ok` carries the worst fitness.
enum class EvalStatus : std::uint8_t {
  ok = 0,
  invalid_body,      ///< the genome failed validation or developed into nothing usable
  self_penetration,  ///< parts overlap at birth
  exploded,          ///< a part moved faster or farther than physically plausible
  non_finite,        ///< NaN or infinity in the state
  unstable,          ///< the creature never came to rest in a settle phase
  timeout,           ///< the wall-clock bound of one evaluation was exceeded
  failed,            ///< an exception inside the evaluation (message says which)
  joint_error,       ///< a joint came apart further than physics.max_joint_error
  self_contact,      ///< the parts hit each other more often than physics.max_contact_rate
  too_tall,          ///< taller than task.max_height once relaxed (Walking with Dinosaurs)
  dismembered,       ///< a joint broke under more than physics.joint_breaking x its strength
};
/// Number of EvalStatus values.
constexpr int kEvalStatusKinds = 12;

/// Lower-case status name ("self_penetration").
const char* statusName(EvalStatus status);

/// The worst fitness: every task's fitness is >= 0, failures get 0 (as Chaumont et al.).
constexpr double kWorstFitness = 0.0;

/// A named jury measure (e.g. "distance" in metres).
struct Measure {
  std::string name;
  double value = 0;
  friend bool operator==(const Measure&, const Measure&) = default;
};

/// A measure a task declares it reports: stored by name in outcomes, histories and tables.
struct MeasureInfo {
  std::string name;  ///< "distance"
  std::string unit;  ///< "m"
  friend bool operator==(const MeasureInfo&, const MeasureInfo&) = default;
};

/// The result of one evaluation. Everything but wall_seconds is deterministic.
struct Outcome {
  EvalStatus status = EvalStatus::ok;
  double fitness = kWorstFitness;
  std::vector<Measure> measures;
  std::uint64_t steps = 0;  ///< physics steps simulated
  double wall_seconds = 0;
  int parts = 0, joints = 0, neurons = 0;
  std::string message;  ///< human-readable detail for non-ok statuses

  /// Value of the named measure, or NaN when absent.
  double measure(const std::string& name) const;
};

}  // namespace cambrian
