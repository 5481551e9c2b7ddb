#include "store/trajectory.hpp"

#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "store/hdf5_io.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace cambrian {

// the store module's HDF5 helpers
using namespace hdf5;

namespace {

// the phase names, index = EvalPhase value
const std::vector<std::string>& phaseNames() {
  static const std::vector<std::string> names = {
      phaseName(EvalPhase::settle), phaseName(EvalPhase::trial), phaseName(EvalPhase::resettle),
      phaseName(EvalPhase::measure)};
  return names;
}

// a dataset of `dims` holding `values` (row-major), with units and a description; false on
// failure
bool writeDescribed(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t type,
                    const void* values, const char* units, const char* description) {
  Handle dataset = writeDataset(location, name, dims, type, values);
  return dataset.valid() && describe(dataset.get(), units, description);
}

// the shape names, index = PartShape value
const std::vector<std::string>& shapeNames() {
  static const std::vector<std::string> names = {
      shapeName(PartShape::box), shapeName(PartShape::capsule), shapeName(PartShape::sphere),
      shapeName(PartShape::cylinder)};
  return names;
}

// shapes as the uint8 values a shape dataset holds
std::vector<std::uint8_t> shapeCodes(const std::vector<PartShape>& shapes) {
  std::vector<std::uint8_t> codes;
  for (PartShape shape : shapes)
    codes.push_back(static_cast<std::uint8_t>(shape));
  return codes;
}

// a shape dataset of `count` entries, with its names attribute; false on failure
bool writeShapes(hid_t location, const std::vector<PartShape>& shapes, const char* description) {
  const std::vector<std::uint8_t> codes = shapeCodes(shapes);
  if (!writeDescribed(location, "shape", {codes.size()}, H5T_NATIVE_UINT8, codes.data(), "1",
                      description))
    return false;
  Handle dataset(H5Dopen2(location, "shape", H5P_DEFAULT), H5Dclose);
  return dataset.valid() && writeStrings(dataset.get(), "names", shapeNames());
}

// a whole dataset as T values; `dims` gets its shape. False when missing or unreadable
template <class T>
bool readDataset(hid_t location, const char* name, std::vector<T>& values,
                 std::vector<hsize_t>& dims) {
  Handle dataset = openDataset(location, name, 3, dims);
  if (!dataset.valid())
    return false;
  hsize_t count = 1;
  for (hsize_t d : dims)
    count *= d;
  return readValues(dataset.get(), count, values);
}

// poses as (x, y, z) positions and (x, y, z, w) quaternions, appended
void flattenPoses(const std::vector<Transform>& poses, std::vector<double>& position,
                  std::vector<double>& orientation) {
  for (const Transform& pose : poses) {
    position.insert(position.end(), {pose.position.x, pose.position.y, pose.position.z});
    orientation.insert(orientation.end(),
                       {pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w});
  }
}

// poses back from flattenPoses' arrays (`count` of them)
std::vector<Transform> unflattenPoses(const std::vector<double>& position,
                                      const std::vector<double>& orientation, hsize_t count) {
  std::vector<Transform> poses;
  for (hsize_t k = 0; k < count; ++k) {
    Transform pose;
    pose.position = {position[3 * k], position[3 * k + 1], position[3 * k + 2]};
    pose.rotation = {orientation[4 * k + 3], orientation[4 * k], orientation[4 * k + 1],
                     orientation[4 * k + 2]};
    poses.push_back(pose);
  }
  return poses;
}

// flushes a closed file's data to the disk (best effort: a failure shows up at rename)
void syncFile(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// the whole trajectory into an open, empty file; false on failure, `what` says where
bool writeContents(hid_t file, const Trajectory& t, std::string& what) {
  // root attributes: format, provenance, outcome
  what = "the root attributes";
  bool ok =
      writeFormat(file, kTrajectoryFormatName, kTrajectoryFormatVersion, kVersion, kGitHash) &&
      writeScalar<std::uint64_t>(file, "creature_id", t.creature_id) &&
      writeString(file, "source", t.source) && writeScalar(file, "fitness", t.fitness) &&
      writeString(file, "status", t.status) && writeString(file, "task", t.task) &&
      writeScalar(file, "time_step", t.time_step) &&
      writeScalar<std::uint64_t>(file, "frame_stride", t.frame_stride) &&
      writeScalar(file, "frame_rate", t.frame_rate) &&
      writeString(file, "genome_text", t.genome_text) && writeString(file, "ground", t.ground) &&
      writeScalar(file, "viscosity", t.viscosity);
  if (!ok)
    return false;

  // per-frame datasets
  const hsize_t frames = t.frameCount(), parts = t.partCount();
  std::vector<std::uint8_t> phases;
  for (EvalPhase phase : t.phase)
    phases.push_back(static_cast<std::uint8_t>(phase));
  std::vector<double> com, position, orientation;
  for (const Vec3& c : t.center_of_mass)
    com.insert(com.end(), {c.x, c.y, c.z});
  flattenPoses(t.poses, position, orientation);
  what = "the frame datasets";
  ok =
      writeDescribed(file, "time", {frames}, H5T_NATIVE_DOUBLE, t.time.data(), "s",
                     "simulated time of each frame") &&
      writeDescribed(file, "step", {frames}, H5T_NATIVE_UINT64, t.step.data(), "1",
                     "physics steps taken before each frame (0: at birth)") &&
      writeDescribed(file, "phase", {frames}, H5T_NATIVE_UINT8, phases.data(), "1",
                     "phase of each frame; index into the names attribute") &&
      writeDescribed(file, "center_of_mass", {frames, 3}, H5T_NATIVE_DOUBLE, com.data(), "m",
                     "mass-weighted centre of the parts, world frame (z up)") &&
      writeDescribed(file, "position", {frames, parts, 3}, H5T_NATIVE_DOUBLE, position.data(), "m",
                     "world position of each part's centre, frame x part x (x, y, z)") &&
      writeDescribed(file, "orientation", {frames, parts, 4}, H5T_NATIVE_DOUBLE, orientation.data(),
                     "1", "world orientation of each part, unit quaternion (x, y, z, w)");
  if (!ok)
    return false;
  {
    Handle phase(H5Dopen2(file, "phase", H5P_DEFAULT), H5Dclose);
    if (!phase.valid() || !writeStrings(phase.get(), "names", phaseNames()))
      return false;
  }

  // the body
  what = "the /part group";
  Handle group(H5Gcreate2(file, "part", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid() ||
      !writeString(group.get(), "description", "one entry per body part, BodyPlan order"))
    return false;
  std::vector<double> half;
  for (const Vec3& h : t.half_extents)
    half.insert(half.end(), {h.x, h.y, h.z});
  std::vector<std::int32_t> parents(t.parent.begin(), t.parent.end());
  ok = writeDescribed(group.get(), "half_extents", {parts, 3}, H5T_NATIVE_DOUBLE, half.data(), "m",
                      "half the box size along the part's own x, y, z axes") &&
       writeDescribed(group.get(), "parent", {parts}, H5T_NATIVE_INT32, parents.data(), "1",
                      "index of the parent part; -1 for the root") &&
       writeShapes(group.get(), t.shape,
                   "each part's shape; index into the names attribute (half_extents read as "
                   "the shape reads its size)");
  std::vector<std::uint8_t> solid = t.solid;
  solid.resize(parts, 1);
  ok =
      ok && writeDescribed(group.get(), "solid", {parts}, H5T_NATIVE_UINT8, solid.data(), "1",
                           "1: the part has a shape of its own; 0: a mass without one (not drawn)");
  if (!ok)
    return false;

  // the shapes the parts carry, when there are any
  if (t.colliderCount() > 0) {
    what = "the /colliders group";
    const hsize_t colliders = t.colliderCount();
    Handle carried(H5Gcreate2(file, "colliders", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    std::vector<double> carried_half, carried_position, carried_orientation;
    for (const Vec3& h : t.collider_half_extents)
      carried_half.insert(carried_half.end(), {h.x, h.y, h.z});
    std::vector<std::int32_t> carriers(t.collider_part.begin(), t.collider_part.end());
    flattenPoses(t.collider_pose, carried_position, carried_orientation);
    const hid_t c = carried.get();
    if (!carried.valid() ||
        !writeString(c, "description",
                     "shapes the parts carry besides their own (a springy organism's tubes), "
                     "fixed in the carrying part's frame") ||
        !writeDescribed(c, "half_extents", {colliders, 3}, H5T_NATIVE_DOUBLE, carried_half.data(),
                        "m", "half the size along the shape's own x, y, z axes") ||
        !writeDescribed(c, "part", {colliders}, H5T_NATIVE_INT32, carriers.data(), "1",
                        "index of the part that carries it") ||
        !writeDescribed(c, "position", {colliders, 3}, H5T_NATIVE_DOUBLE, carried_position.data(),
                        "m", "its centre in the carrying part's frame") ||
        !writeDescribed(
            c, "orientation", {colliders, 4}, H5T_NATIVE_DOUBLE, carried_orientation.data(), "1",
            "its orientation in the carrying part's frame, unit quaternion (x, y, z, w)") ||
        !writeShapes(c, t.collider_shape, "each shape; index into the names attribute"))
      return false;
  }

  // the light, when recorded
  if (!t.light.empty()) {
    what = "the /light group";
    Handle light_group(H5Gcreate2(file, "light", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    std::vector<double> light;
    for (const Vec3& l : t.light)
      light.insert(light.end(), {l.x, l.y, l.z});
    if (!light_group.valid() ||
        !writeString(light_group.get(), "description",
                     "the point the photosensors point at, per frame (the task may move it)") ||
        !writeDescribed(light_group.get(), "position", {frames, 3}, H5T_NATIVE_DOUBLE, light.data(),
                        "m", "world position of the light in each frame"))
      return false;
  }
  // the terrain, with a heightfield ground
  if (t.ground == "heightfield") {
    what = "the /ground group";
    Handle ground(H5Gcreate2(file, "ground", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    const hsize_t n = static_cast<hsize_t>(t.terrain_samples);
    if (!ground.valid() ||
        !writeString(ground.get(), "description",
                     "the terrain: heights on a square grid centred on the origin, sample (row r, "
                     "column c) at x = (c - (n - 1) / 2) spacing, y = (r - (n - 1) / 2) spacing") ||
        !writeScalar(ground.get(), "spacing", t.terrain_spacing) ||
        !writeDescribed(ground.get(), "heights", {n, n}, H5T_NATIVE_DOUBLE,
                        t.terrain_heights.data(), "m", "z of each sample, row (y) x column (x)"))
      return false;
  }
  if (t.heldCount() == 0)
    return true;

  // the held objects (a catapult's projectile), only when there are any
  what = "the /held group";
  const hsize_t held = t.heldCount();
  Handle held_group(H5Gcreate2(file, "held", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!held_group.valid() ||
      !writeString(held_group.get(), "description",
                   "objects the creature holds at birth (a catapult's projectile), BodyPlan "
                   "order; held until released, then free"))
    return false;
  std::vector<double> held_half, held_position, held_orientation;
  for (const Vec3& h : t.held_half_extents)
    held_half.insert(held_half.end(), {h.x, h.y, h.z});
  std::vector<std::int32_t> holders(t.held_part.begin(), t.held_part.end());
  flattenPoses(t.held_poses, held_position, held_orientation);
  hid_t g = held_group.get();
  return writeDescribed(g, "half_extents", {held, 3}, H5T_NATIVE_DOUBLE, held_half.data(), "m",
                        "half the box size along the object's own x, y, z axes") &&
         writeDescribed(g, "part", {held}, H5T_NATIVE_INT32, holders.data(), "1",
                        "index of the part that holds it at birth") &&
         writeDescribed(g, "position", {frames, held, 3}, H5T_NATIVE_DOUBLE, held_position.data(),
                        "m",
                        "world position of each object's centre, frame x object x (x, y, z)") &&
         writeDescribed(g, "orientation", {frames, held, 4}, H5T_NATIVE_DOUBLE,
                        held_orientation.data(), "1",
                        "world orientation of each object, unit quaternion (x, y, z, w)") &&
         writeShapes(g, t.held_shape, "each object's shape; index into the names attribute") &&
         writeDescribed(g, "released", {frames, held}, H5T_NATIVE_UINT8, t.held_released.data(),
                        "1", "1 once the object has been let go");
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(std::uint64_t stride)
    : stride_(std::max<std::uint64_t>(1, stride)) {
  trajectory_.frame_stride = stride_;
}

void TrajectoryRecorder::begin(const BodyPlan& plan, double time_step,
                               const Environment& environment) {
  // a fresh recording of this body, in this environment
  Trajectory fresh;
  switch (environment.ground.kind) {
    case Ground::Kind::plane:
      fresh.ground = "plane";
      break;
    case Ground::Kind::none:
      fresh.ground = "none";
      break;
    case Ground::Kind::heightfield: {
      const Heightfield& field = environment.ground.heightfield;
      fresh.ground = "heightfield";
      fresh.terrain_samples = field.samples;
      fresh.terrain_spacing = field.spacing;
      fresh.terrain_heights = *field.heights;
      break;
    }
  }
  fresh.viscosity = environment.fluid.viscosity;
  fresh.frame_stride = stride_;
  fresh.time_step = time_step;
  fresh.frame_rate = 1.0 / (static_cast<double>(stride_) * time_step);
  for (const PartPlan& part : plan.parts) {
    fresh.half_extents.push_back(part.size * 0.5);
    fresh.parent.push_back(part.parent);
    fresh.shape.push_back(part.shape);
    fresh.solid.push_back(part.solid ? 1 : 0);
  }
  for (const ColliderPlan& collider : plan.colliders) {
    fresh.collider_half_extents.push_back(collider.size * 0.5);
    fresh.collider_part.push_back(collider.part);
    fresh.collider_shape.push_back(collider.shape);
    fresh.collider_pose.push_back(collider.pose);
  }
  for (const HeldObject& held : plan.held) {
    fresh.held_half_extents.push_back(held.size * 0.5);
    fresh.held_part.push_back(held.part);
    fresh.held_shape.push_back(held.shape);
  }
  trajectory_ = std::move(fresh);
}

void TrajectoryRecorder::frame(const EvalFrame& frame) {
  trajectory_.time.push_back(frame.time);
  trajectory_.step.push_back(frame.step);
  trajectory_.phase.push_back(frame.phase);
  trajectory_.center_of_mass.push_back(frame.center_of_mass);
  trajectory_.poses.insert(trajectory_.poses.end(), frame.poses.begin(), frame.poses.end());
  trajectory_.held_poses.insert(trajectory_.held_poses.end(), frame.held_poses.begin(),
                                frame.held_poses.end());
  trajectory_.held_released.insert(trajectory_.held_released.end(), frame.held_released.begin(),
                                   frame.held_released.end());
  trajectory_.light.push_back(frame.light);
}

std::uint64_t frameStrideFor(double frame_rate, double time_step) {
  // both must be positive and finite
  if (!(frame_rate > 0) || !std::isfinite(frame_rate)) {
    std::ostringstream message;
    message << "frame rate = " << frame_rate << " Hz: must be > 0 and finite";
    throw ConfigError(message.str());
  }
  if (!(time_step > 0) || !std::isfinite(time_step)) {
    std::ostringstream message;
    message << "physics.time_step = " << time_step << " s: must be > 0";
    throw ConfigError(message.str());
  }
  double steps = std::round(1.0 / (frame_rate * time_step));
  return steps < 1 ? 1 : static_cast<std::uint64_t>(steps);
}

void writeTrajectory(const std::string& path, const Trajectory& t) {
  // the arrays must agree before anything touches the disk
  const std::size_t frames = t.frameCount(), parts = t.partCount();
  const std::size_t colliders = t.colliderCount();
  bool bad_collider = t.collider_part.size() != colliders || t.collider_shape.size() != colliders ||
                      t.collider_pose.size() != colliders;
  for (int part : t.collider_part)
    bad_collider = bad_collider || part < 0 || static_cast<std::size_t>(part) >= parts;
  if (t.parent.size() != parts || t.shape.size() != parts ||
      (!t.solid.empty() && t.solid.size() != parts) || bad_collider ||
      t.held_shape.size() != t.heldCount() || t.step.size() != frames || t.phase.size() != frames ||
      t.center_of_mass.size() != frames || t.poses.size() != frames * parts ||
      t.held_part.size() != t.heldCount() || t.held_poses.size() != frames * t.heldCount() ||
      t.held_released.size() != frames * t.heldCount() ||
      (!t.light.empty() && t.light.size() != frames) ||
      (t.ground == "heightfield") !=
          (t.terrain_samples > 1 &&
           t.terrain_heights.size() == static_cast<std::size_t>(t.terrain_samples) *
                                           static_cast<std::size_t>(t.terrain_samples))) {
    throw Error(ExitCode::failure, path + ": inconsistent trajectory (" + std::to_string(frames) +
                                       " frames, " + std::to_string(parts) + " parts, " +
                                       std::to_string(t.poses.size()) + " poses)");
  }

  // write a temporary file beside the target, then rename it into place
  QuietErrors quiet;
  std::string temporary = path + ".tmp." + std::to_string(::getpid());
  auto fail = [&](const std::string& what) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw Error(ExitCode::output_file, path + ": " + what);
  };
  {
    Handle file = createFile(temporary, H5F_LIBVER_EARLIEST);
    if (!file.valid())
      fail("cannot create the HDF5 file " + temporary);
    std::string what;
    if (!writeContents(file.get(), t, what))
      fail("cannot write " + what);
    if (file.reset() < 0)
      fail("cannot close the HDF5 file " + temporary);
  }
  syncFile(temporary);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    fail("cannot rename " + temporary + " into place: " + error.message());
}

Trajectory readTrajectory(const std::string& path) {
  QuietErrors quiet;
  auto fail = [&](const std::string& what) { throw InputError(path + ": " + what); };

  // missing, not HDF5, corrupt
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    fail("no such trajectory file");
  if (H5Fis_hdf5(path.c_str()) <= 0)
    fail("not an HDF5 file");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid())
    fail("HDF5 file cannot be opened (truncated or corrupt)");
  hid_t f = file.get();

  // a cambrian trajectory of a version we read
  std::string format;
  if (!readString(f, "format", format) || format != kTrajectoryFormatName)
    fail("not a cambrian trajectory (root attribute 'format' is not '" +
         std::string(kTrajectoryFormatName) + "')");
  std::int32_t version = 0;
  if (!readScalar(f, "format_version", version) || version < 1 ||
      version > kTrajectoryFormatVersion)
    fail("format_version " + std::to_string(version) + " is not supported (this cambrian reads " +
         std::to_string(kTrajectoryFormatVersion) + ")");
  Trajectory t;
  bool ok = readScalar(f, "creature_id", t.creature_id) && readString(f, "source", t.source) &&
            readScalar(f, "fitness", t.fitness) && readString(f, "status", t.status) &&
            readString(f, "task", t.task) && readScalar(f, "time_step", t.time_step) &&
            readScalar(f, "frame_stride", t.frame_stride) &&
            readScalar(f, "frame_rate", t.frame_rate) &&
            readString(f, "genome_text", t.genome_text);
  if (!ok)
    fail("a root attribute is missing or of the wrong type");
  // the surroundings (files of before have neither: a plane, no fluid)
  if (H5Aexists(f, "ground") > 0 && !readString(f, "ground", t.ground))
    fail("root attribute 'ground' unreadable");
  if (t.ground != "plane" && t.ground != "none" && t.ground != "heightfield")
    fail("root attribute 'ground' is '" + t.ground + "', not plane, none or heightfield");
  if (H5Aexists(f, "viscosity") > 0 && !readScalar(f, "viscosity", t.viscosity))
    fail("root attribute 'viscosity' unreadable");

  // the datasets, with shapes checked against each other
  std::vector<hsize_t> dims;
  std::vector<std::uint8_t> phases;
  std::vector<double> com, position, orientation, half;
  std::vector<std::int32_t> parents;
  auto need = [&](bool read, const char* name) {
    if (!read)
      fail(std::string("dataset /") + name + " missing or unreadable");
  };
  need(readDataset(f, "time", t.time, dims), "time");
  const hsize_t frames = dims[0];
  need(readDataset(f, "part/half_extents", half, dims), "part/half_extents");
  const hsize_t parts = dims[0];
  auto shape = [&](const char* name, std::vector<hsize_t> wanted) {
    if (dims != wanted)
      fail(std::string("dataset /") + name + " has the wrong shape for " + std::to_string(frames) +
           " frames and " + std::to_string(parts) + " parts");
  };
  shape("part/half_extents", {parts, 3});
  need(readDataset(f, "part/parent", parents, dims), "part/parent");
  shape("part/parent", {parts});
  // shapes (files of before have none: boxes)
  auto readShapes = [&](const char* name, hsize_t count, std::vector<PartShape>& shapes) {
    shapes.assign(count, PartShape::box);
    if (H5Lexists(f, name, H5P_DEFAULT) <= 0)
      return;
    std::vector<std::uint8_t> codes;
    need(readDataset(f, name, codes, dims), name);
    if (dims != std::vector<hsize_t>{count})
      fail(std::string("dataset /") + name + " has the wrong shape for " + std::to_string(count) +
           " entries");
    for (hsize_t k = 0; k < count; ++k) {
      if (codes[k] >= kPartShapeKinds)
        fail(std::string("dataset /") + name + ": value " + std::to_string(codes[k]) +
             " at entry " + std::to_string(k) + " is not a shape");
      shapes[k] = static_cast<PartShape>(codes[k]);
    }
  };
  readShapes("part/shape", parts, t.shape);
  // whether each part has a shape of its own (files of before: every part has)
  if (H5Lexists(f, "part/solid", H5P_DEFAULT) > 0) {
    need(readDataset(f, "part/solid", t.solid, dims), "part/solid");
    shape("part/solid", {parts});
  }
  // the shapes the parts carry (files without /colliders: none)
  if (H5Lexists(f, "colliders", H5P_DEFAULT) > 0) {
    std::vector<double> carried_half, carried_position, carried_orientation;
    std::vector<std::int32_t> carriers;
    need(readDataset(f, "colliders/half_extents", carried_half, dims), "colliders/half_extents");
    const hsize_t colliders = dims.size() == 2 ? dims[0] : 0;
    auto collider_shape = [&](const char* name, std::vector<hsize_t> wanted) {
      if (dims != wanted)
        fail(std::string("dataset /") + name + " has the wrong shape for " +
             std::to_string(colliders) + " colliders");
    };
    collider_shape("colliders/half_extents", {colliders, 3});
    need(readDataset(f, "colliders/part", carriers, dims), "colliders/part");
    collider_shape("colliders/part", {colliders});
    need(readDataset(f, "colliders/position", carried_position, dims), "colliders/position");
    collider_shape("colliders/position", {colliders, 3});
    need(readDataset(f, "colliders/orientation", carried_orientation, dims),
         "colliders/orientation");
    collider_shape("colliders/orientation", {colliders, 4});
    for (hsize_t k = 0; k < colliders; ++k) {
      if (carriers[k] < 0 || static_cast<hsize_t>(carriers[k]) >= parts)
        fail("dataset /colliders/part: value " + std::to_string(carriers[k]) + " at entry " +
             std::to_string(k) + " is not one of the " + std::to_string(parts) + " parts");
      t.collider_half_extents.push_back(
          {carried_half[3 * k], carried_half[3 * k + 1], carried_half[3 * k + 2]});
      t.collider_part.push_back(carriers[k]);
    }
    readShapes("colliders/shape", colliders, t.collider_shape);
    t.collider_pose = unflattenPoses(carried_position, carried_orientation, colliders);
  }
  need(readDataset(f, "step", t.step, dims), "step");
  shape("step", {frames});
  need(readDataset(f, "phase", phases, dims), "phase");
  shape("phase", {frames});
  need(readDataset(f, "center_of_mass", com, dims), "center_of_mass");
  shape("center_of_mass", {frames, 3});
  need(readDataset(f, "position", position, dims), "position");
  shape("position", {frames, parts, 3});
  need(readDataset(f, "orientation", orientation, dims), "orientation");
  shape("orientation", {frames, parts, 4});

  // into the structure
  for (hsize_t p = 0; p < parts; ++p) {
    t.half_extents.push_back({half[3 * p], half[3 * p + 1], half[3 * p + 2]});
    t.parent.push_back(parents[p]);
  }
  for (hsize_t i = 0; i < frames; ++i) {
    if (phases[i] > static_cast<std::uint8_t>(EvalPhase::measure))
      fail("dataset /phase: value " + std::to_string(phases[i]) + " at frame " + std::to_string(i) +
           " is not a phase");
    t.phase.push_back(static_cast<EvalPhase>(phases[i]));
    t.center_of_mass.push_back({com[3 * i], com[3 * i + 1], com[3 * i + 2]});
  }
  t.poses = unflattenPoses(position, orientation, frames * parts);

  // the light, when recorded
  if (H5Lexists(f, "light", H5P_DEFAULT) > 0) {
    std::vector<double> light;
    need(readDataset(f, "light/position", light, dims), "light/position");
    if (dims != std::vector<hsize_t>{frames, 3})
      fail("dataset /light/position has the wrong shape for " + std::to_string(frames) + " frames");
    for (hsize_t i = 0; i < frames; ++i)
      t.light.push_back({light[3 * i], light[3 * i + 1], light[3 * i + 2]});
  }

  // the terrain, with a heightfield ground
  if (t.ground == "heightfield") {
    need(H5Lexists(f, "ground", H5P_DEFAULT) > 0 &&
             readDataset(f, "ground/heights", t.terrain_heights, dims),
         "ground/heights");
    if (dims.size() != 2 || dims[0] != dims[1] || dims[0] < 2)
      fail("dataset /ground/heights is not a square grid of at least 2 x 2 samples");
    t.terrain_samples = static_cast<int>(dims[0]);
    Handle ground(H5Gopen2(f, "ground", H5P_DEFAULT), H5Gclose);
    if (!ground.valid() || !readScalar(ground.get(), "spacing", t.terrain_spacing) ||
        !(t.terrain_spacing > 0) || !std::isfinite(t.terrain_spacing))
      fail("attribute /ground spacing missing, unreadable or not > 0");
  }

  // the held objects, when the file has any (files without /held hold none)
  if (H5Lexists(f, "held", H5P_DEFAULT) <= 0)
    return t;
  std::vector<std::int32_t> holders;
  need(readDataset(f, "held/half_extents", half, dims), "held/half_extents");
  const hsize_t held = dims.size() == 2 ? dims[0] : 0;
  auto held_shape = [&](const char* name, std::vector<hsize_t> wanted) {
    if (dims != wanted)
      fail(std::string("dataset /") + name + " has the wrong shape for " + std::to_string(frames) +
           " frames and " + std::to_string(held) + " held objects");
  };
  held_shape("held/half_extents", {held, 3});
  need(readDataset(f, "held/part", holders, dims), "held/part");
  held_shape("held/part", {held});
  need(readDataset(f, "held/position", position, dims), "held/position");
  held_shape("held/position", {frames, held, 3});
  need(readDataset(f, "held/orientation", orientation, dims), "held/orientation");
  held_shape("held/orientation", {frames, held, 4});
  need(readDataset(f, "held/released", t.held_released, dims), "held/released");
  held_shape("held/released", {frames, held});
  for (hsize_t k = 0; k < held; ++k) {
    t.held_half_extents.push_back({half[3 * k], half[3 * k + 1], half[3 * k + 2]});
    t.held_part.push_back(holders[k]);
  }
  readShapes("held/shape", held, t.held_shape);
  t.held_poses = unflattenPoses(position, orientation, frames * held);
  return t;
}

}  // namespace cambrian
