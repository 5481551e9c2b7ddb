// cambrian: the [physics] keys and their ranges.
#include "physics/physics_settings.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "physics/world.hpp"

#include <cmath>

namespace cambrian {

void PhysicsSettings::declareSettings(SettingsSchema& s) {
  PhysicsSettings& p = *this;
  s.describeSection("physics", "[physics] world");
  s.add("physics.world", p.world, "world backend: " + worldNamesText()).oneOf(worldNames());
  s.add("physics.time_step", p.time_step, "fixed physics step, s")
      .require([&p] { return p.time_step > 0 && p.time_step <= 0.1; }, "must be in (0, 0.1] s");
  s.add("physics.substeps", p.substeps, "Bullet steps per time step (torques re-applied each)")
      .require([&p] { return p.substeps >= 1 && p.substeps <= 100; }, "must be in 1..100");
  s.add("physics.gravity", p.gravity,
        "gravity, m/s^2 (downwards) on the plane (water: environment.net_gravity)")
      .require([&p] { return p.gravity >= 0 && std::isfinite(p.gravity); }, "must be >= 0");
  s.add("physics.ground_friction", p.ground_friction, "ground friction coefficient")
      .require([&p] { return p.ground_friction >= 0 && std::isfinite(p.ground_friction); },
               "must be >= 0");
  s.add("physics.restitution", p.restitution,
        "restitution of the ground and of parts whose material sets none")
      .require([&p] { return p.restitution >= 0 && p.restitution <= 1; }, "must be in [0, 1]");
  s.add("physics.joint_damping", p.joint_damping, "passive joint damping, N m s/rad")
      .require([&p] { return p.joint_damping >= 0 && std::isfinite(p.joint_damping); },
               "must be >= 0");
  s.add("physics.implicit_damping", p.implicit_damping,
        "joint damping solved implicitly, before the contacts (it can only remove energy); "
        "false: an explicit torque from the velocity before the step, which light limbs turn "
        "into jitter and creep")
      .earlierRunsUsed("false");
  s.add("physics.strength_per_area", p.strength_per_area,
        "joint torque per m^2 of the joint's cross-section (the face genome.strength_section "
        "names), N m/m^2")
      .require([&p] { return p.strength_per_area >= 0 && std::isfinite(p.strength_per_area); },
               "must be >= 0");
  s.addChoice("physics.actuation", p.actuation,
              {{"motor", Actuation::saturated_motor}, {"torque", Actuation::torque}},
              "motor (Chaumont: velocity motor at saturation, torque limit from the command) | "
              "torque (Sims: explicit joint torque)");
  s.add("physics.motor_speed", p.motor_speed, "target speed of a saturated motor, rad/s")
      .require([&p] { return p.motor_speed > 0 && std::isfinite(p.motor_speed); }, "must be > 0");
  s.add("physics.self_collision", p.self_collision,
        "parts collide with each other while moving, joint neighbours excepted (Sims); false: "
        "only with the ground and objects (Walking with Dinosaurs). Overlap at birth is rejected "
        "either way");
  s.add("physics.joint_breaking", p.joint_breaking,
        "a joint breaks, ending the evaluation `dismembered`, once it carries more than this "
        "times its strength (Walking with Dinosaurs: 1.05, 'Tensiles are 5% stronger than "
        "muscle'); the rigid-body world: Bullet's breaking impulse on every row of the joint, "
        "featherstone: the norm of the muscle and limit torques; 0: joints never break")
      .require([&p] { return p.joint_breaking >= 0 && std::isfinite(p.joint_breaking); },
               "must be >= 0 and finite");
  s.add("physics.friction_anchors", p.friction_anchors,
        "contacts hold their point while inside the friction cone (Bullet friction anchors): a "
        "body at rest stays at rest; false: Bullet's default, resting contacts creep")
      .earlierRunsUsed("false");
  s.add("physics.ground_contact_corners", p.ground_contact_corners,
        "a part meeting the ground touches it at all its touching corners from the first step "
        "(Bullet's plane-convex multipoint); false: Bullet's default, one new point a step "
        "(converges better at 2 substeps)")
      .earlierRunsUsed("false");
  s.add("physics.momentum_correction", p.momentum_correction,
        "without ground or objects (water): after each Bullet step the body's momentum and angular "
        "momentum are what gravity and the fluid gave it (Bullet's integrator lets a wriggling "
        "body drift and spin by itself); false: Bullet's as they come");
  s.add("physics.solve_every_dof", p.solve_every_dof,
        "the Featherstone world solves the motor and limits of every joint degree of freedom; "
        "false: the middle one of a spherical joint has neither (a fault of earlier runs: it "
        "turns freely)")
      .earlierRunsUsed("false");
  s.add("physics.contact_slop", p.contact_slop,
        "overlap a contact keeps uncorrected, m (only deeper overlap is pushed apart)")
      .require([&p] { return p.contact_slop >= 0 && p.contact_slop <= 0.1; },
               "must be in [0, 0.1] m")
      .earlierRunsUsed("0");
  s.add("physics.joint_erp", p.joint_erp,
        "share of a joint's position error (a passed limit; in the rigid-body world also a joint "
        "coming apart) removed per Bullet step (Bullet's erp)")
      .require([&p] { return p.joint_erp > 0 && p.joint_erp <= 1; }, "must be in (0, 1]");
  s.add("physics.contact_erp", p.contact_erp,
        "share of a contact's overlap beyond the slop removed per Bullet step (Bullet's erp2)")
      .require([&p] { return p.contact_erp >= 0 && p.contact_erp <= 1; }, "must be in [0, 1]");
  s.add("physics.global_cfm", p.global_cfm,
        "ODE's global constraint force mixing at physics.time_step, m/(N s): the rigid-body "
        "world's joint, motor, contact and friction rows become springs of stiffness "
        "global_erp / (time_step global_cfm) and dampers of (1 - global_erp) / global_cfm, the "
        "same at any substeps (physics.global_erp then replaces joint_erp and contact_erp); 0: "
        "rigid rows")
      .require([&p] { return p.global_cfm >= 0 && p.global_cfm <= 1; }, "must be in [0, 1]")
      .require([&p] { return p.global_cfm == 0 || p.world == "rigid_bodies"; },
               "is built in physics.world = rigid_bodies only (0 elsewhere)");
  s.add("physics.global_erp", p.global_erp,
        "ODE's global error reduction at physics.time_step: with physics.global_cfm the rows' "
        "stiffness")
      .require([&p] { return p.global_erp > 0 && p.global_erp < 1; }, "must be in (0, 1)");
  s.addChoice("physics.constraint_solver", p.constraint_solver,
              {{"sequential_impulse", ConstraintSolver::sequential_impulse},
               {"dantzig", ConstraintSolver::dantzig}},
              "the rigid-body world's constraint solver: sequential_impulse (Bullet's iterations, "
              "physics.solver_iterations of them) | dantzig (all rows of a step solved together "
              "and exactly by Bullet's MLCP solver, as ODE's dWorldStep does, with "
              "physics.global_cfm's soft rows; a step it cannot solve falls back to sequential "
              "impulses)")
      .require(
          [&p] {
            return p.constraint_solver != ConstraintSolver::dantzig || p.world == "rigid_bodies";
          },
          "dantzig is built in physics.world = rigid_bodies only")
      .require(
          [&p] { return p.constraint_solver != ConstraintSolver::dantzig || p.global_cfm > 0; },
          "dantzig needs physics.global_cfm > 0 (rigid rows make the matrix of a contact's "
          "corners or a closed loop singular, and nearly every step falls back)");
  s.add("physics.solver_tolerance", p.solver_tolerance,
        "stop iterating once no constraint row changes a velocity by more than this, m/s (0: "
        "always physics.solver_iterations)")
      .require([&p] { return p.solver_tolerance >= 0 && std::isfinite(p.solver_tolerance); },
               "must be >= 0 and finite")
      .earlierRunsUsed("0");
  s.add("physics.solver_iterations", p.solver_iterations,
        "most constraint solver iterations per Bullet step")
      .require([&p] { return p.solver_iterations >= 1 && p.solver_iterations <= 1000; },
               "must be in 1..1000");
  s.add("physics.max_speed", p.max_speed, "a part faster than this has exploded, m/s")
      .require([&p] { return p.max_speed > 0 && std::isfinite(p.max_speed); },
               "must be > 0 and finite");
  s.add("physics.max_displacement", p.max_displacement,
        "a part farther than this from its start has exploded, m")
      .require([&p] { return p.max_displacement > 0 && std::isfinite(p.max_displacement); },
               "must be > 0 and finite");
  s.add("physics.max_joint_speed", p.max_joint_speed,
        "a joint turning faster than this has exploded, rad/s (sliders m/s; 0 = not watched)")
      .require([&p] { return p.max_joint_speed >= 0 && p.max_joint_speed < p.joint_speed_clamp; },
               "must be in [0, physics.joint_speed_clamp) (0 = not watched; no joint turns "
               "faster than the clamp)");
  s.add("physics.joint_speed_clamp", p.joint_speed_clamp,
        "the Featherstone world holds every joint's speed (and the root's velocity and spin) to "
        "this when the solver's impulses are applied, rad/s (sliders m/s); the clamp does not "
        "conserve momentum, so a body held at it is pushed by nothing")
      .require([&p] { return p.joint_speed_clamp > 0 && p.joint_speed_clamp <= 1e6; },
               "must be in (0, 1e6]")
      .earlierRunsUsed("100");
  s.add("physics.max_angular_speed", p.max_angular_speed,
        "a part turning faster than this has exploded, rad/s (0 = not watched)")
      .require([&p] { return p.max_angular_speed >= 0 && std::isfinite(p.max_angular_speed); },
               "must be >= 0 and finite (0 = not watched)");
  s.add("physics.max_joint_error", p.max_joint_error,
        "a turning joint (revolute, universal, spherical) whose pivots part further than this "
        "ends the evaluation with status joint_error, m (0 = not watched)")
      .require([&p] { return p.max_joint_error >= 0 && std::isfinite(p.max_joint_error); },
               "must be >= 0 and finite (0 = not watched)");
  s.add("physics.max_contact_rate", p.max_contact_rate,
        "more new touches between the creature's own parts than this in the last simulated "
        "second end the evaluation with status self_contact, per s (negative = not watched)")
      .require([&p] { return std::isfinite(p.max_contact_rate); }, "must be finite");
  s.add("physics.penetration_tolerance", p.penetration_tolerance,
        "overlap allowed between non-adjacent parts at birth, m")
      .require(
          [&p] { return p.penetration_tolerance >= 0 && std::isfinite(p.penetration_tolerance); },
          "must be >= 0 and finite");
  s.add("physics.max_wall_seconds", p.max_wall_seconds,
        "wall-clock bound of one evaluation, s (0 = none)")
      .require([&p] { return p.max_wall_seconds >= 0 && std::isfinite(p.max_wall_seconds); },
               "must be >= 0 and finite (0 = no bound)");
  s.add("physics.max_energy_gain", p.max_energy_gain,
        "largest rise of the body's mechanical energy not explained by gravity and the "
        "effectors, in units of its weight times its length; more: exploded (0 = not watched)")
      .require([&p] { return p.max_energy_gain >= 0 && std::isfinite(p.max_energy_gain); },
               "must be >= 0 and finite (0 = not watched)")
      .earlierRunsUsed("0");
}

}  // namespace cambrian
