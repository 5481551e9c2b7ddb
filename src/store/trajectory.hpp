// cambrian: a creature's trajectory for rendering — the world pose of every part, frame by
// frame, recorded during an evaluation and stored as traj.h5 (layout in docs/hdf5-schema.md,
// read by analysis/animate.py).
#pragma once

#include "cambrian/evaluate.hpp"
#include "cambrian/math.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cambrian {

/// Version of the trajectory layout; a reader refuses files with a newer one.
constexpr int kTrajectoryFormatVersion = 1;

/// Value of the root attribute "format" that marks a cambrian trajectory file.
constexpr const char* kTrajectoryFormatName = "cambrian-trajectory";

/// creature_id of a trajectory that does not come from a history (UINT64_MAX).
constexpr std::uint64_t kNoCreatureId = std::numeric_limits<std::uint64_t>::max();

/// Everything a trajectory file holds. Frames are in time order; per-frame part data is
/// frame-major: entry `frame * partCount() + part` (held objects: `frame * heldCount() + k`).
struct Trajectory {
  // provenance and outcome (root attributes)
  std::uint64_t creature_id = kNoCreatureId;  ///< id in the source history, or kNoCreatureId
  std::string source;              ///< where the creature came from: history path or genome file
  double fitness = 0;              ///< fitness of the evaluation that was recorded
  std::string status = "ok";       ///< statusName of that evaluation
  std::string task;                ///< the task's name ("walk", "jump")
  double time_step = 0;            ///< physics step, s
  std::uint64_t frame_stride = 1;  ///< physics steps between two frames
  double frame_rate = 0;           ///< frames per simulated second = 1 / (stride * time_step)
  std::string genome_text;         ///< genomeToText of the creature

  // the body (one entry per part, BodyPlan order)
  std::vector<Vec3> half_extents;  ///< half the box size along the part's own axes, m
  std::vector<int> parent;         ///< parent part index, -1 for the root
  std::vector<PartShape> shape;    ///< each part's shape (half_extents as PartShape reads size)
  /// 1: the part has a shape of its own; 0: a mass without one, not drawn (a springy organism's
  /// proxy bodies). Empty: every part has (files of before)
  std::vector<std::uint8_t> solid;

  // the shapes parts carry besides their own (BodyPlan::colliders: a springy organism's tubes);
  // each moves with its part, so its pose is in the part's frame
  std::vector<Vec3> collider_half_extents;  ///< half the size, as PartShape reads it, m
  std::vector<int> collider_part;           ///< the part that carries it
  std::vector<PartShape> collider_shape;    ///< its shape
  std::vector<Transform> collider_pose;     ///< its pose in the carrying part's frame

  // the frames
  std::vector<double> time;          ///< simulated time of each frame, s
  std::vector<std::uint64_t> step;   ///< physics steps before each frame
  std::vector<EvalPhase> phase;      ///< phase of each frame
  std::vector<Vec3> center_of_mass;  ///< per frame, world frame, m
  std::vector<Transform> poses;      ///< frames x parts world poses (frame-major)

  // objects held at birth (BodyPlan::held order: a catapult's projectile); none for most
  std::vector<Vec3> held_half_extents;      ///< half the box size along its own axes, m
  std::vector<int> held_part;               ///< the part that holds it at birth
  std::vector<PartShape> held_shape;        ///< its shape
  std::vector<Transform> held_poses;        ///< frames x held world poses (frame-major)
  std::vector<std::uint8_t> held_released;  ///< frames x held: 1 once it has been let go

  // what surrounds the body (root attributes ground and viscosity; /light when recorded)
  /// "plane" (a ground plane at z = 0), "none" (water) or "heightfield" (hills: /ground)
  std::string ground = "plane";
  double viscosity = 0;  ///< the fluid's, N s / m^3; 0: none
  /// with a heightfield: its samples per side, spacing (m) and heights (Heightfield's layout)
  int terrain_samples = 0;
  double terrain_spacing = 0;
  std::vector<double> terrain_heights;
  /// the light's position per frame (what the photosensors point at); empty in files of before
  std::vector<Vec3> light;

  /// Number of parts.
  std::size_t partCount() const { return half_extents.size(); }
  /// Number of carried colliders.
  std::size_t colliderCount() const { return collider_half_extents.size(); }
  /// Number of held objects.
  std::size_t heldCount() const { return held_half_extents.size(); }
  /// Number of frames.
  std::size_t frameCount() const { return time.size(); }
};

/// A FrameObserver that records every frame it is shown into a Trajectory (body on begin(),
/// one frame per frame()). It fills only the body and frame fields; provenance is the caller's.
class TrajectoryRecorder : public FrameObserver {
 public:
  /// Records every `stride`-th step (clamped to >= 1).
  explicit TrajectoryRecorder(std::uint64_t stride);
  /// The stride given at construction.
  std::uint64_t frameStride() const override { return stride_; }
  /// Takes the part and held-object sizes from `plan`, the ground and fluid from `environment`;
  /// forgets any earlier recording.
  void begin(const BodyPlan& plan, double time_step, const Environment& environment) override;
  /// Appends one frame.
  void frame(const EvalFrame& frame) override;
  /// What has been recorded so far (time_step and frame_stride set by begin()).
  const Trajectory& trajectory() const { return trajectory_; }
  /// Moves the recording out.
  Trajectory take() { return std::move(trajectory_); }

 private:
  std::uint64_t stride_;
  Trajectory trajectory_;
};

/// Physics steps between frames for a wanted `frame_rate` (Hz) at `time_step` (s): the nearest
/// whole number, at least 1. Throws ConfigError naming the value unless both are finite and > 0.
std::uint64_t frameStrideFor(double frame_rate, double time_step);

/// Writes `trajectory` to `path` atomically (a temporary file beside it, then rename), so a
/// reader never sees a half-written file. Throws Error(output_file) naming the path when it
/// cannot be written, and Error(failure) when the trajectory's arrays disagree in length.
void writeTrajectory(const std::string& path, const Trajectory& trajectory);

/// Reads a trajectory file. A missing, non-HDF5, foreign, newer or inconsistent file throws
/// InputError naming the file and what is wrong.
Trajectory readTrajectory(const std::string& path);

}  // namespace cambrian
