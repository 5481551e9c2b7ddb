#include "store/hdf5_io.hpp"

#include <filesystem>
#include <system_error>

namespace cambrian::hdf5 {

Handle& Handle::operator=(Handle&& other) noexcept {
  // close the own identifier, then take the other one
  if (this != &other) {
    reset();
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
  }
  return *this;
}

herr_t Handle::reset() {
  // close at most once
  herr_t status = 0;
  if (id_ >= 0 && close_)
    status = close_(id_);
  id_ = -1;
  return status;
}

std::string systemReason() {
  // the innermost message that quotes the system's ("..., errno = 28, error message = '...'")
  std::string reason;
  auto visit = [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
    std::string text = error->desc ? error->desc : "";
    const std::string marker = "error message = '";
    std::size_t at = text.find(marker);
    if (at != std::string::npos) {
      std::size_t end = text.find('\'', at + marker.size());
      *static_cast<std::string*>(data) = text.substr(at + marker.size(), end - at - marker.size());
    }
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, visit, &reason);
  return reason;
}

QuietErrors::QuietErrors() {
  // keep the printer for the destructor
  H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() {
  H5Eset_auto2(H5E_DEFAULT, function_, data_);
}

Handle stringType() {
  // variable length, UTF-8
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  return type;
}

Handle createFile(const std::string& path, H5F_libver_t oldest) {
  // the file format bounds, then the file
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(access.get(), oldest, H5F_LIBVER_LATEST);
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (file < 0) {
    // the failure's error stack outlives the property list's close (systemReason reads it)
    hid_t stack = H5Eget_current_stack();
    access.reset();
    H5Eset_current_stack(stack);
  }
  return Handle(file, H5Fclose);
}

// metadata read attempts of a SWMR reader: the sleeps between them double from a microsecond,
// so 20 wait about a second in all (HDF5's default, 100, can wait for minutes)
constexpr unsigned kSwmrReadAttempts = 20;

Handle openFile(const std::string& path, const char* kind, bool swmr, std::string& problem) {
  // missing, not HDF5, truncated or corrupt
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    problem = std::string("no such ") + kind + " file";
    return Handle();
  }
  if (!std::filesystem::is_regular_file(path, error)) {
    problem = "not a regular file";
    return Handle();
  }
  htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
  if (is_hdf5 == 0) {
    problem = "not an HDF5 file (no HDF5 signature)";
    return Handle();
  }
  if (is_hdf5 < 0) {
    problem = "cannot read the HDF5 signature (unreadable or truncated file)";
    return Handle();
  }

  // read-only, without HDF5's file lock, as the history writer opens it (the flags must agree
  // within a process). A finished file opens plainly: a damaged one then fails at its first bad
  // checksum. Only a file a writer holds (growing, or left so by a crash) needs SWMR reading,
  // whose reader retries a bad checksum with doubling sleeps, by default 100 times (minutes on
  // a damaged file): here a bounded number of times, about a second in all
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(access.get(), false, true);
  Handle file;
  file = Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose);
  if (!file.valid() && swmr) {
    H5Pset_metadata_read_attempts(access.get(), kSwmrReadAttempts);
    file =
        Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, access.get()), H5Fclose);
  }
  if (!file.valid())
    problem = "HDF5 file cannot be opened (truncated or corrupt)";
  return file;
}

Handle openFileForSwmrWriting(const std::string& path) {
  // newest format bounds (SWMR needs them), no file lock
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
  H5Pset_file_locking(access.get(), false, true);
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR | H5F_ACC_SWMR_WRITE, access.get()), H5Fclose);
}

bool writeString(hid_t location, const char* name, const std::string& value) {
  // a scalar attribute holding one pointer to the text
  Handle type = stringType();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  const char* text = value.c_str();
  return attribute.valid() && H5Awrite(attribute.get(), type.get(), &text) >= 0;
}

