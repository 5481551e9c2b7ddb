// cambrian: step_cost — what one time step of a creature costs when cambrian runs it, against a
// bare, hand-written Bullet loop of the same body (docs/performance.md, "Per-step cost against a
// bare Bullet loop"; jobs/bench/step_cost.sh). The body is a chain of N boxes lying on the
// ground, joined by revolute joints whose axes alternate between pitch and yaw, every joint
// driven by a sine. Three loops step it, interleaved, and each reports microseconds per step:
//   bare      a minimal Bullet program: world, ground plane, the multibody, one joint motor per
//             joint set from the sine once a step; nothing else
//   matched   the bare loop plus what cambrian's world adds inside Bullet: a joint-limit
//             constraint per joint, passive joint damping each substep, and its contact model
//             (friction anchors, contact slop, contact_erp, ground contact corners)
//   cambrian  the same BodyPlan and sine oscillators run through Simulation: sensors (contact
//             readout, joint angles, light), the controller, the world (its collider filter,
//             limits, damping, motors) and the safety monitors
// All three share cambrian's PhysicsSettings (the defaults, or key=value on the command line):
// time step, substeps, solver iterations and tolerance, gravity, ground friction, restitution,
// actuation, motor speed, strength and self-collision; `--bare key=value` changes them for the
// bare loop alone (the usual yardstick: Bullet's 1 substep and 10 iterations). A setting added to
// the Featherstone world later must be mirrored in BareLoop by hand to keep the matched loop equal
// to cambrian's. One is not: the matched loop damps the joints as a Bullet program does, with an
// explicit torque each substep; cambrian solves the damping implicitly (physics.implicit_damping:
// one backward-Euler solve over the body's joint coordinates per substep, which Bullet has no
// class for), so with the default the cambrian loop does that extra work, and
// physics.implicit_damping=false compares like with like.
#include "cambrian/body_plan.hpp"
#include "cambrian/error.hpp"
#include "cambrian/math.hpp"
#include "cambrian/outcome.hpp"

