// tests of the trajectory file (traj.h5) and of recording one during an evaluation
#include "store/trajectory.hpp"

#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "brain/allocation_counter.hpp"
#include "physics/physics_settings.hpp"
#include "store/history.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace cambrian {
namespace {

// a fresh path in the test temp directory
std::string tempPath(const std::string& name) {
  std::string path = testing::TempDir() + "/cambrian_trajectory_test_" + name;
  std::filesystem::remove(path);
  return path;
}

// a small made-up trajectory: 3 parts, 5 frames, every value distinct
Trajectory makeTrajectory() {
  Trajectory t;
  t.creature_id = 42;
  t.source = "run/history.h5";
  t.fitness = 1.0 / 3.0;
  t.status = "ok";
  t.task = "walk";
  t.time_step = 1.0 / 240.0;
  t.frame_stride = 8;
  t.frame_rate = 30;
  t.genome_text = "cambrian-genome 1\nnode 0 size 1 1 1\n";
  t.half_extents = {{0.3, 0.15, 0.075}, {0.15, 0.05, 0.05}, {0.15, 0.05, 0.05}};
  t.parent = {-1, 0, 0};
  t.shape = {PartShape::box, PartShape::capsule, PartShape::sphere};
  const EvalPhase phases[] = {EvalPhase::settle, EvalPhase::trial, EvalPhase::resettle,
                              EvalPhase::measure, EvalPhase::measure};
  for (int f = 0; f < 5; ++f) {
    t.time.push_back(f * 8 * t.time_step);
    t.step.push_back(static_cast<std::uint64_t>(f) * 8);
    t.phase.push_back(phases[f]);
    t.center_of_mass.push_back({0.1 * f, -0.01 * f, 0.2 + 0.001 * f});
    for (int p = 0; p < 3; ++p) {
      Transform pose;
      pose.position = {f + 0.1 * p, f - 0.2 * p, 0.5 + p};
      pose.rotation = {0.5, 0.5 + 0.01 * f, -0.5, 0.5 - 0.01 * p};
      t.poses.push_back(pose);
    }
  }
  return t;
}

// the same poses, bit for bit; `what` names them in a failure
void expectSamePoses(const std::vector<Transform>& a, const std::vector<Transform>& b,
                     const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position) << what << " " << i;
    EXPECT_EQ(a[i].rotation, b[i].rotation) << what << " " << i;
  }
}

// the same bits, field by field
void expectSame(const Trajectory& a, const Trajectory& b) {
  EXPECT_EQ(a.creature_id, b.creature_id);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(std::memcmp(&a.fitness, &b.fitness, sizeof a.fitness), 0);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.task, b.task);
  EXPECT_EQ(a.time_step, b.time_step);
  EXPECT_EQ(a.frame_stride, b.frame_stride);
  EXPECT_EQ(a.frame_rate, b.frame_rate);
  EXPECT_EQ(a.genome_text, b.genome_text);
  EXPECT_EQ(a.half_extents, b.half_extents);
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_EQ(a.shape, b.shape);
  EXPECT_EQ(a.held_shape, b.held_shape);
  // no solid flags: every part solid
  auto solid = [](const Trajectory& t) {
    return t.solid.empty() ? std::vector<std::uint8_t>(t.partCount(), 1) : t.solid;
  };
  EXPECT_EQ(solid(a), solid(b));
  EXPECT_EQ(a.collider_half_extents, b.collider_half_extents);
  EXPECT_EQ(a.collider_part, b.collider_part);
  EXPECT_EQ(a.collider_shape, b.collider_shape);
  expectSamePoses(a.collider_pose, b.collider_pose, "collider");
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.phase, b.phase);
  EXPECT_EQ(a.center_of_mass, b.center_of_mass);
  expectSamePoses(a.poses, b.poses, "pose");
  EXPECT_EQ(a.held_half_extents, b.held_half_extents);
  EXPECT_EQ(a.held_part, b.held_part);
  EXPECT_EQ(a.held_released, b.held_released);
  expectSamePoses(a.held_poses, b.held_poses, "held pose");
  EXPECT_EQ(a.ground, b.ground);
  EXPECT_EQ(a.viscosity, b.viscosity);
  EXPECT_EQ(a.light, b.light);
  EXPECT_EQ(a.terrain_samples, b.terrain_samples);
  EXPECT_EQ(a.terrain_spacing, b.terrain_spacing);
  EXPECT_EQ(a.terrain_heights, b.terrain_heights);
}

