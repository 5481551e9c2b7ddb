// cambrian inspect: print a genome and the body it develops into.
#include "cambrian/body_plan.hpp"
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "commands.hpp"
#include "options.hpp"

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace cambrian {

namespace {

// Prints one genome (unless body_only) and the body it develops into.
void inspectGenome(const std::string& genome_path, const Encoding& encoding, bool body_only) {
  // the genome, checked against the limits
  Genotype genome = readGenomeFile(genome_path);
  if (!body_only)
    std::cout << genome.encoding().toText(genome);
  try {
    encoding.validate(genome);
  } catch (const GenomeError& e) {
    throw GenomeError(genome_path + ": " + e.what());
  }

  // the body it develops into
  Creature creature = encoding.develop(genome);
  const BodyPlan& plan = creature.body;
  std::cout << std::flush;
  std::printf(
      "\n# body: %zu parts, %d joints, %d degrees of freedom, %zu sensors, %zu effectors%s\n",
      plan.parts.size(), plan.jointCount(), plan.degreesOfFreedom(), plan.sensors.size(),
      plan.effectors.size(), plan.truncated ? " (truncated at the encoding's part limit)" : "");
  std::printf("# controller: %s, %d neurons\n",
              creature.controller ? creature.controller->kind().c_str() : "none",
              creature.controller ? creature.controller->neuronCount() : 0);
  std::printf("# mass %.4g kg, volume %.4g m^3, body length %.4g m\n", plan.totalMass(),
              plan.totalVolume(), bodyLength(plan));
  std::printf("# %4s %4s %6s  %-9s %-8s %-23s %8s %8s\n", "part", "node", "parent", "joint",
              "shape", "size (m)", "mass", "x-sect");
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const PartPlan& p = plan.parts[i];
    std::printf("# %4zu %4d %6d  %-9s %-8s %6.3f %6.3f %6.3f   %8.3f %8.4f%s\n", i, p.node,
                p.parent, i == 0 ? "-" : jointName(p.joint), shapeName(p.shape), p.size.x, p.size.y,
                p.size.z, p.mass, p.cross_section, p.reflected ? "  (mirror)" : "");
  }
  std::fflush(stdout);
}

}  // namespace

int runInspect(int argc, char** argv) {
  CreatureSettings settings;
  SettingsSchema schema;
  settings.declareSettings(schema);
  std::vector<std::string> genome_paths;
  std::string config_path;

  // options: the genome file is positional
  po::options_description cli(
      "cambrian inspect: print a genome and its body statistics\n\n"
      "usage: cambrian inspect FILE... [--config FILE] [settings]\n"
      "(several files: each is printed after a line \"==> FILE <==\")\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("genome,g", po::value(&genome_paths),
                                                "genome file(s) (text or binary, any encoding)")(
      "config,c", po::value(&config_path), "INI file with [genome] limits")(
      "body-only", "print only the body statistics, not the genome text");
  po::positional_options_description positional;
  positional.add("genome", -1);
  OptionOrigins origins;
  po::variables_map vm =
      parseOptions(argc, argv, cli, schema, &positional, "config", &origins, kEvolveOnlySections);
  if (vm.count("help")) {
    std::cout << optionsHelp(cli, schema) << "\n";
    return 0;
  }
  if (genome_paths.empty())
    throw Error(ExitCode::usage, "give a genome file to inspect");
  adoptGenomeEncoding(genome_paths.front(), schema, origins);
  checkSettings(schema, origins);

  const Encoding& encoding = settings.encoding();
  for (std::size_t i = 0; i < genome_paths.size(); ++i) {
    if (genome_paths.size() > 1)
      std::printf("%s==> %s <==\n", i == 0 ? "" : "\n", genome_paths[i].c_str());
    std::fflush(stdout);
    inspectGenome(genome_paths[i], encoding, vm.count("body-only") > 0);
  }
  return 0;
}

}  // namespace cambrian
