// cambrian inspect: print a genome and the body it develops into.
#include "cambrian/body_plan.hpp"
#include "cambrian/error.hpp"
#include "cambrian/genome.hpp"

#include "commands.hpp"
#include "options.hpp"
#include "tasks/juries.hpp"

#include <cstdio>
#include <iostream>

namespace cambrian {

namespace {

const char* jointName(JointType type) {
  static constexpr const char* kNames[] = {"rigid", "revolute", "universal", "spherical"};
  return kNames[static_cast<int>(type)];
}

}  // namespace

int runInspect(int argc, char** argv) {
  CreatureSettings settings;
  std::string genome_path, config_path;

  // options: the genome file is positional
  po::options_description cli(
      "cambrian inspect: print a genome and its body statistics\n\n"
      "usage: cambrian inspect FILE [--config FILE] [settings]\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("genome,g", po::value(&genome_path),
                                                "genome file (text or binary)")(
      "config,c", po::value(&config_path), "INI file with [genome] limits")(
      "body-only", "print only the body statistics, not the genome text");
  po::positional_options_description positional;
  positional.add("genome", 1);
  po::options_description creature = creatureOptions(settings);
  OptionOrigins origins;
  po::variables_map vm = parseOptions(argc, argv, cli, creature, &positional, "config", &origins);
  if (vm.count("help")) {
    std::cout << cli << "\n" << creature << "\n";
    return 0;
  }
  finishCreatureSettings(settings, origins);
  if (genome_path.empty())
    throw Error(ExitCode::usage, "give a genome file to inspect");

  // the genome, checked against the limits
  Genome genome = readGenomeFile(genome_path);
  if (!vm.count("body-only"))
    std::cout << genomeToText(genome);
  try {
    validateGenome(genome, settings.limits);
  } catch (const GenomeError& e) {
    throw GenomeError(genome_path + ": " + e.what());
  }

  // the body it develops into
  BodyPlan plan = develop(genome, settings.limits);
  std::printf(
      "\n# body: %zu parts, %d joints, %d degrees of freedom, %zu sensors, %zu neurons, "
      "%zu effectors%s\n",
      plan.parts.size(), plan.jointCount(), plan.degreesOfFreedom(), plan.sensors.size(),
      plan.neurons.size(), plan.effectors.size(),
      plan.truncated ? " (truncated at genome.max_parts)" : "");
  std::printf("# mass %.4g kg, volume %.4g m^3, body length %.4g m\n", plan.totalMass(),
              plan.totalVolume(), bodyLength(plan));
  std::printf("# %4s %4s %6s  %-9s %-23s %8s %8s\n", "part", "node", "parent", "joint", "size (m)",
              "mass", "x-sect");
  for (std::size_t i = 0; i < plan.parts.size(); ++i) {
    const PartPlan& p = plan.parts[i];
    std::printf("# %4zu %4d %6d  %-9s %6.3f %6.3f %6.3f   %8.3f %8.4f%s\n", i, p.node, p.parent,
                i == 0 ? "-" : jointName(p.joint), p.size.x, p.size.y, p.size.z, p.mass,
                p.cross_section, p.reflected ? "  (mirror)" : "");
  }
  return 0;
}

}  // namespace cambrian