// makeTrajectory with a projectile held by part 0 and let go after frame 2
Trajectory makeThrowTrajectory() {
  Trajectory t = makeTrajectory();
  t.task = "catapult";
  t.held_half_extents = {{0.1, 0.1, 0.05}};
  t.held_part = {0};
  t.held_shape = {PartShape::cylinder};
  for (std::size_t f = 0; f < t.frameCount(); ++f) {
    Transform pose;
    pose.position = {1.5 * static_cast<double>(f), 0.25, 1.0 - 0.1 * static_cast<double>(f)};
    pose.rotation = {0.6, 0.0, 0.8, 0.01 * static_cast<double>(f)};
    t.held_poses.push_back(pose);
    t.held_released.push_back(f > 2 ? 1 : 0);
  }
  return t;
}

// the exit code of what `action` throws, or -1
template <class Action>
int thrownCode(Action action) {
  try {
    action();
  } catch (const Error& e) {
    return static_cast<int>(e.code());
  }
  return -1;
}

// every field survives a write and a read, bit for bit; no temporary file is left behind
TEST(Trajectory, RoundTrip) {
  std::string path = tempPath("round_trip.h5");
  Trajectory written = makeTrajectory();
  writeTrajectory(path, written);
  expectSame(readTrajectory(path), written);
  for (const auto& entry : std::filesystem::directory_iterator(testing::TempDir())) {
    EXPECT_EQ(entry.path().filename().string().find("cambrian_trajectory_test_round_trip.h5.tmp"),
              std::string::npos);
  }
}

// a trajectory with a held object keeps it, bit for bit; one without writes no /held group and
// reads back none
TEST(Trajectory, HeldObjectsRoundTrip) {
  std::string path = tempPath("held.h5");
  Trajectory written = makeThrowTrajectory();
  writeTrajectory(path, written);
  Trajectory read = readTrajectory(path);
  EXPECT_EQ(read.heldCount(), 1u);
  expectSame(read, written);
  writeTrajectory(path, makeTrajectory());
  EXPECT_EQ(readTrajectory(path).heldCount(), 0u);
  // a held pose missing is refused before anything is written
  Trajectory broken = makeThrowTrajectory();
  broken.held_poses.pop_back();
  EXPECT_EQ(thrownCode([&] { writeTrajectory(path, broken); }),
            static_cast<int>(ExitCode::failure));
  EXPECT_EQ(readTrajectory(path).heldCount(), 0u);
}

// the surroundings (no ground, a fluid, a light moving frame by frame) survive bit for bit; a
// trajectory without a light writes no /light group and reads back none
TEST(Trajectory, SurroundingsRoundTrip) {
  std::string path = tempPath("surroundings.h5");
  Trajectory written = makeTrajectory();
  written.ground = "none";
  written.viscosity = 1.0 / 7.0;
  for (std::size_t f = 0; f < written.frameCount(); ++f)
    written.light.push_back({5.0 + 0.1 * static_cast<double>(f), -1.0 / 3.0, 0.25});
  writeTrajectory(path, written);
  expectSame(readTrajectory(path), written);
  writeTrajectory(path, makeTrajectory());
  const Trajectory plain = readTrajectory(path);
  EXPECT_TRUE(plain.light.empty());
  EXPECT_EQ(plain.ground, "plane");
  EXPECT_EQ(plain.viscosity, 0);
  // a light missing a frame is refused before anything is written
  written.light.pop_back();
  EXPECT_EQ(thrownCode([&] { writeTrajectory(path, written); }),
            static_cast<int>(ExitCode::failure));
  EXPECT_TRUE(readTrajectory(path).light.empty());
}

