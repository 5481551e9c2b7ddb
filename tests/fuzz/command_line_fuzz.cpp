// Fuzz target: command lines, parsed as `cambrian evolve` parses them (every key as
// --section.key, the short forms, the config option naming no file) and range-checked. The
// fuzzer's bytes are the arguments, separated by NUL bytes. A command line refused ends in
// cambrian::Error.
#include "cambrian/error.hpp"

#include "fuzz/experiment_settings.hpp"
#include "options.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

// the arguments after the program name: the bytes split at NUL, at most 64 of them
std::vector<std::string> arguments(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> out(1);
  for (std::size_t i = 0; i < size && out.size() <= 64; ++i) {
    if (data[i] == 0)
      out.emplace_back();
    else
      out.back() += static_cast<char>(data[i]);
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words = arguments(data, size);
  std::vector<const char*> argv = {"cambrian"};
  for (const std::string& word : words)
    argv.push_back(word.c_str());

  cambrian::fuzz::ExperimentSettings settings;
  std::string seed, out;
  bool quiet = false, fresh = false;
  cambrian::po::options_description cli("Command line");
  cli.add_options()("help,h", "print this help")("seed", cambrian::po::value(&seed), "run seed")(
      "out,o", cambrian::po::value(&out), "output folder")(
      "quiet,q", cambrian::po::bool_switch(&quiet), "quiet")(
      "fresh", cambrian::po::bool_switch(&fresh), "start over");
  try {
    cambrian::OptionOrigins origins;
    // no config option: the arguments never name a file to read
    cambrian::parseOptions(static_cast<int>(argv.size()), argv.data(), cli, settings.schema,
                           nullptr, "", &origins);
    cambrian::checkSettings(settings.schema, origins);
    settings.schema.iniText();
  } catch (const cambrian::Error&) {
  }
  return 0;
}