#include "brain/sine_oscillators.hpp"
#include "core/settings.hpp"
#include "physics/environment.hpp"
#include "physics/physics_settings.hpp"
#include "physics/simulation.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace cambrian {
namespace {

// a bad command-line argument; the message names the argument and its value (exit code 2)
class UsageError : public Error {
 public:
  explicit UsageError(const std::string& message) : Error(ExitCode::usage, message) {}
};

constexpr const char* kUsage =
    "usage: cambrian_step_cost [options] [physics.KEY=VALUE ...]\n"
    "Microseconds per time step of a chain of N boxes driven by sines: a bare Bullet loop, the\n"
    "bare loop with cambrian's joint limits, damping and contact model (matched), and cambrian's\n"
    "Simulation.\n"
    "The physics is cambrian's default [physics] unless overridden by KEY=VALUE (e.g.\n"
    "physics.substeps=1 physics.solver_iterations=10); the bare loops mirror it.\n"
    "options:\n"
    "  --parts LIST     part counts of the chains, comma-separated, each 2..100 (2,5,10,20)\n"
    "  --seconds S      simulated seconds per timed block, per loop (2)\n"
    "  --rounds R       timed blocks per loop, interleaved; the median is reported (5)\n"
    "  --warmup S       simulated seconds run before timing (1)\n"
    "  --frequency HZ   frequency of every joint's sine (1)\n"
    "  --loops LIST     which loops: bare,matched,cambrian (all three)\n"
    "  --tsv            one tab-separated row per chain and loop instead of the tables\n"
    "  --bare K=V       change physics setting K for the bare loop alone (repeatable; not the\n"
    "                   time step), e.g. --bare physics.substeps=1\n"
    "  --help           this text\n"
    "exit: 0 every loop ran sound; 1 a loop exploded, stood still or was not born; 2 bad usage\n";

using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------------------------
// the body and its drive, shared by every loop

// the chain's geometry and drive
struct ChainShape {
  Vec3 part_size{0.2, 0.1, 0.1};   // m, every box; the chain lies along x
  double density = 1000;           // kg / m^3: 2 kg a part
  double joint_limit = 1.0;        // rad, symmetric, every joint
  double frequency = 1.0;          // Hz, every joint's sine
  double phase_step = -0.5 * kPi;  // rad between neighbouring joints: a wave running tailwards
};

// whether joint `joint` (0 = between parts 0 and 1) turns about y (pitch, out of the ground
// plane); the others turn about z (yaw)
bool pitches(int joint) {
  return joint % 2 == 0;
}

// N boxes in a row along x, each jointed to the one before at their shared face; sensors as
// development makes them (per part its joint angle and contact, then three photo sensors of the
// root); one effector per joint
BodyPlan chainPlan(int parts, const ChainShape& shape) {
  BodyPlan plan;
  const Vec3 size = shape.part_size;
  for (int i = 0; i < parts; ++i) {
    PartPlan part;
    part.parent = i - 1;
    part.connection = i == 0 ? -1 : 0;
    part.depth = i;
    part.shape = PartShape::box;
    part.size = size;
    part.mass = shape.density * size.x * size.y * size.z;
    part.material.density = shape.density;
    part.pose.position = {i * size.x, 0, 0};
    if (i > 0) {
      part.joint = JointType::revolute;
      part.pivot_in_parent = {0.5 * size.x, 0, 0};
      part.pivot_in_child = {-0.5 * size.x, 0, 0};
      part.axes[0] = pitches(i - 1) ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
      part.joint_limit = {shape.joint_limit, shape.joint_limit, shape.joint_limit};
      part.cross_section = size.y * size.z;
    }
    plan.parts.push_back(part);
  }
  for (int i = 0; i < parts; ++i) {
    if (i > 0)
      plan.sensors.push_back({SensorKind::joint_angle, i, 0});
    plan.sensors.push_back({SensorKind::contact, i, 0});
  }
  for (int axis = 0; axis < 3; ++axis)
    plan.sensors.push_back({SensorKind::photo, 0, axis});
  for (int i = 1; i < parts; ++i)
    plan.effectors.push_back({i, 0});
  return plan;
}

// one sine oscillator per joint: full amplitude, the same frequency, phases a wave apart
SineOscillatorsPlan chainOscillators(int joints, const ChainShape& shape) {
  SineOscillatorsPlan drive;
  for (int j = 0; j < joints; ++j) {
    SineOscillator oscillator;
    oscillator.enabled = true;
    oscillator.amplitude = 1;
    oscillator.frequency = shape.frequency;
    oscillator.phase = j * shape.phase_step;
    drive.oscillators.push_back(oscillator);
  }
  return drive;
}

// an oscillator's command at time t, as SineOscillators::step computes it and Simulation
// clamps it
double sineCommand(const SineOscillator& oscillator, double t) {
  constexpr double kTwoPi = 2 * kPi;
  const double drive =
      oscillator.amplitude * std::sin(kTwoPi * oscillator.frequency * t + oscillator.phase) +
      oscillator.offset;
  return std::clamp(drive, -1.0, 1.0);
}

// ---------------------------------------------------------------------------------------------
// the loops

// rows the multibody solver set up, summed over the solves counted
struct SolverRows {
  std::uint64_t joint = 0;     // motor and joint-limit rows
  std::uint64_t contact = 0;   // contact normals
  std::uint64_t friction = 0;  // friction directions (torsional and spinning included)
};

// Bullet's multibody solver, adding up the rows it set up in each solve (reads four array sizes
// a solve: nothing measurable)
class CountingSolver : public btMultiBodyConstraintSolver {
 public:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* debug_drawer) override {
    const btScalar result = btMultiBodyConstraintSolver::solveGroupCacheFriendlySetup(
        bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info,
        debug_drawer);
    rows.joint += static_cast<std::uint64_t>(m_multiBodyNonContactConstraints.size());
    rows.contact += static_cast<std::uint64_t>(m_multiBodyNormalContactConstraints.size());
    rows.friction +=
        static_cast<std::uint64_t>(m_multiBodyFrictionContactConstraints.size() +
                                   m_multiBodyTorsionalFrictionContactConstraints.size() +
                                   m_multiBodySpinningFrictionContactConstraints.size());
    return result;
  }
  SolverRows rows;
};

// one way of stepping the chain
class ChainLoop {
 public:
  virtual ~ChainLoop() = default;
  // one time step (its substeps), the sine commands included
  virtual void step() = 0;
  // the world position of the chain's first part (the root), m
  virtual Vec3 firstPartPosition() const = 0;
  // "" while the chain is sound; otherwise what went wrong (not born, non-finite, exploded,
  // asleep)
  virtual std::string trouble() const = 0;
  // parts touching anything after the last step, counted as cambrian's contact sensors count
  virtual int touchingParts() = 0;
  // the largest |joint angle| now, rad
  virtual double largestJointAngle() const = 0;
  // the solver rows since the last call; none where the loop cannot see its solver
  virtual std::optional<SolverRows> takeSolverRows() { return std::nullopt; }
};

btVector3 toBt(Vec3 v) {
  return btVector3(v.x, v.y, v.z);
}
btQuaternion toBt(Quat q) {
  return btQuaternion(q.x, q.y, q.z, q.w);
}

// the bare loop (matched = false) and the matched one (true), written against Bullet alone
class BareLoop : public ChainLoop {
 public:
  BareLoop(const BodyPlan& plan, const SineOscillatorsPlan& drive, const PhysicsSettings& physics,
           bool matched);
  ~BareLoop() override;
  BareLoop(const BareLoop&) = delete;
  BareLoop& operator=(const BareLoop&) = delete;

  void step() override;
  Vec3 firstPartPosition() const override { return partPosition(0); }
  std::string trouble() const override;
  int touchingParts() override;
  double largestJointAngle() const override;
  std::optional<SolverRows> takeSolverRows() override {
    SolverRows rows = solver_.rows;
    solver_.rows = {};
    return rows;
  }

 private:
  Vec3 partPosition(int part) const {
    const btVector3& origin = colliders_[part]->getWorldTransform().getOrigin();
    return {origin.x(), origin.y(), origin.z()};
  }

