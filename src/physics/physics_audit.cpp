// cambrian: the rest and energy audits of one body.
#include "physics/physics_audit.hpp"

#include "physics/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace cambrian {

namespace {

// whole steps in `seconds`, at least one
long stepsIn(double seconds, double time_step) {
  return std::max(1L, std::lround(seconds / time_step));
}

// the simulation's status into an audit's
template <class Audit>
void takeStatus(const Simulation& simulation, Audit& audit) {
  audit.status = simulation.status();
  audit.message = simulation.message();
  audit.unexplained = simulation.unexplainedEnergy();
  audit.energy_scale = simulation.energyScale();
}

}  // namespace

RestAudit auditRest(const BodyPlan& plan, const Environment& environment,
                    const PhysicsSettings& physics, const AuditSettings& settings) {
  RestAudit audit;
  Simulation simulation(plan, nullptr, environment, physics);
  const double dt = physics.time_step;

  // settle: until every part has been slower than rest_speed for rest_window in a row
  const long window = stepsIn(settings.rest_window, dt), last = stepsIn(settings.settle_max, dt);
  long resting = 0;
  for (long s = 0; s < last && simulation.status() == EvalStatus::ok && resting < window; ++s) {
    simulation.step(false);
    resting = simulation.fastestPartSpeed() < settings.rest_speed ? resting + 1 : 0;
  }
  audit.at_rest = simulation.status() == EvalStatus::ok && resting >= window;
  audit.rest_time = simulation.time();

  // measure: the centre of mass over two spans of `measure` s (a body still moving is watched
  // for its energy)
  const long measure = stepsIn(settings.measure, dt);
  auto span = [&] {
    const Vec3 start = simulation.centerOfMass();
    for (long s = 0; s < measure && simulation.status() == EvalStatus::ok; ++s)
      simulation.step(false);
    return simulation.centerOfMass() - start;
  };
  const Vec3 first = span();
  audit.creep = std::hypot(first.x, first.y);
  audit.rise = first.z;
  const Vec3 second = span();
  audit.later_creep = std::hypot(second.x, second.y);
  takeStatus(simulation, audit);
  return audit;
}

DrivenAudit auditDriven(const BodyPlan& plan, const ControllerPlan* controller,
                        const Environment& environment, const PhysicsSettings& physics,
                        const AuditSettings& settings) {
  DrivenAudit audit;
  Simulation simulation(plan, controller, environment, physics);
  const double dt = physics.time_step;
  const long settle = stepsIn(0.5, dt), driven = stepsIn(settings.driven, dt);
  for (long s = 0; s < settle + driven && simulation.status() == EvalStatus::ok; ++s)
    simulation.step(s >= settle);
  takeStatus(simulation, audit);
  return audit;
}

}  // namespace cambrian
