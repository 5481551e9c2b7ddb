// cambrian: main — dispatches to the subcommands and turns errors into documented exit codes.
#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "commands.hpp"

#include <cstring>
#include <iostream>
#include <string>

namespace {

void printUsage(std::ostream& out) {
  out << "cambrian " << cambrian::kVersion << " (" << cambrian::kGitHash << ")\n"
      << "Evolves virtual creatures (jointed blocks with neural controllers) in Bullet, under "
         "MPI.\n\n"
      << "usage: cambrian <command> [options]      (cambrian <command> --help for more)\n\n"
      << "commands:\n"
      << "  evolve     run an evolution: mpirun -np N cambrian evolve --config FILE\n"
      << "  simulate   evaluate one creature and print its outcome\n"
      << "  replay     re-simulate a creature of a history.h5 bit for bit; export its trajectory\n"
      << "  inspect    print a genome and its body statistics\n"
      << "  audit      check the physics on many bodies: rest stays rest, energy is explained\n"
      << "  version    print the version and git hash\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
      !std::strcmp(argv[1], "help")) {
    printUsage(std::cout);
    return argc < 2 ? static_cast<int>(cambrian::ExitCode::usage) : 0;
  }
  std::string command = argv[1];

  // subcommands see their own name as argv[0]
  try {
    if (command == "simulate")
      return cambrian::runSimulate(argc - 1, argv + 1);
    if (command == "inspect")
      return cambrian::runInspect(argc - 1, argv + 1);
    if (command == "evolve")
      return cambrian::runEvolve(argc - 1, argv + 1);
    if (command == "replay")
      return cambrian::runReplay(argc - 1, argv + 1);
    if (command == "audit")
      return cambrian::runAudit(argc - 1, argv + 1);
    if (command == "version" || command == "--version") {
      std::cout << "cambrian " << cambrian::kVersion << " (" << cambrian::kGitHash << ")\n";
      return 0;
    }
  } catch (const cambrian::Error& e) {
    std::cerr << "cambrian " << command << ": error: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "cambrian " << command << ": internal error: " << e.what() << "\n";
    return static_cast<int>(cambrian::ExitCode::failure);
  }
  std::cerr << "cambrian: unknown command '" << command << "' (try cambrian --help)\n";
  return static_cast<int>(cambrian::ExitCode::usage);
}