  const BodyPlan& plan_;
  const SineOscillatorsPlan& drive_;
  PhysicsSettings physics_;
  bool matched_;
  std::uint64_t steps_ = 0;
  std::vector<double> max_torque_;  // per joint, N m
  std::vector<Vec3> birth_position_;

  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  CountingSolver solver_;
  btMultiBodyDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  btStaticPlaneShape ground_shape_{btVector3(0, 0, 1), 0};
  btCollisionObject ground_;
  std::vector<std::unique_ptr<btBoxShape>> shapes_;
  std::unique_ptr<btMultiBody> body_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::vector<std::unique_ptr<btMultiBodyJointLimitConstraint>> limits_;
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors_;
};

BareLoop::BareLoop(const BodyPlan& plan, const SineOscillatorsPlan& drive,
                   const PhysicsSettings& physics, bool matched)
    : plan_(plan), drive_(drive), physics_(physics), matched_(matched) {
  const int part_count = static_cast<int>(plan.parts.size());

  // world: gravity, solver iterations (matched: cambrian's contact model), the ground plane
  world_.setGravity(btVector3(0, 0, -physics.gravity));
  world_.getSolverInfo().m_numIterations = physics.solver_iterations;
  world_.getSolverInfo().m_leastSquaresResidualThreshold =
      physics.solver_tolerance * physics.solver_tolerance;
  if (matched_) {
    world_.getSolverInfo().m_erp2 = physics.contact_erp;
    world_.getSolverInfo().m_linearSlop = physics.contact_slop;
    if (physics.ground_contact_corners)
      configuration_.setPlaneConvexMultipointIterations();
  }
  // matched: contacts hold their point inside the friction cone, as cambrian's do
  auto anchor = [&](btCollisionObject& object) {
    if (matched_ && physics.friction_anchors)
      object.setCollisionFlags(object.getCollisionFlags() |
                               btCollisionObject::CF_HAS_FRICTION_ANCHOR);
  };
  ground_.setCollisionShape(&ground_shape_);
  ground_.setFriction(physics.ground_friction);
  ground_.setRestitution(physics.restitution);
  ground_.setUserIndex(-1);
  anchor(ground_);
  world_.addCollisionObject(&ground_, btBroadphaseProxy::StaticFilter,
                            btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);

  // the body's shapes and their inertia; its lowest point on the ground
  std::vector<btVector3> inertia(part_count);
  double lowest = 0;
  for (int i = 0; i < part_count; ++i) {
    const PartPlan& part = plan.parts[i];
    shapes_.push_back(std::make_unique<btBoxShape>(toBt(part.size * 0.5)));
    shapes_.back()->calculateLocalInertia(part.mass, inertia[i]);
    lowest = i == 0 ? lowestZ(part, part.pose) : std::min(lowest, lowestZ(part, part.pose));
  }

  // the multibody: the first box the floating base, one revolute link per further box
  const PartPlan& root = plan.parts[0];
  body_ = std::make_unique<btMultiBody>(part_count - 1, root.mass, inertia[0], false, false);
  body_->setBasePos(toBt(root.pose.position + Vec3{0, 0, -lowest}));
  body_->setWorldToBaseRot(toBt(conjugate(root.pose.rotation)));
  body_->setHasSelfCollision(physics.self_collision);
  body_->setLinearDamping(0);
  body_->setAngularDamping(0);
  body_->setMaxCoordinateVelocity(100);
  for (int i = 1; i < part_count; ++i) {
    const PartPlan& part = plan.parts[i];
    body_->setupRevolute(i - 1, part.mass, inertia[i], part.parent - 1,
                         toBt(conjugate(part.parent_to_child)), toBt(part.axes[0]),
                         toBt(part.pivot_in_parent), toBt(-part.pivot_in_child), true);
    max_torque_.push_back(physics.strength_per_area * part.cross_section);
  }
  body_->finalizeMultiDof();
  world_.addMultiBody(body_.get());

  // one collider per box
  for (int i = 0; i < part_count; ++i) {
    const PartPlan& part = plan.parts[i];
    colliders_.push_back(std::make_unique<btMultiBodyLinkCollider>(body_.get(), i - 1));
    btMultiBodyLinkCollider& collider = *colliders_.back();
    collider.setCollisionShape(shapes_[i].get());
    collider.setFriction(part.material.friction);
    collider.setRestitution(part.material.restitution < 0 ? physics.restitution
                                                          : part.material.restitution);
    collider.setUserIndex(i);
    anchor(collider);
    if (i == 0)
      body_->setBaseCollider(&collider);
    else
      body_->getLink(i - 1).m_collider = &collider;
    world_.addCollisionObject(&collider, btBroadphaseProxy::DefaultFilter,
                              btBroadphaseProxy::AllFilter);
  }

  // matched: a limit constraint on every joint, as cambrian's world adds them
  if (matched_) {
    for (int link = 0; link < part_count - 1; ++link) {
      const double limit = plan.parts[link + 1].joint_limit.x;
      limits_.push_back(
          std::make_unique<btMultiBodyJointLimitConstraint>(body_.get(), link, -limit, limit));
      world_.addMultiBodyConstraint(limits_.back().get());
    }
  }

  // a velocity motor per joint (saturated-motor actuation)
  if (physics.actuation == Actuation::saturated_motor) {
    for (int link = 0; link < part_count - 1; ++link) {
      motors_.push_back(std::make_unique<btMultiBodyJointMotor>(body_.get(), link, 0.0, 0.0));
      world_.addMultiBodyConstraint(motors_.back().get());
    }
  }

  // collider transforms from the birth pose
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  body_->updateCollisionObjectWorldTransforms(world_to_local, local_origin);
  for (int i = 0; i < part_count; ++i)
    birth_position_.push_back(partPosition(i));
}

