// cambrian simulate: evaluate one creature and print its outcome.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "commands.hpp"
#include "options.hpp"
#include "physics/physics_settings.hpp"
#include "store/trajectory.hpp"
#include "tasks/episode.hpp"
#include "tasks/task.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

namespace cambrian {

int runSimulate(int argc, char** argv) {
  CreatureSettings settings;
  SettingsSchema schema;
  settings.declareSettings(schema);
  std::string genome_path, config_path, task_name, save_path, export_path, seed_text = "1";
  double frame_rate = 30;

  // command-line-only options; the settings come from the creature settings' schema
  po::options_description cli(
      "cambrian simulate: evaluate one creature\n\n"
      "usage: cambrian simulate (--genome FILE | --random [--seed N]) [--task NAME] "
      "[--config FILE] [--export traj.h5] [settings]\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("genome,g", po::value(&genome_path),
                                                "genome file (text or binary, any encoding)")(
      "random", "evaluate a random genome of the encoding (genome.encoding) instead")(
      "seed", po::value(&seed_text)->default_value(seed_text),
      "seed of the random genome and evaluation")("task", po::value(&task_name),
                                                  "the task (same as --task.name)")(
      "config,c", po::value(&config_path),
      "INI file with settings (command line wins; an experiment file's [evolution] and [run] "
      "keys are passed over)")("save", po::value(&save_path),
                               "write the evaluated genome to this file (text form)")(
      "export", po::value(&export_path),
      "write the trajectory (per-frame part poses, HDF5) for analysis/animate.py")(
      "frame-rate", po::value(&frame_rate)->default_value(frame_rate),
      "frames per simulated second in the export, Hz");
  OptionOrigins origins;
  po::variables_map vm =
      parseOptions(argc, argv, cli, schema, nullptr, "config", &origins, kEvolveOnlySections);
  if (vm.count("help")) {
    std::cout << optionsHelp(cli, schema) << "\n";
    return 0;
  }
  if (!task_name.empty()) {
    schema.set("task.name", task_name);
    origins.setOnCommandLine("task.name");
  }
  adoptGenomeEncoding(genome_path, schema, origins);
  checkSettings(schema, origins);
  std::uint64_t seed = 0;
  if (!parseSeed(seed_text, seed))
    throw Error(ExitCode::usage, "the argument ('" + seed_text +
                                     "') for option '--seed' is invalid: not a seed (0..2^64-1)");

  frameStrideFor(frame_rate, 1.0);  // a bad --frame-rate is refused, used or not

  // the creature
  bool random = vm.count("random") > 0;
  if (random == !genome_path.empty())
    throw Error(ExitCode::usage, "give exactly one of --genome FILE or --random");
  const Encoding& encoding = settings.encoding();
  Genotype genome = random ? encoding.random(seed, 0, 0) : readGenomeFile(genome_path);

  // a genome file given by the user is checked against the limits, naming the file (a random
  // genome is valid by construction)
  if (!random) {
    try {
      encoding.validate(genome);
    } catch (const GenomeError& e) {
      throw InputError(genome_path + ": " + e.what());
    }
  }
  if (!save_path.empty())
    writeGenomeFile(save_path, genome);
  const Task& task = settings.task();
  if (!export_path.empty() && !task.needsBody())
    throw Error(ExitCode::usage, "--export: the " + task.name() + " task has no bodies to record");

  // evaluate (observed when exporting: the outcome is the same) and report
  const double time_step = settings.physics().time_step;
  std::optional<TrajectoryRecorder> recorder;
  if (!export_path.empty())
    recorder.emplace(frameStrideFor(frame_rate, time_step));
  Outcome outcome = evaluate(genome, settings, seed, recorder ? &*recorder : nullptr);
  std::printf("creature   %s\n",
              random ? ("random, seed " + std::to_string(seed)).c_str() : genome_path.c_str());
  std::printf("body       %d parts, %d joints, %d neurons\n", outcome.parts, outcome.joints,
              outcome.neurons);
  std::printf("task       %s, %g s measured, step %g s\n", task.name().c_str(),
              settings.episode().evaluation_time, time_step);
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
    trajectory.task = task.name();
    trajectory.time_step = time_step;
    trajectory.genome_text = encoding.toText(genome);
    writeTrajectory(export_path, trajectory);
    std::printf("export     %s (%zu frames of %zu parts at %g Hz)\n", export_path.c_str(),
                trajectory.frameCount(), trajectory.partCount(), trajectory.frame_rate);
  }
  return 0;
}

}  // namespace cambrian
