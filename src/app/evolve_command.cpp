// cambrian evolve: rank 0 breeds and schedules, ranks 1..N-1 evaluate; one rank evaluates in
// process. Every rank parses the same options; a bad setting ends every rank with
// ExitCode::config before any simulation starts.
#include "cambrian/error.hpp"
#include "cambrian/genome.hpp"

#include "commands.hpp"
#include "evolution/evolution_settings.hpp"
#include "options.hpp"
#include "parallel/evolution_run.hpp"
#include "parallel/mpi_context.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/stop_request.hpp"
#include "parallel/test_kill.hpp"
#include "parallel/worker.hpp"

#include <charconv>
#include <iostream>
#include <malloc.h>
#include <map>
#include <sstream>

namespace cambrian {

namespace {

// everything evolve reads from the command line and the experiment file
struct EvolveSettings {
  CreatureSettings creature;
  EvolutionSettings evolution;
  RunSettings run;
  std::string selection_name = "truncation";
  std::vector<std::string> seed_genomes;
  SeedValue seed;
  std::uint64_t fail_every = 0;
  std::uint64_t test_worker_abort_at = 0;
  std::string dispatch_order_name = "largest_first";
  DispatchSettings dispatch;
  SeedValue dispatch_seed;
};

// the [evolution] and [run] keys
po::options_description evolutionOptions(EvolveSettings& s) {
  EvolutionSettings& e = s.evolution;
  MutationSettings& m = e.mutation;
  po::options_description evolution("[evolution] genetic algorithm");
  evolution.add_options()("evolution.population",
                          po::value(&e.population)->default_value(e.population),
                          "individuals per generation")(
      "evolution.generations", po::value(&e.generations)->default_value(e.generations),
      "generations to run, the first included")(
      "evolution.elite_fraction", po::value(&e.elite_fraction)->default_value(e.elite_fraction),
      "share of the best kept unchanged and not re-evaluated (0..1)")(
      "evolution.mutation_fraction",
      po::value(&e.mutation_fraction)->default_value(e.mutation_fraction),
      "share of offspring made by mutation (the three fractions sum to 1)")(
      "evolution.crossover_fraction",
      po::value(&e.crossover_fraction)->default_value(e.crossover_fraction),
      "share of offspring made by crossover")(
      "evolution.graft_fraction", po::value(&e.graft_fraction)->default_value(e.graft_fraction),
      "share of offspring made by grafting")(
      "evolution.mutation_rate", po::value(&m.parameter_rate)->default_value(m.parameter_rate),
      "chance each parameter of an asexual offspring is perturbed (0..1)")(
      "evolution.mutation_perturbation", po::value(&m.perturbation)->default_value(m.perturbation),
      "perturbation scale, fraction of each parameter's range")(
      "evolution.add_node_rate", po::value(&m.add_node_rate)->default_value(m.add_node_rate),
      "chance a mutation adds a node")(
      "evolution.remove_node_rate",
      po::value(&m.remove_node_rate)->default_value(m.remove_node_rate),
      "chance a mutation removes a node")(
      "evolution.add_connection_rate",
      po::value(&m.add_connection_rate)->default_value(m.add_connection_rate),
      "chance a mutation adds a connection")(
      "evolution.remove_connection_rate",
      po::value(&m.remove_connection_rate)->default_value(m.remove_connection_rate),
      "chance a mutation removes a connection")(
      "evolution.repoint_rate", po::value(&m.repoint_rate)->default_value(m.repoint_rate),
      "chance each connection is re-pointed")(
      "evolution.add_neuron_rate", po::value(&m.add_neuron_rate)->default_value(m.add_neuron_rate),
      "chance a mutation adds a neuron")(
      "evolution.remove_neuron_rate",
      po::value(&m.remove_neuron_rate)->default_value(m.remove_neuron_rate),
      "chance a mutation removes a neuron")(
      "evolution.keep_unconnected",
      po::value(&m.keep_unconnected)->default_value(m.keep_unconnected),
      "keep nodes unreachable from the root (Chaumont) instead of collecting them")(
      "evolution.post_crossover_mutation_chance",
      po::value(&e.post_crossover_mutation_chance)->default_value(e.post_crossover_mutation_chance),
      "chance an offspring of crossover or grafting is then mutated")(
      "evolution.post_crossover_mutation_rate",
      po::value(&e.post_crossover_mutation_rate)->default_value(e.post_crossover_mutation_rate),
      "per-parameter rate of that mutation")(
      "evolution.selection", po::value(&s.selection_name)->default_value(s.selection_name),
      "parent selection: truncation | tournament | roulette | sus | rank")(
      "evolution.truncation_fraction",
      po::value(&e.selection.truncation_fraction)->default_value(e.selection.truncation_fraction),
      "truncation: share of the best that may be parents")(
      "evolution.tournament_size",
      po::value(&e.selection.tournament_size)->default_value(e.selection.tournament_size),
      "tournament: contestants per pick")(
      "evolution.rank_pressure",
      po::value(&e.selection.rank_pressure)->default_value(e.selection.rank_pressure),
      "rank: expected picks of the best (1..2)")(
      "evolution.seed_genomes", po::value(&s.seed_genomes)->composing(),
      "genome files the first generation starts from (repeat the key or separate by spaces)");

  po::options_description run("[run] this run");
  s.seed.value = e.seed;
  run.add_options()("run.seed", po::value(&s.seed)->default_value(s.seed),
                    "run seed, 0..2^64-1 (same seed, same run)")(
      "run.out", po::value(&s.run.out_dir)->default_value(s.run.out_dir),
      "output directory (history.h5, individuals.tsv, generations.tsv)")(
      "run.quiet", po::value(&s.run.quiet)->default_value(s.run.quiet),
      "no progress lines, only the digest")("run.verbose",
                                            po::value(&s.run.verbose)->default_value(s.run.verbose),
                                            "timing details after each progress line")(
      "run.fail_every", po::value(&s.fail_every)->default_value(s.fail_every),
      "testing: workers fail every creature whose id is a multiple of this (0 = never)")(
      "run.test_worker_abort_at",
      po::value(&s.test_worker_abort_at)->default_value(s.test_worker_abort_at),
      "testing: the worker rank that receives the creature with this id stops with an "
      "unrecoverable error, ending the job with exit code 8 (0 = never)")(
      "run.dispatch_order", po::value(&s.dispatch_order_name)->default_value(s.dispatch_order_name),
      "order in which a generation's creatures are handed out: largest_first (genome size) | "
      "shuffled | smallest_first; results are the same, only the span changes")(
      "run.dispatch_seed", po::value(&s.dispatch_seed)->default_value(s.dispatch_seed),
      "shuffled: seed of the per-generation permutations (0 = the run seed)")(
      "run.checkpoint_every",
      po::value(&s.run.checkpoint_every)->default_value(s.run.checkpoint_every),
      "write DIR/checkpoint.h5 every this many generations (0 = no generation cadence; a "
      "checkpoint always follows the last generation and precedes a clean stop)")(
      "run.checkpoint_minutes",
      po::value(&s.run.checkpoint_minutes)->default_value(s.run.checkpoint_minutes),
      "... or when this many minutes passed since the last one, whichever comes first (0 = off)")(
      "run.max_hours", po::value(&s.run.max_hours)->default_value(s.run.max_hours),
      "stop cleanly (checkpoint, exit 0) before this many hours of wall time: no generation "
      "starts that the measured times say would not end in time (0 = no limit)")(
      "run.test_kill_at", po::value(&s.run.test_kill_at)->default_value(s.run.test_kill_at),
      "testing: rank 0 SIGKILLs itself at POINT:GENERATION, POINT one of evaluation, history, "
      "checkpoint_write, checkpoint_rename, checkpoint_done");

  po::options_description all("Evolution settings (INI sections [evolution], [run])");
  all.add(evolution).add(run);
  return all;
}

// the checkpoint and time-limit keys; throws ConfigError naming the key and value
void checkRunSettings(const RunSettings& run) {
  if (run.checkpoint_every < 0)
    throw ConfigError("run.checkpoint_every = " + std::to_string(run.checkpoint_every) +
                      ": must be >= 0");
  if (!(run.checkpoint_minutes >= 0))
    throw ConfigError("run.checkpoint_minutes = " + std::to_string(run.checkpoint_minutes) +
                      ": must be >= 0");
  if (!(run.max_hours >= 0))
    throw ConfigError("run.max_hours = " + std::to_string(run.max_hours) + ": must be >= 0");
  setTestKillPoint(run.test_kill_at);
}

// splits "a.txt b.txt,c.txt" lists into single paths
std::vector<std::string> splitList(const std::vector<std::string>& values) {
  std::vector<std::string> items;
  for (std::string value : values) {
    for (char& c : value) {
      if (c == ',')
        c = ' ';
    }
    std::istringstream words(value);
    std::string word;
    while (words >> word)
      items.push_back(word);
  }
  return items;
}

// one option value as INI text (numbers in the shortest form that reads back exactly)
std::string valueText(const boost::any& value) {
  char number[64];
  if (const auto* v = boost::any_cast<double>(&value))
    return std::string(number, std::to_chars(number, number + sizeof number, *v).ptr);
  if (const auto* v = boost::any_cast<float>(&value))
    return std::string(number, std::to_chars(number, number + sizeof number, *v).ptr);
  if (const auto* v = boost::any_cast<bool>(&value))
    return *v ? "true" : "false";
  if (const auto* v = boost::any_cast<std::string>(&value))
    return *v;
  if (const auto* v = boost::any_cast<int>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<unsigned>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<long>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<unsigned long>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<long long>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<unsigned long long>(&value))
    return std::to_string(*v);
  if (const auto* v = boost::any_cast<SeedValue>(&value))
    return std::to_string(v->value);
  if (const auto* v = boost::any_cast<std::vector<std::string>>(&value)) {
    std::string text;
    for (const std::string& item : *v)
      text += (text.empty() ? "" : " ") + item;
    return text;
  }
  return "?";
}

// the effective settings as INI text: every [section] key = value, sorted (history provenance)
std::string configText(const po::options_description& settings, const po::variables_map& vm) {
  std::map<std::string, std::map<std::string, std::string>> sections;
  for (const auto& option : settings.options()) {
    const std::string& name = option->long_name();
    std::size_t dot = name.find('.');
    if (dot == std::string::npos || !vm.count(name))
      continue;
    sections[name.substr(0, dot)][name.substr(dot + 1)] = valueText(vm[name].value());
  }
  std::string text;
  for (const auto& [section, keys] : sections) {
    text += (text.empty() ? "[" : "\n[") + section + "]\n";
    for (const auto& [key, value] : keys)
      text += key + " = " + value + "\n";
  }
  return text;
}

// what parsing produced: settings, or an exit code and message
struct Setup {
  EvolveSettings settings;
  std::vector<Genome> seeds;
  bool help = false;
  std::string help_text;
};

// parses and checks everything; throws Error with the config code and the file named
Setup parse(int argc, char** argv, bool read_seeds) {
  Setup setup;
  EvolveSettings& s = setup.settings;
  po::options_description settings;
  settings.add(creatureOptions(s.creature)).add(evolutionOptions(s));
  std::string config_path;
  SeedValue seed;
  std::string out;
  bool quiet = false, verbose = false, fresh = false, help_markdown = false;
  double max_hours = 0;
  po::options_description cli("Command line");
  cli.add_options()("help,h", "print this help")(
      "help-markdown", po::bool_switch(&help_markdown),
      "print every experiment file key as Markdown tables (the reference of docs/user-guide.md)")(
      "config,c", po::value(&config_path), "experiment file (INI)")("seed", po::value(&seed),
                                                                    "short for --run.seed")(
      "out,o", po::value(&out), "short for --run.out")("quiet,q", po::bool_switch(&quiet),
                                                       "short for --run.quiet true")(
      "verbose,v", po::bool_switch(&verbose), "short for --run.verbose true")(
      "max-hours", po::value(&max_hours), "short for --run.max_hours")(
      "fresh", po::bool_switch(&fresh),
      "start over even when DIR holds a checkpoint (removes it, overwrites history.h5)");

  OptionOrigins origins;
  po::variables_map vm = parseOptions(argc, argv, cli, settings, nullptr, "config", &origins);
  if (help_markdown) {
    setup.help = true;
    setup.help_text = optionsMarkdown(settings);
    return setup;
  }
  if (vm.count("help")) {
    std::ostringstream text;
    text << "usage: mpirun -np N cambrian evolve --config FILE [--seed S] [--out DIR] [options]\n"
         << "Rank 0 breeds, ranks 1..N-1 evaluate; with one rank it evaluates in process.\n"
         << "Every key works in the INI file ([section] key = value) and as --section.key.\n"
         << "Writes DIR/history.h5 (HDF5, appended and flushed every generation, readable while\n"
         << "the run goes on: provenance attributes, /individuals with genome bytes,\n"
         << "/generations; schema in docs/hdf5-schema.md, Python reader in\n"
         << "analysis/cambrian_history.py) and DIR/individuals.tsv, DIR/generations.tsv at the\n"
         << "end.\n"
         << "Checkpoints: DIR/checkpoint.h5 (atomic, previous kept as checkpoint.prev.h5) every\n"
         << "run.checkpoint_every generations or run.checkpoint_minutes minutes. Running the same\n"
         << "command again continues from it exactly (raise evolution.generations to extend a\n"
         << "finished run; the rank count may differ); --fresh starts over. SIGUSR1 or SIGTERM\n"
         << "(use SIGUSR1 under mpirun) and --max-hours stop cleanly after a generation with a\n"
         << "checkpoint and exit 0. Details in docs/checkpoints.md.\n\n"
         << cli << "\n"
         << optionsHelp(settings);
    setup.help = true;
    setup.help_text = text.str();
    return setup;
  }

  // short forms win over the long keys, in the settings and in the stored settings text
  auto shortForm = [&](const char* key, const boost::any& value) {
    vm.at(key).value() = value;
    origins.setOnCommandLine(key);
  };
  if (vm.count("seed")) {
    s.seed = seed;
    shortForm("run.seed", seed);
  }
  if (vm.count("out")) {
    s.run.out_dir = out;
    shortForm("run.out", out);
  }
  if (quiet) {
    s.run.quiet = true;
    shortForm("run.quiet", true);
  }
  if (verbose) {
    s.run.verbose = true;
    shortForm("run.verbose", true);
  }
  if (vm.count("max-hours")) {
    s.run.max_hours = max_hours;
    shortForm("run.max_hours", max_hours);
  }
  s.evolution.seed = s.seed.value;
  s.run.fresh = fresh;
  s.run.config_text = configText(settings, vm);
  // every setting at its default (keys added since a checkpoint was written compare with these)
  po::variables_map defaults;
  po::store(po::parsed_options(&settings), defaults);
  s.run.default_config_text = configText(settings, defaults);

  // words to enums and range checks, naming the file or the command line the value came from
  try {
    finishCreatureSettings(s.creature);
    s.evolution.selection.method = selectionMethodFromName(s.selection_name);
    s.evolution.seed_genomes = splitList(s.seed_genomes);
    validateEvolutionSettings(s.evolution);
    checkRunSettings(s.run);
    s.dispatch.order = dispatchOrderFromName(s.dispatch_order_name);
    s.dispatch.seed = s.dispatch_seed.value;
  } catch (const ConfigError& e) {
    throw ConfigError(locateSettingError(e.what(), origins));
  }

  // seed genomes (rank 0 only), checked against the limits
  if (read_seeds) {
    for (const std::string& path : s.evolution.seed_genomes) {
      Genome genome = readGenomeFile(path);
      try {
        validateGenome(genome, s.creature.limits);
      } catch (const Error& e) {
        throw InputError(path + ": " + e.what());
      }
      setup.seeds.push_back(std::move(genome));
    }
  }
  return setup;
}

}  // namespace

int runEvolve(int argc, char** argv) {
  // SIGTERM / SIGUSR1 (first, so an early one ends nothing): rank 0 stops cleanly after the
  // generation, workers carry on until rank 0 tells them to stop
  installStopSignals();
  MpiContext mpi(&argc, &argv);
  bool root = mpi.rank() == 0;

  // every rank parses; the worst code decides for all of them, before any evaluation
  Setup setup;
  int code = 0;
  try {
    setup = parse(argc, argv, root);
  } catch (const Error& e) {
    code = static_cast<int>(e.code());
    if (root) {
      std::cerr << "cambrian evolve: error: " << e.what() << std::endl;
    } else if (e.code() != ExitCode::config && e.code() != ExitCode::usage) {
      std::cerr << "cambrian evolve: rank " << mpi.rank() << ": error: " << e.what() << std::endl;
    }
  }
  code = mpi.allReduceMax(code);
  if (code != 0)
    return code;
  if (setup.help) {
    if (root)
      std::cout << setup.help_text;
    return 0;
  }

  // the creature settings every evaluation uses
  const EvolveSettings& s = setup.settings;
  WorkerSettings worker;
  worker.limits = s.creature.limits;
  worker.task = s.creature.task;
  worker.physics = s.creature.physics;
  worker.fail_every = s.fail_every;
  worker.test_abort_at = s.test_worker_abort_at;

  try {
    if (!root) {
      runWorker(mpi, worker);
      return 0;
    }
    // rank 0: schedule over the workers, or evaluate in process with one rank
    std::unique_ptr<PopulationEvaluator> evaluator;
    MpiScheduler* scheduler = nullptr;
    if (mpi.size() > 1) {
      auto owned = std::make_unique<MpiScheduler>(mpi, s.dispatch);
      scheduler = owned.get();
      evaluator = std::move(owned);
    } else {
      evaluator = std::make_unique<InProcessEvaluator>(worker, s.dispatch);
    }
    if (!s.run.quiet) {
      std::cout << "cambrian evolve: " << mpi.size() << " rank(s), " << evaluator->workers()
                << " evaluating; task " << s.creature.task_name << ", population "
                << s.evolution.population << ", generations " << s.evolution.generations
                << ", seed " << s.evolution.seed << std::endl;
    }
    // Chaumont 5.5: new bodies that overlap themselves are redrawn before evaluation
    RunSettings run = s.run;
    run.rank_count = mpi.size();
    run.stop_requested = stopRequested;
    run.stop_reason = stopSignalName;
    if (s.creature.task.kind != TaskKind::synthetic) {
      run.viable = [&s](const Genome& genome) {
        return isViable(genome, s.creature.limits, s.creature.physics);
      };
    }
    // rank 0 keeps the memory it frees (glibc): every generation builds megabytes of genome
    // bytes, messages and history rows, and handing them back to the kernel only to fault them in
    // again cost ~3 ms of serial and ~7 ms of CPU time per generation at population 300
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    RunResult result =
        runEvolution(s.evolution, s.creature.limits, setup.seeds, *evaluator, run, std::cout);
    if (scheduler)
      scheduler->stopWorkers();

    // the run digest (so far, when stopped) and rank 0's cost
    std::cout << (result.stopped ? "digest_so_far " : "digest ") << result.digest << "\n"
              << "rank0_cpu_seconds " << result.rank0_cpu_seconds << "\n"
              << "wall_seconds " << result.wall_seconds << "\n"
              << "history " << s.run.out_dir << "/history.h5\n"
              << "tables " << s.run.out_dir << "/individuals.tsv " << s.run.out_dir
              << "/generations.tsv" << std::endl;
    return 0;
  } catch (const Error& e) {
    mpi.abort(root ? e.code() : ExitCode::worker_failure, e.what());
  } catch (const std::exception& e) {
    mpi.abort(root ? ExitCode::failure : ExitCode::worker_failure, e.what());
  }
}

}  // namespace cambrian
