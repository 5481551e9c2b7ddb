// cambrian: the settings of the physical world an evaluation runs in ([physics] keys).
#pragma once

#include <cstdint>
#include <string>

namespace cambrian {

class SettingsSchema;

/// How effector commands move the joints.
/// The rigid-body world's constraint solver (physics.constraint_solver).
enum class ConstraintSolver : std::uint8_t {
  sequential_impulse,  ///< Bullet's iterative projected Gauss-Seidel
  dantzig,             ///< Bullet's MLCP solver with Dantzig pivoting (ODE's dWorldStep)
};

enum class Actuation : std::uint8_t {
  /// Chaumont et al. 5.3: a velocity motor run at saturation. The command's sign picks the
  /// direction of a fixed, high target speed and its magnitude the largest torque the motor may
  /// use (|command| * strength); the constraint solver applies it implicitly with the contacts.
  saturated_motor,
  /// Sims: the command times the strength is applied as an explicit joint torque.
  torque,
};

/// The physical world an evaluation runs in. Units: SI.
struct PhysicsSettings {
  std::string world = "featherstone";  ///< the world backend (a registered World)
  double time_step = 1.0 / 240.0;  ///< s, fixed: sensors, controller and monitors run at this rate
  /// Bullet steps per time step (1: about half the cost, not converged; see
  /// docs/physics-and-tasks.md, "Converged, cheap defaults")
  int substeps = 2;
  double gravity = 9.81;         ///< m / s^2, pointing down (-z)
  double ground_friction = 1.0;  ///< Coulomb coefficient of the ground
  double restitution = 0.0;      ///< of the ground and of parts whose material sets none
  double joint_damping = 0.05;   ///< N m s / rad, passive damping on every joint
  /// The joint damping solved implicitly (backward Euler over all the body's joint coordinates
  /// at once, before the contacts and limits: impulse = -damping x step x the speed after it), so
  /// it can only take energy out. Off (what runs stored before this key used): an explicit torque
  /// of -damping x the velocity before the step, which reverses a light limb's velocity each step
  /// and makes a passive body creep (docs/physics-and-tasks.md, "No motion from nothing").
  bool implicit_damping = true;
  double strength_per_area = 2000;  ///< N m of torque per m^2 of a joint's cross-section
  Actuation actuation = Actuation::saturated_motor;  ///< how commands move the joints
  double motor_speed = 10;                           ///< rad / s, target speed of a saturated motor
  /// Whether a creature's parts collide with each other while it moves, joint neighbours excepted
  /// (Sims), or only with the ground and objects (Walking with Dinosaurs; Chaumont et al. test
  /// self-overlap at birth only). Overlap at birth is rejected either way.
  bool self_collision = true;
  /// A joint breaks once it carries more than this times its strength, and the evaluation ends
  /// `dismembered` (the rigid-body world: Bullet's breaking impulse on any row of the joint, per
  /// substep; featherstone: the norm of its muscle plus limit torques); 0: joints never break.
  /// Walking with Dinosaurs: "Tensiles are 5% stronger than muscle" (1.05).
  double joint_breaking = 0;
  /// Contacts keep the point where they began while their friction force stays inside the
  /// friction cone (Bullet's friction anchors), so a body at rest stays where it is. Off (Bullet's
  /// default, and what runs stored before this key used): resting contacts slip a little every step
  /// and a passive body creeps, which evolution selects for (docs/physics-and-tasks.md, "No motion
  /// from nothing").
  bool friction_anchors = true;
  /// A part meeting the ground gets a contact at each of its touching corners from the first
  /// step (Bullet's plane-convex multipoint), not one new point a step. Off (the default, and
  /// Bullet's): better converged at 2 substeps (docs/physics-and-tasks.md, "Converged, cheap
  /// defaults"); on: a box dropped flat lands flat even at 1 substep.
  bool ground_contact_corners = false;
  /// m of overlap a contact keeps without correction: only deeper overlap is pushed apart, so a
  /// resting contact is not pushed out and dropped back every step (Box2D's linear slop).
  double contact_slop = 0.001;
  /// Bullet's integrator changes a multibody's momentum when only its joints move (the map from
  /// joint speeds to momentum moves with the body within a step), so a wriggling body drifts and
  /// spins though nothing outside pushes it: a snake 0.36 m in 4.5 s in a vacuum at the defaults.
  /// On: in a world where every outside force is known — no ground, no objects (water) — the
  /// body's linear and angular momentum after each Bullet step are set to what gravity and the
  /// fluid gave it, and its centre of mass to where that momentum carried it
  /// (docs/physics-and-tasks.md, "No swimming in a vacuum"). On the ground the contacts hold it.
  bool momentum_correction = true;
  /// The Featherstone world solves the motor and the limits of every degree of freedom. Off (what
  /// runs stored before this key used): the middle degree of freedom of a spherical joint has
  /// neither — it turns freely whatever its command — because Bullet solves a multibody
  /// constraint only in the island of a link that carries a collider, and that one's link and
  /// parent are both collider-less virtual links (docs/physics-and-tasks.md, "Every degree of
  /// freedom solved").
  bool solve_every_dof = true;
  /// Share of a joint's position error (a limit passed; in the rigid-body world also the parts
  /// drifting apart at a joint) removed per Bullet step (Bullet's erp). The correction adds
  /// velocity, so it can add energy: in the rigid-body world, strong joints on light parts gain
  /// energy through it (docs/performance.md, "The two worlds").
  double joint_erp = 0.2;
  /// Share of a contact's overlap (beyond contact_slop) removed per Bullet step (Bullet's erp2).
  double contact_erp = 0.2;
  /// ODE's global constraint force mixing, m/(N s), as at a step of time_step: the rigid-body
  /// world makes every joint, motor, limit, contact and friction row a spring and damper
  /// (stiffness global_erp / (time_step global_cfm), damping (1 - global_erp) / global_cfm), the
  /// same at any substeps, and global_erp then replaces joint_erp and contact_erp. The springy
  /// organisms' thesis ran ODE at "CFM (global) 0.01". 0: rigid rows (Bullet's).
  double global_cfm = 0;
  /// ODE's global error reduction, with global_cfm the rows' stiffness (ODE's default 0.2)
  double global_erp = 0.2;
  /// The rigid-body world's constraint solver: "sequential_impulse" (Bullet's iterative
  /// projected Gauss-Seidel, solver_iterations sweeps) or "dantzig" (Bullet's MLCP solver with
  /// its Dantzig pivoting: every row of a step solved together and exactly, as ODE's dWorldStep
  /// does; a step it cannot solve falls back to sequential impulses). Dantzig needs global_cfm's
  /// soft rows: with rigid ones a contact's corners or a closed loop make the matrix singular.
  ConstraintSolver constraint_solver = ConstraintSolver::sequential_impulse;
  int solver_iterations = 20;  ///< the most constraint solver iterations per Bullet step
  /// m/s: the solver stops iterating once no constraint row changes a velocity by more than this
  /// in an iteration (Bullet's least-squares residual threshold); 0: always solver_iterations.
  /// 1e-4: a resting contact keeps at most 0.1 mm/s, so a body at rest creeps under 1 mm in 10 s
  double solver_tolerance = 1e-4;
  double max_speed = 50;          ///< m / s: any part faster has exploded
  double max_displacement = 100;  ///< m: any part farther from its start has exploded
  /// rad/s (prismatic: m/s): a joint turning faster has exploded (Minemonics discards creatures
  /// of "very high joint velocities"); 0: not watched. Less than joint_speed_clamp.
  double max_joint_speed = 0;
  /// rad/s (prismatic: m/s; also m/s and rad/s for the root's velocity and spin): the Featherstone
  /// world's multibody holds every coordinate's speed to this when the solver's impulses are
  /// applied (btMultiBody's coordinate velocity clamp). The clamp does not conserve momentum: a
  /// limb driven into its limit or the ground at the clamp pushes the body with nothing. Runs
  /// stored before this key used Bullet's 100 rad/s, which evolution under explicit torques
  /// reached in every step of a stroke and rode 95 m in 10 s (docs/physics-and-tasks.md, "No push
  /// from the speed clamp").
  double joint_speed_clamp = 1000;
  /// rad/s: a part turning faster has exploded (the springy organisms' "maximal allowed angular
  /// velocity"); 0: not watched
  double max_angular_speed = 0;
  /// m: a joint whose two pivots have come further apart than this has status joint_error (the
  /// springy organisms' "maximal allowed joint error"); 0: not watched
  double max_joint_error = 0;
  /// hits per second: more new touches between the creature's own parts over the last simulated
  /// second give status self_contact (the springy organisms' "maximal allowed contacts");
  /// negative: not watched
  double max_contact_rate = -1;
  double penetration_tolerance = 0.002;  ///< m of overlap allowed between non-adjacent parts at
                                         ///< birth
  double max_wall_seconds = 60;          ///< wall-clock bound of one evaluation (0 = none)
  /// Largest rise of the body's mechanical energy that gravity and the effectors do not explain,
  /// in units of its weight times its length (m 9.81 m/s^2 L); more ends the evaluation as
  /// exploded. The effectors' share is bounded by torque limit x |command| x |joint speed|.
  /// 0: not watched.
  double max_energy_gain = 1.0;

  /// Declares the [physics] keys, bound to this object, with their ranges.
  void declareSettings(SettingsSchema& schema);
};

/// Bullet's scalar type in this build: "float64" (the float64 package, the default) or
/// "float32"; recorded in every history (bullet_precision), since results depend on it.
const char* bulletPrecision();

}  // namespace cambrian
