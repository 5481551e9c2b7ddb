// cambrian: audits of the physics on one body — does a passive body at rest stay at rest, and
// does its mechanical energy stay explained, passive and driven? The measuring instrument of
// `cambrian audit`, of the physics tests and of docs/physics-and-tasks.md ("Physics you can
// trust").
#pragma once

#include "cambrian/body_plan.hpp"
#include "cambrian/controller.hpp"
#include "cambrian/outcome.hpp"

#include "physics/environment.hpp"
#include "physics/physics_settings.hpp"

#include <string>

namespace cambrian {

/// How a body is audited.
struct AuditSettings {
  double settle_max = 10;     ///< s, the longest a passive body may take to come to rest
  double rest_speed = 0.002;  ///< m/s, every part's centre slower than this counts as rest
  double rest_window = 0.25;  ///< s, for this long in a row
  double measure = 10;        ///< s watched after coming to rest (creep), then as long again
  double driven = 10;         ///< s with the controller on (0: no driven run)
};

/// A passive body (controller off, from birth): when it came to rest, how far it crept after,
/// and its energy balance over the whole run.
struct RestAudit {
  EvalStatus status = EvalStatus::ok;  ///< not ok: refused at birth or a monitor ended the run
  std::string message;                 ///< detail for a non-ok status
  bool at_rest = false;  ///< came to rest within settle_max (else: creep is not measured)
  double rest_time = 0;  ///< s after birth when the rest window ended
  double creep = 0;      ///< m, horizontal travel of the centre of mass over `measure` s
  double rise = 0;       ///< m, vertical change of the centre of mass over those s
  /// m, the same travel over the next `measure` s: a real motion (a part turning freely about a
  /// vertical joint, a slow rock) dies out under damping and friction, a numerical drift does not
  double later_creep = 0;
  double unexplained = 0;   ///< Simulation::unexplainedEnergy() at the end, J
  double energy_scale = 0;  ///< Simulation::energyScale(), J
};

/// The same body driven by its controller after a short passive settle: the energy gain its
/// effectors do not explain.
struct DrivenAudit {
  EvalStatus status = EvalStatus::ok;  ///< not ok: refused at birth or a monitor ended the run
  std::string message;                 ///< detail for a non-ok status
  double unexplained = 0;              ///< Simulation::unexplainedEnergy() at the end, J
  double energy_scale = 0;             ///< Simulation::energyScale(), J
};

/// Runs `plan` passive in `environment`: settles until at rest (at most settings.settle_max),
/// then measures its creep over two spans of settings.measure s.
RestAudit auditRest(const BodyPlan& plan, const Environment& environment,
                    const PhysicsSettings& physics, const AuditSettings& settings);

/// Runs `plan` with `controller` on for settings.driven s, after 0.5 s passive.
DrivenAudit auditDriven(const BodyPlan& plan, const ControllerPlan* controller,
                        const Environment& environment, const PhysicsSettings& physics,
                        const AuditSettings& settings);

}  // namespace cambrian
