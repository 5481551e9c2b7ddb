// cambrian: errors and the exit codes every subcommand returns.
#pragma once

#include <stdexcept>
#include <string>

namespace cambrian {

/// Process exit codes, documented in docs/exit-codes.md. Stable: scripts depend on them.
enum class ExitCode : int {
  ok = 0,
  failure = 1,         ///< an unexpected internal error
  usage = 2,           ///< unknown option, missing argument, bad command line
  config = 3,          ///< an experiment/config file or option value is invalid
  input_file = 4,      ///< a genome, history or checkpoint file is missing, malformed or foreign
  output_file = 5,     ///< an output file could not be written
  checkpoint = 6,      ///< a checkpoint does not match the experiment it is resumed with
  mpi = 7,             ///< wrong rank count or an MPI-level failure (rank named in the message)
  worker_failure = 8,  ///< a worker rank hit an unrecoverable error
  interrupted = 9,     ///< stopped by a signal before a clean checkpoint could be written
  /// a replayed creature's outcome differs from the one its history stores (cambrian replay)
  replay_mismatch = 10,
  /// a body broke a physics check: crept at rest or gained unexplained energy (cambrian audit)
  audit_failed = 11,
};

/// Base of all cambrian errors: a message for people and the exit code for the process.
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

/// A config file, key or option value is invalid; the message names the file, key and value.
class ConfigError : public Error {
 public:
  explicit ConfigError(const std::string& message) : Error(ExitCode::config, message) {}
};

/// An input file (genome, history, checkpoint) is missing, malformed or foreign.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(ExitCode::input_file, message) {}
};

/// A genome breaks a structural rule; the message names the gene and the field.
class GenomeError : public Error {
 public:
  explicit GenomeError(const std::string& message) : Error(ExitCode::input_file, message) {}
};

}  // namespace cambrian
