// cambrian simulate: evaluate one creature and print its outcome.
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/genome.hpp"

#include "commands.hpp"
#include "options.hpp"
#include "store/trajectory.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

namespace cambrian {

int runSimulate(int argc, char** argv) {
  CreatureSettings settings;
  std::string genome_path, config_path, task_name, save_path, export_path;
  SeedValue seed_option{1};
  double frame_rate = 30;

  // command-line-only options; settings come from creatureOptions()
  po::options_description cli(
      "cambrian simulate: evaluate one creature\n\n"
      "usage: cambrian simulate (--genome FILE | --random [--seed N]) "
      "[--task walk|jump|synthetic] [--config FILE] [--export traj.h5] [settings]\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("genome,g", po::value(&genome_path),
                                                "genome file (text or binary)")(
      "random", "evaluate a random genome instead")(
      "seed", po::value(&seed_option)->default_value(seed_option),
      "seed of the random genome and evaluation")(
      "task", po::value(&task_name), "task: walk | jump | synthetic (same as --task.name)")(
      "config,c", po::value(&config_path), "INI file with settings (command line wins)")(
      "save", po::value(&save_path), "write the evaluated genome to this file (text form)")(
      "export", po::value(&export_path),
      "write the trajectory (per-frame part poses, HDF5) for analysis/animate.py")(
      "frame-rate", po::value(&frame_rate)->default_value(frame_rate),
      "frames per simulated second in the export, Hz");
  po::options_description creature = creatureOptions(settings);
  OptionOrigins origins;
  po::variables_map vm = parseOptions(argc, argv, cli, creature, nullptr, "config", &origins);
  if (vm.count("help")) {
    std::cout << cli << "\n" << creature << "\n";
    return 0;
  }
  if (!task_name.empty()) {
    settings.task_name = task_name;
    origins.setOnCommandLine("task.name");
  }
  finishCreatureSettings(settings, origins);

  // the creature
  bool random = vm.count("random") > 0;
  if (random == !genome_path.empty()) {
    throw Error(ExitCode::usage, "give exactly one of --genome FILE or --random");
  }
  const std::uint64_t seed = seed_option.value;
  Genome genome = random ? randomGenome(settings.limits, seed) : readGenomeFile(genome_path);

  // a genome file given by the user is checked against the limits, naming the file (a random
  // genome is valid by construction)
  if (!random) {
    try {
      validateGenome(genome, settings.limits);
    } catch (const GenomeError& e) {
      throw InputError(genome_path + ": " + e.what());
    }
  }
  if (!save_path.empty())
    writeGenomeFile(save_path, genome);
  if (!export_path.empty() && settings.task.kind == TaskKind::synthetic)
    throw Error(ExitCode::usage, "--export: the synthetic task has no bodies to record");

  // evaluate (observed when exporting: the outcome is the same) and report
  std::optional<TrajectoryRecorder> recorder;
  if (!export_path.empty())
    recorder.emplace(frameStrideFor(frame_rate, settings.physics.time_step));
  Outcome outcome = evaluate(genome, settings.limits, settings.task, settings.physics, seed,
                             recorder ? &*recorder : nullptr);
  std::printf("creature   %s\n",
              random ? ("random, seed " + std::to_string(seed)).c_str() : genome_path.c_str());
  std::printf("body       %d parts, %d joints, %d neurons\n", outcome.parts, outcome.joints,
              outcome.neurons);
  std::printf("task       %s, %g s measured, step %g s\n", taskName(settings.task.kind),
              settings.task.evaluation_time, settings.physics.time_step);
  std::printf("status     %s%s%s\n", statusName(outcome.status),
              outcome.message.empty() ? "" : ": ", outcome.message.c_str());
  std::printf("fitness    %.17g\n", outcome.fitness);
  for (const Measure& m : outcome.measures)
    std::printf("%-10s %.17g\n", m.name.c_str(), m.value);
  std::printf("steps      %llu\n", static_cast<unsigned long long>(outcome.steps));
  std::printf("wall time  %.4f s (%.0f steps/s)\n", outcome.wall_seconds,
              outcome.wall_seconds > 0 ? outcome.steps / outcome.wall_seconds : 0.0);

  // the trajectory, with where the creature came from
  if (recorder) {
    Trajectory trajectory = recorder->take();
    trajectory.source = random ? "random genome, seed " + std::to_string(seed) : genome_path;
    trajectory.fitness = outcome.fitness;
    trajectory.status = statusName(outcome.status);
    trajectory.task = taskName(settings.task.kind);
    trajectory.time_step = settings.physics.time_step;
    trajectory.genome_text = genomeToText(genome);
    writeTrajectory(export_path, trajectory);
    std::printf("export     %s (%zu frames of %zu parts at %g Hz)\n", export_path.c_str(),
                trajectory.frameCount(), trajectory.partCount(), trajectory.frame_rate);
  }
  return 0;
}

}  // namespace cambrian