BareLoop::~BareLoop() {
  for (auto& motor : motors_)
    world_.removeMultiBodyConstraint(motor.get());
  for (auto& limit : limits_)
    world_.removeMultiBodyConstraint(limit.get());
  for (auto& collider : colliders_)
    world_.removeCollisionObject(collider.get());
  world_.removeMultiBody(body_.get());
  world_.removeCollisionObject(&ground_);
}

void BareLoop::step() {
  const double t = static_cast<double>(steps_) * physics_.time_step;
  const double substep = physics_.time_step / physics_.substeps;
  const int joints = static_cast<int>(max_torque_.size());

  // motors: the command's sign picks the target speed, its size the torque budget (kept by the
  // motor through the substeps)
  if (physics_.actuation == Actuation::saturated_motor) {
    for (int j = 0; j < joints; ++j) {
      const double command = sineCommand(drive_.oscillators[j], t);
      motors_[j]->setVelocityTarget(command < 0 ? -physics_.motor_speed : physics_.motor_speed);
      motors_[j]->setMaxAppliedImpulse(std::abs(command) * max_torque_[j] * substep);
    }
  }

  // the substeps; joint torques (damping when matched, torque actuation) are cleared by every
  // Bullet step, so they are applied before each
  for (int k = 0; k < physics_.substeps; ++k) {
    if (matched_) {
      for (int link = 0; link < joints; ++link)
        body_->addJointTorque(link, -physics_.joint_damping * body_->getJointVel(link));
    }
    if (physics_.actuation == Actuation::torque) {
      for (int j = 0; j < joints; ++j)
        body_->addJointTorque(j, sineCommand(drive_.oscillators[j], t) * max_torque_[j]);
    }
    world_.stepSimulation(substep, 0);
  }
  ++steps_;
}

std::string BareLoop::trouble() const {
  // cambrian's monitor rules, looked at now: finite, not too far from birth; and awake
  for (std::size_t i = 0; i < colliders_.size(); ++i) {
    const Vec3 position = partPosition(static_cast<int>(i));
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
      return "non_finite: part " + std::to_string(i);
    if (norm(position - birth_position_[i]) > physics_.max_displacement)
      return "exploded: part " + std::to_string(i) + " beyond physics.max_displacement";
  }
  if (!body_->isAwake())
    return "asleep";
  return "";
}

int BareLoop::touchingParts() {
  // every manifold with a point within 1 mm marks both parts (FeatherstoneWorld::contacts)
  std::vector<std::uint8_t> touching(colliders_.size(), 0);
  for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
    bool touches = false;
    for (int c = 0; c < manifold->getNumContacts() && !touches; ++c)
      touches = manifold->getContactPoint(c).getDistance() <= 0.001;
    if (!touches)
      continue;
    for (const btCollisionObject* object : {manifold->getBody0(), manifold->getBody1()}) {
      if (object->getUserIndex() >= 0)
        touching[object->getUserIndex()] = 1;
    }
  }
  return static_cast<int>(std::count(touching.begin(), touching.end(), 1));
}

double BareLoop::largestJointAngle() const {
  double largest = 0;
  for (int link = 0; link < body_->getNumLinks(); ++link)
    largest = std::max(largest, std::abs(body_->getJointPos(link)));
  return largest;
}

// cambrian's loop: the chain's BodyPlan and its sine oscillators through Simulation
class CambrianLoop : public ChainLoop {
 public:
  CambrianLoop(const BodyPlan& plan, const SineOscillatorsPlan& drive,
               const PhysicsSettings& physics)
      : plan_(plan),
        environment_(PlaneEnvironment().build(physics)),
        simulation_(plan, &drive, environment_, physics) {}

  void step() override { simulation_.step(true); }
  Vec3 firstPartPosition() const override { return simulation_.world().partPosition(0); }
  std::string trouble() const override {
    if (simulation_.status() == EvalStatus::ok)
      return "";
    return std::string(statusName(simulation_.status())) + ": " + simulation_.message();
  }
  int touchingParts() override {
    // the contact sensors of the last step (read at its start: the contacts one step earlier)
    int touching = 0;
    for (std::size_t s = 0; s < plan_.sensors.size(); ++s) {
      if (plan_.sensors[s].kind == SensorKind::contact && simulation_.sensors()[s] > 0)
        ++touching;
    }
    return touching;
  }
  double largestJointAngle() const override {
    double largest = 0;
    for (std::size_t i = 1; i < plan_.parts.size(); ++i)
      largest =
          std::max(largest, std::abs(simulation_.world().jointPosition(static_cast<int>(i), 0)));
    return largest;
  }