// a heightfield ground's terrain survives bit for bit; a heightfield without a square grid of
// heights, or heights without a heightfield, is refused before anything is written
TEST(Trajectory, TerrainRoundTrip) {
  std::string path = tempPath("terrain.h5");
  Trajectory written = makeTrajectory();
  written.ground = "heightfield";
  written.terrain_samples = 3;
  written.terrain_spacing = 0.3;
  written.terrain_heights = {0, 0.1, 0.2, 1.0 / 3.0, 0, -0.5, 0.25, 0.125, 2};
  writeTrajectory(path, written);
  expectSame(readTrajectory(path), written);
  Trajectory broken = written;
  broken.terrain_heights.pop_back();
  EXPECT_EQ(thrownCode([&] { writeTrajectory(path, broken); }),
            static_cast<int>(ExitCode::failure));
  broken = makeTrajectory();
  broken.terrain_samples = 3;
  broken.terrain_heights = written.terrain_heights;
  EXPECT_EQ(thrownCode([&] { writeTrajectory(path, broken); }),
            static_cast<int>(ExitCode::failure));
  expectSame(readTrajectory(path), written);  // the file is as it was
}

// a creature on the hills: the recording holds the environment's terrain
TEST(TrajectoryRecorder, TheHillsAreRecorded) {
  CreatureSettings settings;
  settings.set("task.evaluation_time", "1");
  settings.set("environment.name", "hills");
  settings.set("environment.hill_size", "8");
  settings.check();
  const Genotype genome = settings.encoding().fromText(
      "cambrian-genome 2\nnode 0 size 0.5 0.3 0.2 density 1000 joint rigid limit 1 1 1 recursion "
      "1\nend\n",
      "test");
  TrajectoryRecorder recorder(8);
  ASSERT_EQ(evaluate(genome, settings, 0, &recorder).status, EvalStatus::ok);
  const Trajectory& t = recorder.trajectory();
  const Ground ground = settings.environment().ground;
  EXPECT_EQ(t.ground, "heightfield");
  EXPECT_EQ(t.terrain_samples, 17);
  EXPECT_EQ(t.terrain_spacing, 0.5);
  EXPECT_EQ(t.terrain_heights, *ground.heightfield.heights);
  // the block rests on the terrain: its centre 0.1 m above the ground somewhere under it
  const Vec3 centre = t.center_of_mass.back();
  EXPECT_GT(centre.z, ground.heightAt(centre.x, centre.y));
  EXPECT_LT(centre.z,
            ground.highestIn(centre.x - 0.3, centre.x + 0.3, centre.y - 0.3, centre.y + 0.3) + 0.1 +
                3e-3);
}

// writing over an existing file replaces it whole
TEST(Trajectory, OverwriteReplaces) {
  std::string path = tempPath("overwrite.h5");
  writeTrajectory(path, makeTrajectory());
  Trajectory smaller = makeTrajectory();
  smaller.time.resize(2);
  smaller.step.resize(2);
  smaller.phase.resize(2);
  smaller.center_of_mass.resize(2);
  smaller.poses.resize(6);
  smaller.creature_id = kNoCreatureId;
  writeTrajectory(path, smaller);
  Trajectory read = readTrajectory(path);
  EXPECT_EQ(read.frameCount(), 2u);
  EXPECT_EQ(read.creature_id, kNoCreatureId);
  expectSame(read, smaller);
}

