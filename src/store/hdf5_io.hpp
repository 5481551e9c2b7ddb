// cambrian: the HDF5 helpers the store module's files share (history, checkpoint, trajectory).
// Private to src/store: nothing outside the module includes <hdf5.h>.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace cambrian::hdf5 {

/// One HDF5 identifier, closed with the matching function (H5Fclose, H5Dclose, ...) when the
/// handle goes away. Movable, not copyable; an invalid handle holds a negative identifier.
class Handle {
 public:
  /// An invalid handle.
  Handle() = default;
  /// Owns `id` (which may be negative: an invalid handle) and closes it with `closer`.
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), close_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  /// Takes the identifier of `other`, which becomes invalid.
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  /// Closes the own identifier, then takes the one of `other`, which becomes invalid.
  Handle& operator=(Handle&& other) noexcept;
  /// Closes the identifier.
  ~Handle() { reset(); }
  /// The identifier (negative when invalid).
  hid_t get() const { return id_; }
  /// Whether the identifier is a valid one.
  bool valid() const { return id_ >= 0; }
  /// Closes the identifier now; the close function's status (0 when there was nothing to close).
  herr_t reset();

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

/// The operating system's reason for the last failed HDF5 call on this thread, as HDF5's error
/// stack records it ("No space left on device", "Disk quota exceeded", ...), or "" when the
/// failure was not the system's. Call before the next HDF5 call clears the stack.
std::string systemReason();

/// Silences HDF5's error stack printing for the lifetime of the object (errors become ours).
class QuietErrors {
 public:
  /// Saves the current error printer and switches printing off.
  QuietErrors();
  /// Restores the saved error printer.
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

/// The native HDF5 type of a C++ value type: uint64, int32, uint8, or double for anything else.
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

/// A variable-length UTF-8 string type.
Handle stringType();

/// Creates (truncating) the HDF5 file `path`, written in formats no older than `oldest`; an
/// invalid handle on failure.
Handle createFile(const std::string& path, H5F_libver_t oldest);

/// Opens the existing HDF5 file `path` read-only (first for SWMR reading when `swmr`). On
/// failure the handle is invalid and `problem` says why, the file called a "`kind` file":
/// missing, not a regular file, without the HDF5 signature, unreadable, truncated or corrupt.
Handle openFile(const std::string& path, const char* kind, bool swmr, std::string& problem);

/// Reopens the existing cambrian file `path` (written in the newest format) for SWMR writing,
/// without HDF5's file lock, so that a reader holding the file open does not stop the writer
/// (the caller keeps other writers out); an invalid handle on failure.
Handle openFileForSwmrWriting(const std::string& path);

/// Writes a scalar variable-length string attribute; false on failure (the caller names the
/// file).
bool writeString(hid_t location, const char* name, const std::string& value);

/// Writes a 1-D variable-length string attribute; false on failure.
bool writeStrings(hid_t location, const char* name, const std::vector<std::string>& values);

/// Writes a scalar attribute of T's native type; false on failure.
template <class T>
bool writeScalar(hid_t location, const char* name, T value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(
      H5Acreate2(location, name, nativeType<T>(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), nativeType<T>(), &value) >= 0;
}

/// Writes the string attributes "units" and "description" of a dataset or group; false on
/// failure.
bool describe(hid_t location, const char* units, const char* description);

/// Writes the root attributes every cambrian file starts with, in this order: format,
/// format_version, cambrian_version, git_hash. False on failure.
bool writeFormat(hid_t file, const char* format, std::int32_t version,
                 const std::string& cambrian_version, const std::string& git_hash);

/// Reads a scalar string attribute (variable or fixed length); false when missing or of
/// another kind.
bool readString(hid_t location, const char* name, std::string& value);

/// Reads a 1-D variable-length string attribute; false when missing or of another kind.
bool readStrings(hid_t location, const char* name, std::vector<std::string>& values);

/// Reads a scalar attribute into T (integer attributes for integer T, floating-point ones for
/// floating-point T); false when missing or of another kind.
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

/// Checks the root attributes 'format' (must be `format`) and 'format_version' (1 to
/// `newest`) of a cambrian `kind` ("history", "checkpoint"), reading the version into `version`.
/// Empty when they are fine, else what is wrong.
std::string checkFormat(hid_t file, const char* kind, const char* format, std::int32_t newest,
                        std::int32_t& version);

/// Creates a fixed-size dataset of shape `dims` (`type` in the file and in memory) with the
/// creation properties `properties` and writes `values` (row-major) into it (nothing where
/// `values` is null: the caller writes the rows); an invalid handle on failure.
Handle writeDataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t type,
                    const void* values, hid_t properties = H5P_DEFAULT);

/// Writes `rows` rows of `width` values (a 1-D dataset: width 1) into `dataset` from row `start`
/// on; false on failure.
bool writeRows(hid_t dataset, hid_t memory_type, const void* data, hsize_t start, hsize_t rows,
               hsize_t width);

/// Opens the dataset `name` below `location` and reads its shape into `dims`; an invalid handle
/// when it is missing, cannot be opened or its rank is not 1 to `max_rank`.
Handle openDataset(hid_t location, const char* name, int max_rank, std::vector<hsize_t>& dims);

/// Reads all `count` values of an open dataset as T into `values`; false when unreadable.
template <class T>
bool readValues(hid_t dataset, hsize_t count, std::vector<T>& values) {
  values.resize(count);
  return count == 0 ||
         H5Dread(dataset, nativeType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
}

}  // namespace cambrian::hdf5
