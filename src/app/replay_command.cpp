// cambrian replay: re-simulates a creature stored in a history file, exactly as the evolution's
// worker evaluated it, checks that the outcome is bit-identical and optionally exports its
// trajectory for rendering (analysis/animate.py).
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/version.hpp"

#include "commands.hpp"
#include "core/settings.hpp"
#include "options.hpp"
#include "physics/physics_settings.hpp"
#include "store/history.hpp"
#include "store/trajectory.hpp"
#include "tasks/episode.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

namespace cambrian {

namespace {

// the sections of a history's config_text that decide how a creature is evaluated
const std::set<std::string> kCreatureSections = {"environment", "genome", "physics", "task"};

// the creature settings of a history: its stored creature sections read with the definitions
// `cambrian evolve` uses; other sections are ignored, unknown creature keys are errors (a
// history of another cambrian version)
CreatureSettings creatureSettingsOf(const HistoryReader& history) {
  CreatureSettings settings;
  try {
    for (const IniEntry& entry :
         parseIni(history.attributes().config_text, history.path() + ": config_text")) {
      std::string section = entry.key.substr(0, entry.key.find('.'));
      if (!kCreatureSections.count(section))
        continue;
      try {
        settings.set(entry.key, entry.value);
      } catch (const ConfigError& e) {
        if (std::string(e.what()).find("unrecognised option") == std::string::npos)
          throw;
        throw InputError(history.path() + ": config_text key " + entry.key +
                         " is unknown to this cambrian " + kVersion +
                         " (the history was written by cambrian " +
                         history.attributes().cambrian_version + ")");
      }
    }
    settings.check();
  } catch (const ConfigError& e) {
    throw InputError(history.path() + ": config_text: " + e.what());
  }
  return settings;
}

// the row of the individual `id` (its first, evaluated row)
const Individual& rowOf(const std::vector<Individual>& rows, std::uint64_t id,
                        const std::string& path) {
  for (const Individual& row : rows) {
    if (row.id == id)
      return row;
  }
  std::uint64_t largest = 0;
  for (const Individual& row : rows)
    largest = std::max(largest, row.id);
  throw InputError(path + ": no individual with id " + std::to_string(id) +
                   (rows.empty() ? " (the history holds no individuals)"
                                 : " (ids run from 0 to " + std::to_string(largest) + ")"));
}

// the best ok row of the whole history, or of generation `generation`; ties: lowest id
const Individual& bestRow(const std::vector<Individual>& rows,
                          std::optional<std::uint64_t> generation, const std::string& path) {
  // the generation must be one the history holds
  if (generation) {
    std::uint64_t last = 0;
    bool any = false;
    for (const Individual& row : rows) {
      last = std::max(last, row.generation);
      any = true;
    }
    if (!any || *generation > last) {
      throw InputError(path + ": generation " + std::to_string(*generation) + " out of range (" +
                       (any ? "the history holds generations 0.." + std::to_string(last)
                            : std::string("the history holds no generations")) +
                       ")");
    }
  }
  const Individual* best = nullptr;
  for (const Individual& row : rows) {
    if (row.outcome.status != EvalStatus::ok || (generation && row.generation != *generation))
      continue;
    if (!best || row.fitness() > best->fitness() ||
        (row.fitness() == best->fitness() && row.id < best->id))
      best = &row;
  }
  if (!best) {
    throw InputError(path + ": no individual with status ok" +
                     (generation ? " in generation " + std::to_string(*generation) : "") +
                     " to replay");
  }
  return *best;
}

// whether two doubles are the same bits
bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// one stored-vs-replayed line; returns whether they match bit for bit (NaN stored = absent)
bool compareLine(const char* name, double stored, double replayed) {
  bool match = sameBits(stored, replayed) || (std::isnan(stored) && std::isnan(replayed));
  std::printf("%-14s %-24.17g %.17g%s\n", name, stored, replayed, match ? "" : "  DIFFERENT");
  if (!match)
    std::printf("%-14s %-24a %a\n", "", stored, replayed);
  return match;
}

}  // namespace

int runReplay(int argc, char** argv) {
  std::string history_path, export_path;
  std::uint64_t id = 0, generation = 0;
  double frame_rate = 30;

  // command-line-only options: the settings come from the history
  po::options_description cli(
      "cambrian replay: re-simulate a creature of a history file and check that its outcome is\n"
      "bit-identical to the stored one; optionally export its trajectory for rendering\n"
      "(python3 analysis/animate.py traj.h5 -o creature.gif).\n\n"
      "usage: cambrian replay --history FILE (--id I | --best [--generation G])\n"
      "                       [--export traj.h5] [--frame-rate HZ]\n\n"
      "The creature settings ([genome], [physics], [task]) and the run seed are read from the\n"
      "history; the evaluation seed is derived from them as the evolution's workers derive it.\n"
      "Exit codes: 0 replay matches, 10 replayed outcome differs from the stored one, 4 missing\n"
      "or foreign history, unknown id, generation out of range or a creature that failed its\n"
      "evaluation, 5 the export cannot be written, 2 bad command line (docs/exit-codes.md).\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("history", po::value(&history_path),
                                                "history.h5 written by `cambrian evolve`")(
      "id", po::value(&id), "replay the individual with this id")(
      "best", "replay the best individual (status ok; ties: lowest id)")(
      "generation", po::value(&generation), "with --best: the best of this generation only")(
      "export", po::value(&export_path),
      "write the trajectory (per-frame part poses) to this HDF5 file")(
      "frame-rate", po::value(&frame_rate)->default_value(frame_rate),
      "frames per simulated second in the export, Hz (rounded to whole physics steps)");
  SettingsSchema no_settings;
  po::variables_map vm = parseOptions(argc, argv, cli, no_settings, nullptr, "");
  if (vm.count("help")) {
    std::cout << cli << "\n";
    return 0;
  }

  // exactly one way to name the creature
  if (history_path.empty())
    throw Error(ExitCode::usage, "--history FILE is required");
  bool best = vm.count("best") > 0;
  if (best == (vm.count("id") > 0))
    throw Error(ExitCode::usage, "give exactly one of --id I or --best");
  if (vm.count("generation") && !best)
    throw Error(ExitCode::usage, "--generation G only goes with --best");
  if (!export_path.empty())
    frameStrideFor(frame_rate, 1.0);

  // the history, its settings and the creature's row
  HistoryReader history(history_path);
  const HistoryAttributes& attributes = history.attributes();
  CreatureSettings settings = creatureSettingsOf(history);
  std::vector<Individual> rows = history.individuals();
  const Individual& row =
      best ? bestRow(rows, vm.count("generation") ? std::optional(generation) : std::nullopt,
                     history_path)
           : rowOf(rows, id, history_path);
  if (row.outcome.status != EvalStatus::ok) {
    throw InputError(history_path + ": individual " + std::to_string(row.id) + " has status " +
                     statusName(row.outcome.status) +
                     " (a failed creature has no outcome to replay; pick one with status ok)");
  }
  const Task& task = settings.task();
  if (!export_path.empty() && !task.needsBody())
    throw Error(ExitCode::usage, "--export: the " + task.name() + " task has no bodies to record");
  const Genotype& genome = row.genome;
  const double time_step = settings.physics().time_step;

  // the evaluation, seeded as the worker seeded it, observed when exporting
  std::uint64_t eval_seed = evaluationSeed(attributes.seed, row.id);
  std::optional<TrajectoryRecorder> recorder;
  if (!export_path.empty())
    recorder.emplace(frameStrideFor(frame_rate, time_step));
  Outcome outcome = evaluate(genome, settings, eval_seed, recorder ? &*recorder : nullptr);

  // what was replayed
  std::printf("history        %s (cambrian %s, git %s, seed %llu)\n", history_path.c_str(),
              attributes.cambrian_version.c_str(), attributes.git_hash.c_str(),
              static_cast<unsigned long long>(attributes.seed));
  if (attributes.cambrian_version != kVersion || attributes.git_hash != kGitHash) {
    std::printf(
        "note           replaying with cambrian %s, git %s: a different version or "
        "Bullet build may not reproduce the outcome bit for bit\n",
        kVersion, kGitHash);
  }
  if (attributes.bullet_precision != bulletPrecision()) {
    std::printf(
        "note           the history was evaluated with Bullet %s, this build uses %s: the "
        "outcome will differ\n",
        attributes.bullet_precision.c_str(), bulletPrecision());
  }
  std::printf("creature       id %llu, generation %llu, operator %s\n",
              static_cast<unsigned long long>(row.id),
              static_cast<unsigned long long>(row.generation), originName(row.origin));
  std::printf("body           %d parts, %d joints, %d neurons\n", outcome.parts, outcome.joints,
              outcome.neurons);
  std::printf("task           %s, %g s measured, step %g s\n", task.name().c_str(),
              settings.episode().evaluation_time, time_step);
  std::printf("eval seed      %llu\n", static_cast<unsigned long long>(eval_seed));

  // stored against replayed, bit for bit
  std::printf("%-14s %-24s %s\n", "", "stored", "replayed");
  bool match = outcome.status == row.outcome.status;
  std::printf("%-14s %-24s %s%s\n", "status", statusName(row.outcome.status),
              statusName(outcome.status), match ? "" : "  DIFFERENT");
  match = compareLine("fitness", row.fitness(), outcome.fitness) && match;
  // every measure either side has, by name: the history's columns first
  std::vector<std::string> names;
  for (const MeasureInfo& measure : history.measures())
    names.push_back(measure.name);
  for (const Measure& measure : outcome.measures) {
    if (std::find(names.begin(), names.end(), measure.name) == names.end())
      names.push_back(measure.name);
  }
  for (const std::string& name : names) {
    double stored = row.outcome.measure(name), replayed = outcome.measure(name);
    if (!std::isnan(stored) || !std::isnan(replayed))
      match = compareLine(name.c_str(), stored, replayed) && match;
  }
  match = compareLine("steps", static_cast<double>(row.outcome.steps),
                      static_cast<double>(outcome.steps)) &&
          match;
  std::printf("wall time      %.4f s\n", outcome.wall_seconds);

  // the trajectory, written even when the replay differs (it shows what was replayed)
  if (recorder) {
    Trajectory trajectory = recorder->take();
    trajectory.creature_id = row.id;
    trajectory.source = history_path;
    trajectory.fitness = outcome.fitness;
    trajectory.status = statusName(outcome.status);
    trajectory.task = task.name();
    trajectory.genome_text = genome.encoding().toText(genome);
    writeTrajectory(export_path, trajectory);
    std::printf("export         %s (%zu frames of %zu parts at %g Hz)\n", export_path.c_str(),
                trajectory.frameCount(), trajectory.partCount(), trajectory.frame_rate);
  }
  if (!match) {
    std::printf("replay         DIFFERS from the stored outcome\n");
    std::fprintf(stderr,
                 "cambrian replay: error: %s: individual %llu replayed to fitness %a (%.17g), "
                 "stored %a (%.17g)\n",
                 history_path.c_str(), static_cast<unsigned long long>(row.id), outcome.fitness,
                 outcome.fitness, row.fitness(), row.fitness());
    return static_cast<int>(ExitCode::replay_mismatch);
  }
  std::printf("replay         bit-identical\n");
  return 0;
}

}  // namespace cambrian