bool writeStrings(hid_t location, const char* name, const std::vector<std::string>& values) {
  // a 1-D attribute holding one pointer per text
  Handle type = stringType();
  hsize_t size = values.size();
  Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose);
  Handle attribute(H5Acreate2(location, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  std::vector<const char*> texts;
  for (const std::string& value : values)
    texts.push_back(value.c_str());
  // an empty list is an attribute of no elements: nothing to write into it
  return attribute.valid() &&
         (texts.empty() || H5Awrite(attribute.get(), type.get(), texts.data()) >= 0);
}

bool describe(hid_t location, const char* units, const char* description) {
  return writeString(location, "units", units) && writeString(location, "description", description);
}

bool writeFormat(hid_t file, const char* format, std::int32_t version,
                 const std::string& cambrian_version, const std::string& git_hash) {
  return writeString(file, "format", format) &&
         writeScalar<std::int32_t>(file, "format_version", version) &&
         writeString(file, "cambrian_version", cambrian_version) &&
         writeString(file, "git_hash", git_hash);
}

bool readString(hid_t location, const char* name, std::string& value) {
  // a scalar string attribute
  if (H5Aexists(location, name) <= 0)
    return false;
  Handle attribute(H5Aopen(location, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING)
    return false;
  Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1)
    return false;

  // variable length: HDF5 allocates the text
  if (H5Tis_variable_str(type.get()) > 0) {
    Handle memory = stringType();
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0 || !text)
      return false;
    value = text;
    H5free_memory(text);
    return true;
  }

  // fixed length: up to the first NUL
  std::string buffer(H5Tget_size(type.get()), '\0');
  if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0)
    return false;
  value = buffer.substr(0, buffer.find('\0'));
  return true;
}

bool readStrings(hid_t location, const char* name, std::vector<std::string>& values) {
  // a 1-D attribute of variable-length strings
  if (H5Aexists(location, name) <= 0)
    return false;
  Handle attribute(H5Aopen(location, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING ||
      H5Tis_variable_str(type.get()) <= 0)
    return false;
  hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0)
    return false;
  std::vector<char*> texts(static_cast<std::size_t>(count), nullptr);
  Handle memory = stringType();
  if (count > 0 && H5Aread(attribute.get(), memory.get(), texts.data()) < 0)
    return false;
  values.clear();
  for (char* text : texts) {
    values.emplace_back(text ? text : "");
    H5free_memory(text);
  }
  return true;
}

std::string checkFormat(hid_t file, const char* kind, const char* format, std::int32_t newest,
                        std::int32_t& version) {
  // the format name
  std::string found;
  if (!readString(file, "format", found))
    return std::string("not a cambrian ") + kind +
           " (HDF5 file without the root attribute 'format')";
  if (found != format)
    return std::string("not a cambrian ") + kind + " (root attribute 'format' is '" + found +
           "', expected '" + format + "')";

  // a version this cambrian reads
  if (!readScalar(file, "format_version", version))
    return "root attribute 'format_version' missing or not an integer";
  if (version < 1 || version > newest)
    return "format_version " + std::to_string(version) + " is not supported (this cambrian reads " +
           std::to_string(newest) + ")";
  return "";
}

Handle writeDataset(hid_t location, const char* name, const std::vector<hsize_t>& dims, hid_t type,
                    const void* values, hid_t properties) {
  // the dataset, then its values unless it is empty
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle dataset(
      H5Dcreate2(location, name, type, space.get(), H5P_DEFAULT, properties, H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid())
    return dataset;
  hsize_t count = 1;
  for (hsize_t d : dims)
    count *= d;
  if (count > 0 && values &&
      H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    return Handle();
  return dataset;
}

bool writeRows(hid_t dataset, hid_t memory_type, const void* data, hsize_t start, hsize_t rows,
               hsize_t width) {
  Handle file_space(H5Dget_space(dataset), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(file_space.get());
  hsize_t offset[2] = {start, 0};
  hsize_t count[2] = {rows, width};
  if (rank < 1 || rank > 2 ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, offset, nullptr, count, nullptr) < 0)
    return false;
  Handle memory_space(H5Screate_simple(rank, count, nullptr), H5Sclose);
  return H5Dwrite(dataset, memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, data) >=
         0;
}

Handle openDataset(hid_t location, const char* name, int max_rank, std::vector<hsize_t>& dims) {
  // present and openable
  if (H5Lexists(location, name, H5P_DEFAULT) <= 0)
    return Handle();
  Handle dataset(H5Dopen2(location, name, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid())
    return dataset;

  // a simple shape of rank 1 to max_rank
  Handle space(H5Dget_space(dataset.get()), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > max_rank)
    return Handle();
  dims.assign(static_cast<std::size_t>(rank), 0);
  if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) != rank)
    return Handle();
  return dataset;
}

}  // namespace cambrian::hdf5