 private:
  const BodyPlan& plan_;
  Environment environment_;
  Simulation simulation_;
};

// ---------------------------------------------------------------------------------------------
// measuring

// the loops, in the order they are built and reported
enum LoopKind { kBare, kMatched, kCambrian, kLoopKinds };
constexpr const char* kLoopNames[kLoopKinds] = {"bare", "matched", "cambrian"};

// one loop of one chain: its timed blocks, its first part's motion, its census
struct LoopRecord {
  std::string name;
  std::unique_ptr<ChainLoop> loop;
  std::vector<double> us_per_step;  // one per timed block
  Vec3 birth, previous;             // the first part's position at birth and after the last step
  double max_speed = 0;             // the first part's, over every step, m/s
  double least_block_path = std::numeric_limits<double>::infinity();  // m, over the timed blocks
  // census (one untimed block after the timing)
  double touching_parts = 0;       // mean per step
  double largest_joint_angle = 0;  // rad
  std::optional<SolverRows> rows;  // summed over the census
  bool rows_from_matched = false;  // cambrian's: the matched loop's, their motions being equal
  std::uint64_t census_steps = 0;
  std::string trouble;
};

// the benchmark's settings
struct Options {
  std::vector<int> parts{2, 5, 10, 20};
  double block_seconds = 2;
  int rounds = 5;
  double warmup_seconds = 1;
  double frequency = 1;
  std::vector<bool> loops = std::vector<bool>(kLoopKinds, true);
  bool tsv = false;
  PhysicsSettings physics;
  PhysicsSettings bare_physics;                // the bare loop's: physics with the --bare changes
  std::vector<std::string> physics_overrides;  // "key=value" as given
  std::vector<std::string> bare_overrides;     // --bare "key=value" as given
};

// `steps` steps of a loop, following its first part; returns the wall time in seconds and adds
// the first part's path to `path`
double runSteps(LoopRecord& record, std::uint64_t steps, double time_step, double& path) {
  ChainLoop& loop = *record.loop;
  const Clock::time_point start = Clock::now();
  for (std::uint64_t s = 0; s < steps; ++s) {
    loop.step();
    const Vec3 position = loop.firstPartPosition();
    const double moved = norm(position - record.previous);
    record.max_speed = std::max(record.max_speed, moved / time_step);
    path += moved;
    record.previous = position;
  }
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// the census: `steps` more steps, counting touching parts, joint angles and solver rows
void runCensus(LoopRecord& record, std::uint64_t steps, double time_step) {
  record.loop->takeSolverRows();
  std::uint64_t touching = 0;
  double path = 0;
  for (std::uint64_t s = 0; s < steps; ++s) {
    runSteps(record, 1, time_step, path);
    touching += static_cast<std::uint64_t>(record.loop->touchingParts());
    record.largest_joint_angle =
        std::max(record.largest_joint_angle, record.loop->largestJointAngle());
  }
  record.census_steps = steps;
  record.touching_parts = steps ? static_cast<double>(touching) / static_cast<double>(steps) : 0;
  record.rows = record.loop->takeSolverRows();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// whole steps in `seconds`
std::uint64_t stepsIn(double seconds, double time_step) {
  return static_cast<std::uint64_t>(std::llround(seconds / time_step));
}

// every selected loop of a chain of `parts` boxes: warm-up, interleaved timed blocks, census
std::vector<LoopRecord> measureChain(int parts, const Options& options) {
  ChainShape shape;
  shape.frequency = options.frequency;
  const BodyPlan plan = chainPlan(parts, shape);
  const SineOscillatorsPlan drive = chainOscillators(parts - 1, shape);
  const PhysicsSettings& physics = options.physics;
  const double dt = physics.time_step;

  // build the loops
  std::vector<LoopRecord> records;
  for (int kind = 0; kind < kLoopKinds; ++kind) {
    if (!options.loops[kind])
      continue;
    LoopRecord record;
    record.name = kLoopNames[kind];
    if (kind == kCambrian)
      record.loop = std::make_unique<CambrianLoop>(plan, drive, physics);
    else
      record.loop = std::make_unique<BareLoop>(
          plan, drive, kind == kMatched ? physics : options.bare_physics, kind == kMatched);
    record.birth = record.previous = record.loop->firstPartPosition();
    record.trouble = record.loop->trouble();
    records.push_back(std::move(record));
  }

  // warm up, then timed blocks, each round starting with the next loop
  double unused_path = 0;
  for (LoopRecord& record : records)
    runSteps(record, stepsIn(options.warmup_seconds, dt), dt, unused_path);
  const std::uint64_t block_steps = std::max<std::uint64_t>(1, stepsIn(options.block_seconds, dt));
  for (int round = 0; round < options.rounds; ++round) {
    for (std::size_t k = 0; k < records.size(); ++k) {
      LoopRecord& record = records[(round + k) % records.size()];
      double path = 0;
      const double seconds = runSteps(record, block_steps, dt, path);
      record.us_per_step.push_back(1e6 * seconds / static_cast<double>(block_steps));
      record.least_block_path = std::min(record.least_block_path, path);
    }
  }

  // census, then the verdict: sound, not too fast, never still
  for (LoopRecord& record : records) {
    runCensus(record, block_steps, dt);
    if (record.trouble.empty())
      record.trouble = record.loop->trouble();
    if (record.trouble.empty() && record.max_speed > physics.max_speed) {
      std::ostringstream message;
      message << "exploded: first part at " << record.max_speed << " m/s";
      record.trouble = message.str();
    }
    // still: neither the first part travelled nor a joint turned (with friction anchors a short
    // chain may flap without its first part sliding)
    if (record.trouble.empty() && record.least_block_path < 1e-4 &&
        record.largest_joint_angle < 0.01)
      record.trouble = "still: the first part moved < 0.1 mm in a timed block, no joint turned";
  }

  // cambrian's solver is out of reach; when its chain ended exactly where the matched loop's did
  // (bit for bit, after thousands of steps: the same motion), its rows are the matched loop's
  LoopRecord* matched = nullptr;
  LoopRecord* cambrian = nullptr;
  for (LoopRecord& record : records) {
    if (record.name == "matched")
      matched = &record;
    if (record.name == "cambrian")
      cambrian = &record;
  }
  if (matched && cambrian && matched->previous == cambrian->previous) {
    cambrian->rows = matched->rows;
    cambrian->census_steps = matched->census_steps;
    cambrian->rows_from_matched = true;
  }

  // the loops hold the plan and the drive, which end here; the records keep what was measured
  for (LoopRecord& record : records)
    record.loop.reset();
  return records;
}

// ---------------------------------------------------------------------------------------------
// the command line and the report

// a number from `text` for option `name`, within [low, high]
double parseNumber(const std::string& name, const std::string& text, double low, double high) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value) || value < low || value > high) {
    std::ostringstream message;
    message << name << " '" << text << "': expected a number in [" << low << ", " << high << "]";
    throw UsageError(message.str());
  }
  return value;
}

