// Fuzz target: experiment files (INI), read as `cambrian evolve --config FILE` reads them: parsed
// into every key of evolve's schema, then range-checked. A file refused ends in cambrian::Error.
#include "cambrian/error.hpp"

#include "fuzz/experiment_settings.hpp"
#include "fuzz/fuzz_file.hpp"
#include "options.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static cambrian::fuzz::FuzzFile file("experiment.ini");
  const std::string& path = file.write(data, size);
  cambrian::fuzz::ExperimentSettings settings;
  cambrian::po::options_description cli("Command line");
  cli.add_options()("config,c", cambrian::po::value<std::string>(), "experiment file (INI)");
  const char* argv[] = {"cambrian", "--config", path.c_str()};
  try {
    cambrian::OptionOrigins origins;
    cambrian::parseOptions(3, argv, cli, settings.schema, nullptr, "config", &origins);
    cambrian::checkSettings(settings.schema, origins);
    settings.schema.iniText();
  } catch (const cambrian::Error&) {
  }
  return 0;
}
