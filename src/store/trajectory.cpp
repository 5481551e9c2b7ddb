#include "store/trajectory.hpp"

#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <sstream>
#include <type_traits>
#include <unistd.h>

namespace cambrian {

namespace {

// one HDF5 identifier, closed with the matching function
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), close_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle& operator=(Handle&&) = delete;
  ~Handle() { reset(); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  herr_t reset() {
    herr_t status = 0;
    if (id_ >= 0 && close_)
      status = close_(id_);
    id_ = -1;
    return status;
  }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

// silences HDF5's error stack printing while alive (errors become ours)
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

// the native HDF5 type of a C++ value type
template <class T>
hid_t nativeType() {
  if constexpr (std::is_same_v<T, std::uint64_t>)
    return H5T_NATIVE_UINT64;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return H5T_NATIVE_INT32;
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return H5T_NATIVE_UINT8;
  else
    return H5T_NATIVE_DOUBLE;
}

// the phase names, index = EvalPhase value
const std::vector<std::string>& phaseNames() {
  static const std::vector<std::string> names = {
      phaseName(EvalPhase::settle), phaseName(EvalPhase::trial), phaseName(EvalPhase::resettle),
      phaseName(EvalPhase::measure)};
  return names;
}

// a variable-length UTF-8 string type
Handle stringType() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

// attribute writers: false on failure (the caller names the file)
bool writeString(hid_t location, const char* name, const std::string& value) {
  Handle type = stringType();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  const char* text = value.c_str();
  return attribute.valid() && H5Awrite(attribute.get(), type.get(), &text) >= 0;
}

bool writeStrings(hid_t location, const char* name, const std::vector<std::string>& values) {
  Handle type = stringType();
  hsize_t size = values.size();
  Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  std::vector<const char*> texts;
  for (const std::string& value : values)
    texts.push_back(value.c_str());
  return attribute.valid() && H5Awrite(attribute.get(), type.get(), texts.data()) >= 0;
}

template <class T>
bool writeScalar(hid_t location, const char* name, T value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(
      H5Acreate2(location, name, nativeType<T>(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), nativeType<T>(), &value) >= 0;
}

// attribute readers: false when missing or of the wrong kind
bool readString(hid_t location, const char* name, std::string& value) {
  if (H5Aexists(location, name) <= 0)
    return false;
  Handle attribute(H5Aopen(location, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING)
    return false;
  Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1)
    return false;
  if (H5Tis_variable_str(type.get()) > 0) {
    Handle memory = stringType();
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0 || !text)
      return false;
    value = text;
    H5free_memory(text);
    return true;
  }
  std::string buffer(H5Tget_size(type.get()), '\0');
  if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0)
    return false;
  value = buffer.substr(0, buffer.find('\0'));
  return true;
}

template <class T>
bool readScalar(hid_t location, const char* name, T& value) {
  if (H5Aexists(location, name) <= 0)
    return false;
  Handle attribute(H5Aopen(location, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  Handle space(H5Aget_space(attribute.get()), H5Sclose);
  H5T_class_t wanted = std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
  if (!type.valid() || H5Tget_class(type.get()) != wanted ||
      H5Sget_simple_extent_npoints(space.get()) != 1)
    return false;
  return H5Aread(attribute.get(), nativeType<T>(), &value) >= 0;
}

// a dataset of `dims` holding `values` (row-major), with units and a description
bool writeDataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t type,
                  const void* values, const char* units, const char* description) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle dataset(
      H5Dcreate2(location, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid())
    return false;
  hsize_t count = 1;
  for (hsize_t d : dims)
    count *= d;
  if (count > 0 && H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    return false;
  return writeString(dataset.get(), "units", units) &&
         writeString(dataset.get(), "description", description);
}

// a whole dataset as T values; `dims` gets its shape. False when missing or unreadable
template <class T>
bool readDataset(hid_t location, const char* name, std::vector<T>& values,
                 std::vector<hsize_t>& dims) {
  if (H5Lexists(location, name, H5P_DEFAULT) <= 0)
    return false;
  Handle dataset(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
    return false;
  Handle space(H5Dget_space(dataset.get()), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > 3)
    return false;
  dims.assign(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  hsize_t count = 1;
  for (hsize_t d : dims)
    count *= d;
  values.resize(count);
  if (count == 0)
    return true;
  return H5Dread(dataset.get(), nativeType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
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
  bool ok = writeString(file, "format", kTrajectoryFormatName) &&
            writeScalar<std::int32_t>(file, "format_version", kTrajectoryFormatVersion) &&
            writeString(file, "cambrian_version", kVersion) &&
            writeString(file, "git_hash", kGitHash) &&
            writeScalar<std::uint64_t>(file, "creature_id", t.creature_id) &&
            writeString(file, "source", t.source) && writeScalar(file, "fitness", t.fitness) &&
            writeString(file, "status", t.status) && writeString(file, "task", t.task) &&
            writeScalar(file, "time_step", t.time_step) &&
            writeScalar<std::uint64_t>(file, "frame_stride", t.frame_stride) &&
            writeScalar(file, "frame_rate", t.frame_rate) &&
            writeString(file, "genome_text", t.genome_text);
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
  for (const Transform& pose : t.poses) {
    position.insert(position.end(), {pose.position.x, pose.position.y, pose.position.z});
    orientation.insert(orientation.end(),
                       {pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w});
  }
  what = "the frame datasets";
  ok = writeDataset(file, "time", {frames}, H5T_NATIVE_DOUBLE, t.time.data(), "s",
                    "simulated time of each frame") &&
       writeDataset(file, "step", {frames}, H5T_NATIVE_UINT64, t.step.data(), "1",
                    "physics steps taken before each frame (0: at birth)") &&
       writeDataset(file, "phase", {frames}, H5T_NATIVE_UINT8, phases.data(), "1",
                    "phase of each frame; index into the names attribute") &&
       writeDataset(file, "center_of_mass", {frames, 3}, H5T_NATIVE_DOUBLE, com.data(), "m",
                    "mass-weighted centre of the parts, world frame (z up)") &&
       writeDataset(file, "position", {frames, parts, 3}, H5T_NATIVE_DOUBLE, position.data(), "m",
                    "world position of each part's centre, frame x part x (x, y, z)") &&
       writeDataset(file, "orientation", {frames, parts, 4}, H5T_NATIVE_DOUBLE, orientation.data(),
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
  return writeDataset(group.get(), "half_extents", {parts, 3}, H5T_NATIVE_DOUBLE, half.data(), "m",
                      "half the box size along the part's own x, y, z axes") &&
         writeDataset(group.get(), "parent", {parts}, H5T_NATIVE_INT32, parents.data(), "1",
                      "index of the parent part; -1 for the root");
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(std::uint64_t stride)
    : stride_(std::max<std::uint64_t>(1, stride)) {
  trajectory_.frame_stride = stride_;
}

void TrajectoryRecorder::begin(const BodyPlan& plan, const PhysicsSettings& physics) {
  // a fresh recording of this body
  Trajectory fresh;
  fresh.frame_stride = stride_;
  fresh.time_step = physics.time_step;
  fresh.frame_rate = 1.0 / (static_cast<double>(stride_) * physics.time_step);
  for (const PartPlan& part : plan.parts) {
    fresh.half_extents.push_back(part.size * 0.5);
    fresh.parent.push_back(part.parent);
  }
  trajectory_ = std::move(fresh);
}

void TrajectoryRecorder::frame(const EvalFrame& frame) {
  trajectory_.time.push_back(frame.time);
  trajectory_.step.push_back(frame.step);
  trajectory_.phase.push_back(frame.phase);
  trajectory_.center_of_mass.push_back(frame.center_of_mass);
  trajectory_.poses.insert(trajectory_.poses.end(), frame.poses.begin(), frame.poses.end());
}

std::uint64_t frameStrideFor(double frame_rate, double time_step) {
  // both must be positive and finite
  if (!(frame_rate > 0) || !std::isfinite(frame_rate)) {
    std::ostringstream message;
    message << "frame rate = " << frame_rate << " Hz: must be > 0";
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
  if (t.parent.size() != parts || t.step.size() != frames || t.phase.size() != frames ||
      t.center_of_mass.size() != frames || t.poses.size() != frames * parts) {
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
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
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
  for (hsize_t k = 0; k < frames * parts; ++k) {
    Transform pose;
    pose.position = {position[3 * k], position[3 * k + 1], position[3 * k + 2]};
    pose.rotation = {orientation[4 * k + 3], orientation[4 * k], orientation[4 * k + 1],
                     orientation[4 * k + 2]};
    t.poses.push_back(pose);
  }
  return t;
}

}  // namespace cambrian