// a body without frames (it never moved) is still a valid file
TEST(Trajectory, NoFrames) {
  std::string path = tempPath("no_frames.h5");
  Trajectory t = makeTrajectory();
  t.time.clear();
  t.step.clear();
  t.phase.clear();
  t.center_of_mass.clear();
  t.poses.clear();
  writeTrajectory(path, t);
  Trajectory read = readTrajectory(path);
  EXPECT_EQ(read.frameCount(), 0u);
  EXPECT_EQ(read.partCount(), 3u);
}

// arrays of different lengths are refused before anything is written
TEST(Trajectory, InconsistentArraysAreRefused) {
  std::string path = tempPath("inconsistent.h5");
  Trajectory t = makeTrajectory();
  t.poses.pop_back();
  EXPECT_EQ(thrownCode([&] { writeTrajectory(path, t); }), static_cast<int>(ExitCode::failure));
  EXPECT_FALSE(std::filesystem::exists(path));
}

// an unwritable place is an output error naming the path
TEST(Trajectory, UnwritablePath) {
  std::string path = testing::TempDir() + "/no_such_directory_for_trajectories/t.h5";
  try {
    writeTrajectory(path, makeTrajectory());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::output_file);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

// missing, non-HDF5 and foreign files are input errors naming the file
TEST(Trajectory, BadFiles) {
  auto expectInputError = [](const std::string& path, const std::string& words) {
    try {
      readTrajectory(path);
      ADD_FAILURE() << path << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expectInputError(tempPath("missing.h5"), "no such trajectory file");
  std::string text = tempPath("text.h5");
  std::ofstream(text) << "not hdf5 at all\n";
  expectInputError(text, "not an HDF5 file");
  std::string history = tempPath("history.h5");
  { HistoryWriter writer(history, HistoryAttributes{}, {{"distance", "m"}}); }
  expectInputError(history, "not a cambrian trajectory");
}

// the stride for a frame rate: nearest whole number of steps, at least one
TEST(Trajectory, FrameStride) {
  EXPECT_EQ(frameStrideFor(30, 1.0 / 240), 8u);
  EXPECT_EQ(frameStrideFor(60, 1.0 / 240), 4u);
  EXPECT_EQ(frameStrideFor(1000, 1.0 / 240), 1u);
  EXPECT_EQ(thrownCode([] { frameStrideFor(0, 1.0 / 240); }), static_cast<int>(ExitCode::config));
  EXPECT_EQ(thrownCode([] { frameStrideFor(-5, 1.0 / 240); }), static_cast<int>(ExitCode::config));
}

// a hand-written walker, short walk task
struct Walker {
  Genotype genome =
      readGenomeFile(std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/walker4.genome");
  CreatureSettings settings;
  Walker() {
    settings.set("task.settle_time", "0.25");
    settings.set("task.trial_time", "0.25");
    settings.set("task.resettle_time", "0.25");
    settings.set("task.evaluation_time", "0.5");
  }
};

// recording changes nothing: the outcome is bit-identical with and without an observer
TEST(TrajectoryRecorder, ObservingDoesNotChangeTheOutcome) {
  Walker w;
  Outcome plain = evaluate(w.genome, w.settings, 7);
  TrajectoryRecorder recorder(3);
  Outcome observed = evaluate(w.genome, w.settings, 7, &recorder);
  ASSERT_EQ(plain.status, EvalStatus::ok) << plain.message;
  EXPECT_EQ(std::memcmp(&plain.fitness, &observed.fitness, sizeof plain.fitness), 0)
      << plain.fitness << " vs " << observed.fitness;
  EXPECT_EQ(plain.measures, observed.measures);
  EXPECT_EQ(plain.steps, observed.steps);
}

// frames at birth and every stride steps, phases in order, body from the plan
TEST(TrajectoryRecorder, FramesAndPhases) {
  Walker w;
  const std::uint64_t stride = 6;
  TrajectoryRecorder recorder(stride);
  Outcome outcome = evaluate(w.genome, w.settings, 7, &recorder);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  const Trajectory& t = recorder.trajectory();
  BodyPlan plan = w.settings.encoding().develop(w.genome).body;
  ASSERT_EQ(t.partCount(), plan.parts.size());
  for (std::size_t p = 0; p < plan.parts.size(); ++p) {
    EXPECT_EQ(t.half_extents[p], plan.parts[p].size * 0.5);
    EXPECT_EQ(t.parent[p], plan.parts[p].parent);
  }
  ASSERT_EQ(t.frameCount(), outcome.steps / stride + 1);
  EXPECT_EQ(t.poses.size(), t.frameCount() * t.partCount());
  EXPECT_EQ(t.step.front(), 0u);
  EXPECT_EQ(t.time.front(), 0.0);
  EXPECT_EQ(t.frame_stride, stride);
  EXPECT_DOUBLE_EQ(t.frame_rate, 1.0 / (stride * w.settings.physics().time_step));
  for (std::size_t f = 1; f < t.frameCount(); ++f) {
    EXPECT_EQ(t.step[f], t.step[f - 1] + stride);
    EXPECT_LE(t.phase[f - 1], t.phase[f]) << "frame " << f;
  }
  EXPECT_EQ(t.phase.back(), EvalPhase::measure);
  // the creature stands on the ground: every part's centre above it
  for (const Transform& pose : t.poses)
    EXPECT_GT(pose.position.z, 0.0);
}

// without an observer, a longer evaluation allocates no more than a shorter one: no heap
// allocation per step on the plain path
TEST(TrajectoryRecorder, PlainPathDoesNotAllocatePerStep) {
  Walker w;
  auto allocations = [&](double seconds) {
    CreatureSettings settings = w.settings;
    settings.set("task.evaluation_time", std::to_string(seconds));
    long before = allocationCount();
    Outcome outcome = evaluate(w.genome, settings, 7);
    EXPECT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
    return allocationCount() - before;
  };
  allocations(0.5);  // warm up anything lazily made once per process
  EXPECT_EQ(allocations(0.5), allocations(1.5));
}

// a creature that never reaches the physics shows no body and no frames
TEST(TrajectoryRecorder, InvalidCreatureRecordsNothing) {
  Walker w;
  CreatureSettings tight = w.settings;
  tight.set("genome.max_nodes", "1");
  TrajectoryRecorder recorder(4);
  Outcome outcome = evaluate(w.genome, tight, 7, &recorder);
  EXPECT_EQ(outcome.status, EvalStatus::invalid_body);
  EXPECT_EQ(recorder.trajectory().partCount(), 0u);
  EXPECT_EQ(recorder.trajectory().frameCount(), 0u);
}

// a catapult's projectile is recorded beside the body: held on the +x face of the 1 m slab
// (0.55 m from its centre) until the mechanism lets go at controller step 30, then free; it ends
// resting on the ground
TEST(TrajectoryRecorder, AHeldProjectileIsRecorded) {
  CreatureSettings settings;
  settings.set("task.name", "catapult");
  settings.set("task.evaluation_time", "3");
  settings.set("genome.catapult", "true");
  settings.set("physics.time_step", "0.016666666666666667");
  settings.set("physics.substeps", "4");
  settings.check();
  const Genotype genome = settings.encoding().fromText(
      "cambrian-genome 2\nnode 0 size 1 1 0.2 density 1000 joint rigid limit 1 1 1 recursion 1\n"
      "projectile size 0.1 0.1 0.1 density 1000 position 1 0 0 trigger constant 0 0 0\nend\n",
      "test");
  TrajectoryRecorder recorder(1);
  const Outcome outcome = evaluate(genome, settings, 0, &recorder);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  const Trajectory& t = recorder.trajectory();
  ASSERT_EQ(t.heldCount(), 1u);
  EXPECT_EQ(t.held_half_extents[0], (Vec3{0.05, 0.05, 0.05}));
  EXPECT_EQ(t.held_part[0], 0);
  EXPECT_EQ(t.held_shape, std::vector<PartShape>{PartShape::box});
  ASSERT_EQ(t.held_poses.size(), t.frameCount());
  ASSERT_EQ(t.held_released.size(), t.frameCount());
  std::size_t first_free = t.frameCount();
  for (std::size_t f = 0; f < t.frameCount(); ++f) {
    if (t.held_released[f] && first_free == t.frameCount()) {
      first_free = f;
    }
    if (f > first_free) {
      EXPECT_EQ(t.held_released[f], 1) << "frame " << f;  // once let go, never held again
    }
    if (!t.held_released[f]) {
      const Vec3 offset = t.held_poses[f].position - t.poses[f].position;
      EXPECT_NEAR(norm(offset), 0.55, 1e-3) << "frame " << f;
    }
  }
  ASSERT_LT(first_free, t.frameCount());
  EXPECT_EQ(t.phase[first_free], EvalPhase::measure);
  EXPECT_NEAR(t.held_poses.back().position.z, 0.05, 5e-3);
}

// a follower of the light in water: the recording says there is no ground and which fluid, and
// holds the light in every frame, where the task put it (light_distance from the centre of mass
// at the start of each measured share, then moved); a walk records its still light, on a plane
TEST(TrajectoryRecorder, TheWaterAndTheMovingLightAreRecorded) {
  CreatureSettings settings;
  settings.set("task.name", "follow_light");
  settings.set("task.evaluation_time", "2");
  settings.set("task.light_trials", "1");
  settings.set("task.light_positions", "2");
  settings.set("task.light_distance", "5");
  settings.set("genome.photosensors", "every_part");
  settings.set("environment.name", "water");
  settings.check();
  const Genotype genome = settings.encoding().fromText(
      "cambrian-genome 2\nnode 0 size 0.5 0.3 0.2 density 1000 joint rigid limit 1 1 1 recursion "
      "1\nend\n",
      "test");
  TrajectoryRecorder recorder(4);
  const Outcome outcome = evaluate(genome, settings, 0, &recorder);
  ASSERT_EQ(outcome.status, EvalStatus::ok) << outcome.message;
  const Trajectory& t = recorder.trajectory();
  EXPECT_EQ(t.ground, "none");
  EXPECT_GT(t.viscosity, 0);
  ASSERT_EQ(t.light.size(), t.frameCount());
  // the measured frames see the light in two places, each 5 m from where the body was
  std::vector<Vec3> places;
  for (std::size_t f = 0; f < t.frameCount(); ++f) {
    if (t.phase[f] == EvalPhase::measure && (places.empty() || !(places.back() == t.light[f])))
      places.push_back(t.light[f]);
  }
  ASSERT_EQ(places.size(), 2u);
  for (const Vec3& place : places) {
    const Vec3 offset = place - t.center_of_mass.back();
    EXPECT_NEAR(std::hypot(offset.x, offset.y), 5.0, 0.05);  // a still block in still water
  }

  CreatureSettings walk;
  walk.set("task.evaluation_time", "1");
  walk.check();
  TrajectoryRecorder plain(8);
  ASSERT_EQ(evaluate(genome, walk, 0, &plain).status, EvalStatus::ok);
  ASSERT_EQ(plain.trajectory().light.size(), plain.trajectory().frameCount());
  EXPECT_EQ(plain.trajectory().light.front(), (Vec3{10, 0, 0}));  // the plane's light
  EXPECT_EQ(plain.trajectory().light.back(), (Vec3{10, 0, 0}));
  EXPECT_EQ(plain.trajectory().ground, "plane");
  EXPECT_EQ(plain.trajectory().viscosity, 0);
}

// each part's and held object's shape is recorded from the plan (no encoding grows other shapes
// yet, so the plan is made by hand) and survives the file
TEST(TrajectoryRecorder, ShapesAreRecorded) {
  BodyPlan plan;
  plan.parts.resize(3);
  plan.parts[0].shape = PartShape::capsule;
  plan.parts[1].shape = PartShape::sphere;
  plan.parts[1].parent = 0;
  plan.parts[2].parent = 0;
  plan.held.resize(1);
  plan.held[0].shape = PartShape::cylinder;
  TrajectoryRecorder recorder(1);
  recorder.begin(plan, 0.01, Environment{});
  const std::vector<Transform> poses(3);
  const std::vector<Transform> held_poses(1);
  const std::vector<std::uint8_t> released(1, 0);
  EvalFrame frame;
  frame.poses = poses;
  frame.held_poses = held_poses;
  frame.held_released = released;
  recorder.frame(frame);
  const std::vector<PartShape> shapes = {PartShape::capsule, PartShape::sphere, PartShape::box};
  EXPECT_EQ(recorder.trajectory().shape, shapes);
  EXPECT_EQ(recorder.trajectory().held_shape, std::vector<PartShape>{PartShape::cylinder});
  const std::string path = tempPath("shapes.h5");
  writeTrajectory(path, recorder.trajectory());
  const Trajectory read = readTrajectory(path);
  EXPECT_EQ(read.shape, shapes);
  EXPECT_EQ(read.held_shape, std::vector<PartShape>{PartShape::cylinder});
}

// a part without a shape of its own and the shapes parts carry (a springy organism's proxies and
// tubes) are recorded, written and read back; a collider on a part that does not exist is
// refused by the writer and by the reader
TEST(TrajectoryRecorder, CarriedShapesAndPartsWithoutAShapeAreRecorded) {
  BodyPlan plan;
  plan.parts.resize(3);
  for (PartPlan& part : plan.parts)
    part.shape = PartShape::sphere;
  plan.parts[1].parent = 0;
  plan.parts[1].solid = false;
  plan.parts[2].parent = 1;
  ColliderPlan tube;
  tube.part = 2;
  tube.shape = PartShape::capsule;
  tube.size = {0.65, 0.15, 0.15};
  tube.pose.position = {0.25, 0, 0};
  tube.pose.rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  plan.colliders = {tube, tube};
  plan.colliders[1].part = 0;
  plan.colliders[1].shape = PartShape::cylinder;
  TrajectoryRecorder recorder(1);
  recorder.begin(plan, 0.01, Environment{});
  const std::vector<Transform> poses(3);
  EvalFrame frame;
  frame.poses = poses;
  recorder.frame(frame);
  const Trajectory& recorded = recorder.trajectory();
  EXPECT_EQ(recorded.solid, (std::vector<std::uint8_t>{1, 0, 1}));
  ASSERT_EQ(recorded.colliderCount(), 2u);
  EXPECT_EQ(recorded.collider_part, (std::vector<int>{2, 0}));
  EXPECT_EQ(recorded.collider_half_extents[0], (Vec3{0.325, 0.075, 0.075}));
  EXPECT_EQ(recorded.collider_shape[1], PartShape::cylinder);
  const std::string path = tempPath("carried.h5");
  writeTrajectory(path, recorded);
  expectSame(readTrajectory(path), recorded);

  Trajectory stray = recorded;
  stray.collider_part[1] = 3;
  const std::string stray_path = tempPath("stray.h5");
  EXPECT_EQ(thrownCode([&] { writeTrajectory(stray_path, stray); }),
            static_cast<int>(ExitCode::failure));
  EXPECT_FALSE(std::filesystem::exists(stray_path));
  {
    hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t parts = H5Dopen2(file, "colliders/part", H5P_DEFAULT);
    const std::int32_t carriers[2] = {2, 3};
    H5Dwrite(parts, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, carriers);
    H5Dclose(parts);
    H5Fclose(file);
  }
  try {
    readTrajectory(path);
    ADD_FAILURE() << "a collider on part 3 of 3 was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("colliders/part: value 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cambrian