// an integer from `text` for option `name`, within [low, high]
int parseInteger(const std::string& name, const std::string& text, int low, int high) {
  const double value = parseNumber(name, text, low, high);
  if (value != std::floor(value)) {
    throw UsageError(name + " '" + text + "': expected a whole number in [" + std::to_string(low) +
                     ", " + std::to_string(high) + "]");
  }
  return static_cast<int>(value);
}

// the words of a comma-separated list
std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> words;
  std::stringstream stream(text);
  std::string word;
  while (std::getline(stream, word, ','))
    words.push_back(word);
  return words;
}

Options parseArguments(int argc, char** argv) {
  Options options;
  SettingsSchema schema;
  options.physics.declareSettings(schema);

  // an option's value: the next argument
  auto valueOf = [&](int& i) -> std::string {
    if (i + 1 >= argc)
      throw UsageError(std::string(argv[i]) + ": needs a value (see --help)");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--parts") {
      const std::string text = valueOf(i);
      options.parts.clear();
      for (const std::string& word : splitList(text))
        options.parts.push_back(parseInteger("--parts", word, 2, 100));
      if (options.parts.empty())
        throw UsageError("--parts '" + text + "': expected part counts like 2,5,10,20");
    } else if (argument == "--seconds") {
      options.block_seconds = parseNumber("--seconds", valueOf(i), 1e-3, 3600);
    } else if (argument == "--rounds") {
      options.rounds = parseInteger("--rounds", valueOf(i), 1, 1000);
    } else if (argument == "--warmup") {
      options.warmup_seconds = parseNumber("--warmup", valueOf(i), 0, 3600);
    } else if (argument == "--frequency") {
      options.frequency = parseNumber("--frequency", valueOf(i), 0, 1000);
    } else if (argument == "--loops") {
      const std::string text = valueOf(i);
      options.loops.assign(kLoopKinds, false);
      for (const std::string& word : splitList(text)) {
        const auto* kind = std::find(std::begin(kLoopNames), std::end(kLoopNames), word);
        if (kind == std::end(kLoopNames)) {
          throw UsageError("--loops '" + text + "': '" + word +
                           "' is not a loop (bare, matched, cambrian)");
        }
        options.loops[kind - std::begin(kLoopNames)] = true;
      }
    } else if (argument == "--tsv") {
      options.tsv = true;
    } else if (argument == "--bare") {
      const std::string change = valueOf(i);
      if (change.find('=') == std::string::npos || change.rfind("physics.", 0) != 0)
        throw UsageError("--bare '" + change + "': expected physics.KEY=VALUE");
      if (change.rfind("physics.time_step=", 0) == 0)
        throw UsageError("--bare '" + change + "': the loops are compared per step of one length");
      options.bare_overrides.push_back(change);
    } else if (argument.find('=') != std::string::npos && argument.rfind("--", 0) != 0) {
      // a physics setting, checked by its own rules
      const std::string key = argument.substr(0, argument.find('='));
      const std::string value = argument.substr(argument.find('=') + 1);
      if (key.rfind("physics.", 0) != 0 || !schema.find(key)) {
        throw UsageError("'" + argument + "': " + key +
                         " is not a [physics] setting (cambrian --help lists them)");
      }
      try {
        schema.set(key, value);
      } catch (const std::exception& e) {
        throw UsageError("'" + argument + "': " + e.what());
      }
      options.physics_overrides.push_back(key + "=" + value);
    } else {
      throw UsageError("unknown argument '" + argument + "' (see --help)");
    }
  }
  try {
    schema.check();
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }

  // the bare loop's physics: the same, with the --bare changes
  options.bare_physics = options.physics;
  SettingsSchema bare_schema;
  options.bare_physics.declareSettings(bare_schema);
  for (const std::string& change : options.bare_overrides) {
    const std::string key = change.substr(0, change.find('='));
    if (!bare_schema.find(key))
      throw UsageError("--bare '" + change + "': " + key + " is not a [physics] setting");
    try {
      bare_schema.set(key, change.substr(change.find('=') + 1));
      bare_schema.check();
    } catch (const std::exception& e) {
      throw UsageError("--bare '" + change + "': " + e.what());
    }
  }
  return options;
}

