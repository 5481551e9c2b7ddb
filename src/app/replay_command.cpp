// cambrian replay: re-simulates a creature stored in a history file, exactly as the evolution's
// worker evaluated it, and checks that the outcome is bit-identical — or re-simulates it under
// changed [physics], [task] or [environment] settings and shows both outcomes side by side.
// Optionally exports its trajectory for rendering (analysis/animate.py) and saves its genome.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"
#include "cambrian/version.hpp"

#include "commands.hpp"
#include "core/settings.hpp"
#include "evolution/population.hpp"
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
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

namespace cambrian {

namespace {

// the sections of a history's config_text that decide how a creature is evaluated
const std::set<std::string> kCreatureSections = {"environment", "genome", "physics", "task"};

// whether a history's fitness is a competitive ranking within each generation
// (evolution.ranking): a lone replay cannot give it back, only the measures it was ranked by
bool rankedRun(const HistoryReader& history) {
  try {
    for (const IniEntry& entry :
         parseIni(history.attributes().config_text, history.path() + ": config_text")) {
      if (entry.key == "evolution.ranking" &&
          entry.value.find_first_not_of(" \t") != std::string::npos)
        return true;
    }
  } catch (const ConfigError&) {
    // creatureSettingsOf names a bad config_text
  }
  return false;
}

// the creature settings of a history: its stored creature sections read with the definitions
// `cambrian evolve` uses; other sections are ignored, unknown creature keys are errors (a
// history of another cambrian version)
CreatureSettings creatureSettingsOf(const HistoryReader& history) {
  CreatureSettings settings;
  try {
    std::vector<IniEntry> entries =
        parseIni(history.attributes().config_text, history.path() + ": config_text");
    // keys newer than the history: what its run used then (friction anchors off, ...)
    SettingsSchema schema;
    settings.declareSettings(schema);
    // (a named pair, not a structured binding: clang 14 cannot capture those)
    for (const auto& earlier : schema.earlierRunValues()) {
      const std::string& key = earlier.first;
      bool stored = std::any_of(entries.begin(), entries.end(),
                                [&key](const IniEntry& entry) { return entry.key == key; });
      if (!stored)
        settings.set(key, earlier.second);
    }
    for (const IniEntry& entry : entries) {
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
  const Individual* best = bestOk(rows, generation);
  if (!best) {
    throw InputError(path + ": no individual with status ok" +
                     (generation ? " in generation " + std::to_string(*generation) : "") +
                     " to replay");
  }
  return *best;
}

// the sections whose settings a replay may change: what the creature is evaluated in and by,
// not what its genome develops into ([genome]) nor anything no evaluation reads
const std::set<std::string> kChangeableSections = {"environment", "physics", "task"};

// the section of a key ("physics" of "physics.time_step")
std::string sectionOf(const std::string& key) {
  return key.substr(0, key.find('.'));
}

// why replay refuses to change `key` (a setting outside kChangeableSections)
std::string whyFixed(const std::string& key) {
  if (sectionOf(key) == "genome") {
    return "replay cannot change [genome] settings: they decide what the stored genome develops "
           "into (save the genome with --save-genome FILE and evaluate it under other limits "
           "with `cambrian simulate --genome FILE --" +
           key + " VALUE`)";
  }
  return "replay changes only [environment], [physics] and [task] settings, the ones a creature "
         "is evaluated under ([" +
         sectionOf(key) + "] is not)";
}

// refuses every given setting a replay cannot change: Error(usage) for the command line,
// ConfigError naming the file for the config file
void refuseFixedSettings(const OptionOrigins& origins) {
  for (const std::string& key : origins.command_line) {
    if (!kChangeableSections.count(sectionOf(key)))
      throw Error(ExitCode::usage, "--" + key + ": " + whyFixed(key));
  }
  for (const std::string& key : origins.config_file) {
    if (!kChangeableSections.count(sectionOf(key)))
      throw ConfigError(origins.config_path + ": " + key + ": " + whyFixed(key));
  }
}

// one setting given for the replay: its key, the stored value and the replayed one (INI text)
struct GivenSetting {
  std::string key;
  std::string stored;
  std::string replayed;
  bool changed() const { return stored != replayed; }
};

// sets on `settings` (the stored ones) every key given on the command line or in the config
// file to its value in `given` (the schema the command line was parsed into), runs the range
// checks (a bad value is a ConfigError naming where it came from) and returns what was given,
// stored against replayed, in declaration order
std::vector<GivenSetting> applyGivenSettings(CreatureSettings& settings,
                                             const SettingsSchema& given,
                                             const OptionOrigins& origins) {
  const CreatureSettings stored = settings;
  SettingsSchema schema;
  settings.declareSettings(schema);
  std::vector<GivenSetting> applied;
  for (const auto& setting : given.settings()) {
    const std::string& key = setting->key();
    if (!origins.command_line.count(key) && !origins.config_file.count(key))
      continue;
    Setting* target = schema.find(key);
    if (target->type() == Setting::Type::list)
      target->reset();  // a list given replaces the stored one
    target->set(setting->text());
    applied.push_back({key, stored.value(key), ""});
  }
  checkSettings(schema, origins);
  for (GivenSetting& item : applied)
    item.replayed = settings.value(item.key);
  return applied;
}

// whether any given setting differs from the stored one
bool anyChanged(const std::vector<GivenSetting>& given) {
  return std::any_of(given.begin(), given.end(), [](const GivenSetting& g) { return g.changed(); });
}

// prints the given settings (changed ones with the stored and the new value) and, when any
// changed, that the stored outcome is shown but not compared
void printGivenSettings(const std::vector<GivenSetting>& given) {
  for (const GivenSetting& item : given) {
    if (item.changed()) {
      std::printf("%-14s %s: stored %s, replayed with %s\n", "changed", item.key.c_str(),
                  item.stored.c_str(), item.replayed.c_str());
    } else {
      std::printf("%-14s %s = %s as stored (unchanged)\n", "setting", item.key.c_str(),
                  item.stored.c_str());
    }
  }
  if (anyChanged(given)) {
    std::printf(
        "note           the stored outcome was made under other settings: it is shown beside the "
        "replayed one, not compared\n");
  }
}

// the trajectory's source: the history, and the changed settings when any
std::string sourceNote(const std::string& history_path, const std::vector<GivenSetting>& given) {
  std::string changes;
  for (const GivenSetting& item : given) {
    if (item.changed())
      changes += (changes.empty() ? "" : "; ") + item.key + " = " + item.replayed + " (stored " +
                 item.stored + ")";
  }
  return changes.empty() ? history_path
                         : history_path + " (replayed under changed settings: " + changes + ")";
}

// refuses an output path that is the history itself (it would replace the history)
void refuseOverwritingHistory(const std::string& option, const std::string& path,
                              const std::string& history_path) {
  std::error_code error;
  if (!path.empty() && std::filesystem::equivalent(path, history_path, error))
    throw Error(ExitCode::usage, option + " " + path + ": that is the history being replayed");
}

// writes the text form of `genome` to `path`, replacing a file there as `simulate --save` does
// (atomically); returns whether a file was replaced. Error(output_file) when it cannot.
bool saveGenome(const std::string& path, const Genotype& genome) {
  std::error_code error;
  bool replaced = std::filesystem::exists(path, error);
  try {
    writeGenomeFile(path, genome);
  } catch (const Error& e) {
    throw Error(e.code(), "--save-genome " + path + ": " + e.what());
  }
  return replaced;
}

// whether two doubles are the same bits
bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// one stored-vs-replayed line; returns whether they match bit for bit (NaN stored = absent).
// Without `compare` (changed settings) both are shown and nothing is marked.
bool compareLine(const char* name, double stored, double replayed, bool compare) {
  bool match = sameBits(stored, replayed) || (std::isnan(stored) && std::isnan(replayed));
  bool marked = compare && !match;
  std::printf("%-14s %-24.17g %.17g%s\n", name, stored, replayed, marked ? "  DIFFERENT" : "");
  if (marked)
    std::printf("%-14s %-24a %a\n", "", stored, replayed);
  return match;
}

// the stored against the replayed outcome, line by line (status, fitness, every measure either
// side has, steps); returns whether all match bit for bit. `compare`: mark differences.
bool compareOutcomes(const HistoryReader& history, const Individual& row, const Outcome& replayed,
                     bool compare) {
  const Outcome& stored = row.outcome;
  std::printf("%-14s %-24s %s\n", "", "stored", "replayed");
  bool match = replayed.status == stored.status;
  std::printf("%-14s %-24s %s%s\n", "status", statusName(stored.status),
              statusName(replayed.status), match || !compare ? "" : "  DIFFERENT");
  // why the replay failed (a stored creature passed: it has no such line)
  if (replayed.status != EvalStatus::ok && !replayed.message.empty())
    std::printf("%-14s %-24s %s\n", "why", "", replayed.message.c_str());
  if (rankedRun(history)) {
    // ranked within its generation (evolution.ranking): shown, not compared
    std::printf(
        "%-14s %-24.17g %.17g  (stored: its rank points in generation %llu, "
        "evolution.ranking; not compared)\n",
        "fitness", row.fitness(), replayed.fitness,
        static_cast<unsigned long long>(row.generation));
  } else {
    match = compareLine("fitness", row.fitness(), replayed.fitness, compare) && match;
  }
  // every measure either side has, by name: the history's columns first
  std::vector<std::string> names;
  for (const MeasureInfo& measure : history.measures())
    names.push_back(measure.name);
  for (const Measure& measure : replayed.measures) {
    if (std::find(names.begin(), names.end(), measure.name) == names.end())
      names.push_back(measure.name);
  }
  for (const std::string& name : names) {
    double a = stored.measure(name), b = replayed.measure(name);
    if (!std::isnan(a) || !std::isnan(b))
      match = compareLine(name.c_str(), a, b, compare) && match;
  }
  match = compareLine("steps", static_cast<double>(stored.steps),
                      static_cast<double>(replayed.steps), compare) &&
          match;
  return match;
}

// what was replayed: the history, notes on the binary, the creature, its body, task and seed
void printHeader(const HistoryReader& history, const Individual& row, const Outcome& outcome,
                 const CreatureSettings& settings, std::uint64_t eval_seed) {
  const HistoryAttributes& attributes = history.attributes();
  std::printf("history        %s (cambrian %s, git %s, seed %llu)\n", history.path().c_str(),
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
  std::printf("task           %s, %g s measured, step %g s\n", settings.task().name().c_str(),
              settings.episode().evaluation_time, settings.physics().time_step);
  std::printf("eval seed      %llu\n", static_cast<unsigned long long>(eval_seed));
}

// an id or a generation: a whole number, not "-1" (which would wrap to 2^64 - 1)
std::uint64_t wholeNumber(const char* option, const std::string& text) {
  std::uint64_t value = 0;
  if (!parseSeed(text, value))
    throw Error(ExitCode::usage, std::string(option) + " " + text +
                                     ": expected a whole number in 0..18446744073709551615");
  return value;
}

// the command line: the options of replay itself; the settings' are added by parseOptions
po::options_description replayOptions(std::string& history_path, std::string& id,
                                      std::string& generation, std::string& export_path,
                                      double& frame_rate, std::string& genome_path,
                                      std::string& config_path) {
  po::options_description cli(
      "cambrian replay: re-simulate a creature of a history file and check that its outcome is\n"
      "bit-identical to the stored one, or re-simulate it under changed [physics], [task] or\n"
      "[environment] settings; optionally export its trajectory for rendering\n"
      "(python3 analysis/animate.py traj.h5 -o creature.gif) and save its genome.\n\n"
      "usage: cambrian replay --history FILE (--id I | --best [--generation G])\n"
      "                       [--export traj.h5] [--frame-rate HZ] [--save-genome FILE]\n"
      "                       [--config FILE] [--physics.KEY V] [--task.KEY V] "
      "[--environment.KEY V]\n\n"
      "The creature settings ([genome], [physics], [task], [environment]) and the run seed are\n"
      "read from the history; the evaluation seed is derived from them as the evolution's\n"
      "workers derive it. --section.key VALUE options and --config FILE (INI, the command line\n"
      "wins) change [physics], [task] and [environment] settings for this replay. A value equal\n"
      "to the stored one changes nothing (the replay is still compared bit for bit); any other\n"
      "is listed (key, stored value, new value), the stored outcome was then made under other\n"
      "settings and is shown beside the replayed one, not compared (exit 0). [genome] settings\n"
      "cannot be changed: they decide what the stored genome develops into.\n"
      "Exit codes: 0 replay matches or ran under changed settings, 10 replayed outcome differs\n"
      "from the stored one, 4 missing or foreign history, unknown id, generation out of range or\n"
      "a creature that failed its evaluation, 5 the export or the genome cannot be written, 3 a\n"
      "bad setting value or --config file, 2 bad command line or a setting replay cannot change\n"
      "(docs/exit-codes.md).\n\n"
      "Options");
  cli.add_options()("help,h", "show this help")("history", po::value(&history_path),
                                                "history.h5 written by `cambrian evolve`")(
      "id", po::value(&id), "replay the individual with this id")(
      "best", "replay the best individual (status ok; ties: lowest id)")(
      "generation", po::value(&generation), "with --best: the best of this generation only")(
      "export", po::value(&export_path),
      "write the trajectory (per-frame part poses) to this HDF5 file")(
      "frame-rate", po::value(&frame_rate)->default_value(frame_rate),
      "frames per simulated second in the export, Hz (rounded to whole physics steps)")(
      "save-genome", po::value(&genome_path),
      "write the creature's genome to this file in the readable text form, which `cambrian "
      "simulate --genome FILE` and evolution.seed_genomes read (an existing file is replaced, "
      "as by simulate --save, and the output says so); the replay still runs")(
      "config,c", po::value(&config_path),
      "INI file of [physics], [task] and [environment] settings to replay under (the command "
      "line wins)");
  return cli;
}

}  // namespace

int runReplay(int argc, char** argv) {
  std::string history_path, export_path, genome_path, config_path, id_text, generation_text;
  double frame_rate = 30;
  po::options_description cli = replayOptions(history_path, id_text, generation_text, export_path,
                                              frame_rate, genome_path, config_path);

  // the settings given on the command line or in --config (the stored ones are the base)
  CreatureSettings given;
  SettingsSchema given_schema;
  given.declareSettings(given_schema);
  OptionOrigins origins;
  po::variables_map vm = parseOptions(argc, argv, cli, given_schema, nullptr, "config", &origins);
  if (vm.count("help")) {
    std::cout << cli << "\nSettings to replay under (default: the value stored in the history):\n"
              << sectionsHelp(given_schema, kChangeableSections) << "\n";
    return 0;
  }
  refuseFixedSettings(origins);

  // exactly one way to name the creature; outputs that do not replace the history
  if (history_path.empty())
    throw Error(ExitCode::usage, "--history FILE is required");
  bool best = vm.count("best") > 0;
  if (best == (vm.count("id") > 0))
    throw Error(ExitCode::usage, "give exactly one of --id I or --best");
  if (vm.count("generation") && !best)
    throw Error(ExitCode::usage, "--generation G only goes with --best");
  refuseOverwritingHistory("--export", export_path, history_path);
  refuseOverwritingHistory("--save-genome", genome_path, history_path);
  if (!export_path.empty() && export_path == genome_path)
    throw Error(ExitCode::usage, "--export and --save-genome name the same file " + export_path);
  // a bad number is refused whether or not it would be used
  std::uint64_t id = vm.count("id") ? wholeNumber("--id", id_text) : 0;
  std::uint64_t generation =
      vm.count("generation") ? wholeNumber("--generation", generation_text) : 0;
  frameStrideFor(frame_rate, 1.0);  // a bad --frame-rate is refused, used or not

  // the history, its settings with the given ones on top, and the creature's row
  HistoryReader history(history_path);
  CreatureSettings settings = creatureSettingsOf(history);
  std::vector<GivenSetting> changes = applyGivenSettings(settings, given_schema, origins);
  const bool compare = !anyChanged(changes);
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
  bool genome_replaced = !genome_path.empty() && saveGenome(genome_path, genome);

  // the evaluation, seeded as the worker seeded it, observed when exporting
  std::uint64_t eval_seed = evaluationSeed(history.attributes().seed, row.id);
  std::optional<TrajectoryRecorder> recorder;
  if (!export_path.empty())
    recorder.emplace(frameStrideFor(frame_rate, settings.physics().time_step));
  Outcome outcome = evaluate(genome, settings, eval_seed, recorder ? &*recorder : nullptr);

  // what was replayed, under which settings, and stored against replayed
  printHeader(history, row, outcome, settings, eval_seed);
  printGivenSettings(changes);
  bool match = compareOutcomes(history, row, outcome, compare);
  std::printf("wall time      %.4f s\n", outcome.wall_seconds);

  // the trajectory, written even when the replay differs (it shows what was replayed)
  if (recorder) {
    Trajectory trajectory = recorder->take();
    trajectory.creature_id = row.id;
    trajectory.source = sourceNote(history_path, changes);
    trajectory.fitness = outcome.fitness;
    trajectory.status = statusName(outcome.status);
    trajectory.task = task.name();
    trajectory.genome_text = genome.encoding().toText(genome);
    writeTrajectory(export_path, trajectory);
    std::printf("export         %s (%zu frames of %zu parts at %g Hz)\n", export_path.c_str(),
                trajectory.frameCount(), trajectory.partCount(), trajectory.frame_rate);
  }
  if (!genome_path.empty()) {
    std::printf("genome         saved to %s (text form)%s\n", genome_path.c_str(),
                genome_replaced ? ", replacing the file that was there" : "");
  }
  if (!compare) {
    std::printf("replay         under changed settings (not compared)\n");
    return 0;
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