// "12.3" with one decimal, or "-" for a value that is not there
std::string fixed(double value, int decimals) {
  if (!std::isfinite(value))
    return "-";
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

// the median µs per step of the loop named `name`, or NaN
double medianOf(const std::vector<LoopRecord>& records, const std::string& name) {
  for (const LoopRecord& record : records) {
    if (record.name == name)
      return median(record.us_per_step);
  }
  return std::nan("");
}

// solver rows of one kind per census step (all its substeps), or "-"
std::string rowsPerStep(const LoopRecord& record, std::uint64_t SolverRows::*kind, int decimals) {
  if (!record.rows || record.census_steps == 0)
    return "-";
  return fixed(static_cast<double>((*record.rows).*kind) / static_cast<double>(record.census_steps),
               decimals);
}

// solver rows per census step, "joint+contact+friction", marked when they are the matched loop's
std::string rowsText(const LoopRecord& record) {
  if (!record.rows)
    return "-";
  return rowsPerStep(record, &SolverRows::joint, 1) + "+" +
         rowsPerStep(record, &SolverRows::contact, 1) + "+" +
         rowsPerStep(record, &SolverRows::friction, 1) +
         (record.rows_from_matched ? " (matched's)" : "");
}

double horizontalDistance(const LoopRecord& record) {
  return std::hypot(record.previous.x - record.birth.x, record.previous.y - record.birth.y);
}

void printHeader(const Options& options) {
  const ChainShape shape;
  const PhysicsSettings& p = options.physics;
  const Vec3 size = shape.part_size;
  std::cout << "chain of N boxes " << size.x << " x " << size.y << " x " << size.z << " m ("
            << shape.density * size.x * size.y * size.z
            << " kg each) on the ground, revolute joints alternating pitch/yaw, limits +-"
            << shape.joint_limit << " rad, each driven by a sine of " << options.frequency
            << " Hz\n"
            << "physics: time_step " << p.time_step << " s, substeps " << p.substeps
            << ", solver_iterations " << p.solver_iterations << ", actuation "
            << (p.actuation == Actuation::saturated_motor ? "motor" : "torque") << " ("
            << p.motor_speed << " rad/s, " << p.strength_per_area << " N m/m^2), self_collision "
            << (p.self_collision ? "on" : "off") << ", joint_damping " << p.joint_damping
            << "; cambrian's defaults";
  if (!options.physics_overrides.empty()) {
    std::cout << " except";
    for (const std::string& override_text : options.physics_overrides)
      std::cout << " " << override_text;
  }
  if (!options.bare_overrides.empty()) {
    std::cout << "; the bare loop with";
    for (const std::string& change : options.bare_overrides)
      std::cout << " " << change;
  }
  std::cout << "\ntiming: " << options.warmup_seconds << " s warm-up, then " << options.rounds
            << " rounds x " << options.block_seconds << " s simulated ("
            << std::max<std::uint64_t>(1, stepsIn(options.block_seconds, p.time_step))
            << " steps) per loop, interleaved; median (min-max) us per step\n"
            << "loops: bare = Bullet + motors; matched = bare + cambrian's joint limits, "
               "damping and contact model; cambrian = Simulation (sensors, controller, world, "
               "monitors)\n\n";
}

// "median (min-max)" µs per step of a loop
std::string timingText(const LoopRecord& record) {
  const auto [low, high] =
      std::minmax_element(record.us_per_step.begin(), record.us_per_step.end());
  return fixed(median(record.us_per_step), 1) + " (" + fixed(*low, 1) + "-" + fixed(*high, 1) + ")";
}

std::string statusText(const LoopRecord& record) {
  return record.trouble.empty() ? "ok" : record.trouble;
}

void printTables(const Options& options, const std::vector<std::vector<LoopRecord>>& chains) {
  printHeader(options);

  // the summary: one row per chain
  std::cout << std::left << std::setw(7) << "parts" << std::setw(24) << "bare us/step"
            << std::setw(24) << "matched us/step" << std::setw(24) << "cambrian us/step"
            << std::setw(15) << "cambrian/bare"
            << "cambrian/matched\n";
  for (std::size_t c = 0; c < chains.size(); ++c) {
    std::cout << std::setw(7) << options.parts[c];
    for (const char* name : kLoopNames) {
      std::string cell = "-";
      for (const LoopRecord& record : chains[c]) {
        if (record.name == name)
          cell = timingText(record);
      }
      std::cout << std::setw(24) << cell;
    }
    const double cambrian = medianOf(chains[c], "cambrian");
    std::cout << std::setw(15) << fixed(cambrian / medianOf(chains[c], "bare"), 2)
              << fixed(cambrian / medianOf(chains[c], "matched"), 2) << "\n";
  }

  // the details: one row per chain and loop
  std::cout << "\n"
            << std::setw(7) << "parts" << std::setw(10) << "loop" << std::setw(12) << "distance m"
            << std::setw(15) << "max speed m/s" << std::setw(17) << "largest |q| rad"
            << std::setw(16) << "touching parts" << std::setw(41)
            << "solver rows/step joint+contact+friction"
            << "status\n";
  for (std::size_t c = 0; c < chains.size(); ++c) {
    for (const LoopRecord& record : chains[c]) {
      std::cout << std::setw(7) << options.parts[c] << std::setw(10) << record.name << std::setw(12)
                << fixed(horizontalDistance(record), 3) << std::setw(15)
                << fixed(record.max_speed, 2) << std::setw(17)
                << fixed(record.largest_joint_angle, 2) << std::setw(16)
                << fixed(record.touching_parts, 2) << std::setw(41) << rowsText(record)
                << statusText(record) << "\n";
    }
  }
  std::cout << "distance and max speed: the chain's first part, over the whole run (distance: "
               "birth to end, horizontal); largest |q|, touching parts and solver rows (per time "
               "step, all substeps): one untimed block after the timing\n";
}

void printTsv(const Options& options, const std::vector<std::vector<LoopRecord>>& chains) {
  std::cout << "parts\tloop\tus_per_step\tus_min\tus_max\tratio_to_bare\tratio_to_matched\t"
               "distance_m\tmax_speed_m_s\tlargest_joint_angle_rad\ttouching_parts\tjoint_rows\t"
               "contact_rows\tfriction_rows\trows_from\tstatus\n";
  for (std::size_t c = 0; c < chains.size(); ++c) {
    for (const LoopRecord& record : chains[c]) {
      const double us = median(record.us_per_step);
      const auto [low, high] =
          std::minmax_element(record.us_per_step.begin(), record.us_per_step.end());
      const char* rows_from = !record.rows ? "-" : record.rows_from_matched ? "matched" : "solver";
      std::cout << options.parts[c] << "\t" << record.name << "\t" << fixed(us, 2) << "\t"
                << fixed(*low, 2) << "\t" << fixed(*high, 2) << "\t"
                << fixed(us / medianOf(chains[c], "bare"), 3) << "\t"
                << fixed(us / medianOf(chains[c], "matched"), 3) << "\t"
                << fixed(horizontalDistance(record), 4) << "\t" << fixed(record.max_speed, 3)
                << "\t" << fixed(record.largest_joint_angle, 3) << "\t"
                << fixed(record.touching_parts, 3) << "\t"
                << rowsPerStep(record, &SolverRows::joint, 2) << "\t"
                << rowsPerStep(record, &SolverRows::contact, 2) << "\t"
                << rowsPerStep(record, &SolverRows::friction, 2) << "\t" << rows_from << "\t"
                << statusText(record) << "\n";
    }
  }
}

int run(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << kUsage;
      return 0;
    }
  }
  const Options options = parseArguments(argc, argv);
  std::vector<std::vector<LoopRecord>> chains;
  for (int parts : options.parts)
    chains.push_back(measureChain(parts, options));
  if (options.tsv)
    printTsv(options, chains);
  else
    printTables(options, chains);

  // a loop that was not sound makes its timing meaningless
  bool sound = true;
  for (const auto& chain : chains) {
    for (const LoopRecord& record : chain)
      sound = sound && record.trouble.empty();
  }
  if (!sound)
    std::cerr
        << "cambrian_step_cost: a loop was not sound (see status); its timing means nothing\n";
  return sound ? 0 : 1;
}

}  // namespace
}  // namespace cambrian

int main(int argc, char** argv) {
  try {
    return cambrian::run(argc, argv);
  } catch (const cambrian::Error& e) {
    std::cerr << "cambrian_step_cost: error: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "cambrian_step_cost: internal error: " << e.what() << "\n";
    return static_cast<int>(cambrian::ExitCode::failure);
  }
}
