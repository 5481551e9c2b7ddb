// cambrian evolve: rank 0 breeds and schedules, ranks 1..N-1 evaluate; one rank evaluates in
// process. Every rank parses the same options; a bad setting ends every rank with
// ExitCode::config before any simulation starts.
#include "cambrian/encodings.hpp"
#include "cambrian/error.hpp"
#include "cambrian/evaluate.hpp"

#include "commands.hpp"
#include "core/hash.hpp"
#include "core/process_usage.hpp"
#include "evolution/competitive_ranking.hpp"
#include "evolution/epochs.hpp"
#include "evolution/evolution_settings.hpp"
#include "evolution/migration.hpp"
#include "evolution/population.hpp"
#include "options.hpp"
#include "parallel/archipelago.hpp"
#include "parallel/island_layout.hpp"
#include "parallel/mpi_context.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/worker.hpp"
#include "run/archipelago_index.hpp"
#include "run/evolution_run.hpp"
#include "run/stop_request.hpp"
#include "store/history.hpp"
#include "tasks/task.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <malloc.h>
#include <optional>
#include <sstream>
#include <string_view>
#include <unistd.h>

namespace cambrian {

namespace {

// everything evolve reads from the command line and the experiment file
struct EvolveSettings {
  WorkerSettings worker;  // the creature settings and the workers' testing keys
  EvolutionSettings evolution;
  MigrationSettings islands;
  RunSettings run;
  DispatchSettings dispatch;

  // every key, bound to these settings
  void declare(SettingsSchema& schema) {
    worker.creature.declareSettings(schema);
    evolution.declareSettings(schema);
    islands.declareSettings(schema);
    run.declareSettings(schema);
    dispatch.declareSettings(schema);
    worker.declareTestingSettings(schema);
    // the rules across sections
    schema.addCheck([this] {
      if (!run.arrival_order.empty() && evolution.mode != EvolutionMode::steady_state)
        throw ConfigError("run.arrival_order = " + run.arrival_order +
                          ": only a steady state (evolution.mode = steady_state) follows a "
                          "recorded order of results");
      std::error_code error;
      if (!run.arrival_order.empty() && islands.islands > 1 &&
          !std::filesystem::is_directory(run.arrival_order, error))
        throw ConfigError("run.arrival_order = " + run.arrival_order +
                          ": with islands.count = " + std::to_string(islands.islands) +
                          " it names the earlier run's directory, whose island_K/history.h5 "
                          "island K follows; this is no directory");
    });
  }
};

// what parsing produced: settings, or an exit code and message
struct Setup {
  EvolveSettings settings;
  std::vector<Genotype> seeds;
  std::string help_text;
};

// evolution.seed_history: the best individual (status ok; ties: lowest id) of the last
// generation of the history at `path`, checked against `encoding`'s limits; InputError naming the
// key and the file when it is missing, unreadable or holds no such individual
Genotype bestOfLastGeneration(const std::string& path, const Encoding& encoding) {
  const std::string key = "evolution.seed_history = " + path + ": ";
  std::optional<Individual> best;
  try {
    HistoryReader history(path);
    const std::vector<GenerationRecord> generations = history.generations();
    if (generations.empty())
      throw InputError("the history holds no complete generation");
    const std::uint64_t last = generations.back().generation;
    const std::vector<Individual> rows = history.individuals();
    if (const Individual* found = bestOk(rows, last))
      best = *found;
    if (!best)
      throw InputError("no individual with status ok in its last generation (" +
                       std::to_string(last) + ")");
  } catch (const Error& e) {
    throw InputError(key + e.what());
  }
  try {
    encoding.validate(best->genome);
  } catch (const Error& e) {
    // a genome the run's encoding does not take (another encoding's, past the limits)
    throw InputError(key + "its best individual (id " + std::to_string(best->id) +
                     "): " + e.what());
  }
  return best->genome;
}

// parses and checks everything; throws Error with the config code and the file named
void parse(int argc, char** argv, bool read_seeds, Setup& setup) {
  EvolveSettings& s = setup.settings;
  SettingsSchema schema;
  s.declare(schema);
  std::string config_path, seed, out, max_hours;
  bool quiet = false, verbose = false, fresh = false, help_markdown = false;
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
  po::variables_map vm = parseOptions(argc, argv, cli, schema, nullptr, "config", &origins);
  if (help_markdown) {
    setup.help_text = optionsMarkdown(schema);
    return;
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
         << optionsHelp(cli, schema);
    setup.help_text = text.str();
    return;
  }

  // short forms win over the long keys, in the settings and in the stored settings text
  auto shortForm = [&](const char* key, const std::string& value) {
    try {
      schema.set(key, value);
    } catch (const SettingTypeError& e) {
      throw Error(ExitCode::usage, std::string("command line: --") + e.what());
    }
    origins.setOnCommandLine(key);
  };
  if (vm.count("seed"))
    shortForm("run.seed", seed);
  if (vm.count("out"))
    shortForm("run.out", out);
  if (quiet)
    shortForm("run.quiet", "true");
  if (verbose)
    shortForm("run.verbose", "true");
  if (vm.count("max-hours"))
    shortForm("run.max_hours", max_hours);

  // range checks, naming the file or the command line the value came from
  checkSettings(schema, origins);
  s.run.fresh = fresh;
  s.run.config_text = schema.iniText();
  // what each setting was before it existed (keys added since a checkpoint was written compare
  // with these)
  s.run.earlier_config_text = schema.earlierRunsIniText();
  s.run.run_only = schema.runOnlyKeys();
  s.run.measures = s.worker.creature.task().measures();
  s.run.repeatable = s.worker.creature.task().repeatable();
  // a competitive ranking, and every epoch's ranking and condition, name measures the task
  // reports
  const auto& measures = s.run.measures;
  auto requireMeasure = [&](const std::string& name, const std::string& key,
                            const std::string& text) {
    if (std::any_of(measures.begin(), measures.end(),
                    [&](const MeasureInfo& m) { return m.name == name; }))
      return;
    std::string names;
    for (const MeasureInfo& m : measures)
      names += (names.empty() ? "" : ", ") + m.name;
    throw ConfigError(key + " = " + text + ": task " + s.worker.creature.task().name() +
                      " has no measure '" + name + "' (its measures: " + names + ")");
  };
  for (const std::string& text : s.evolution.ranking)
    requireMeasure(parseRankedMeasure(text, "evolution.ranking").measure, "evolution.ranking",
                   text);
  for (const std::string& text : s.evolution.epochs) {
    const Epoch epoch = parseEpoch(text, "evolution.epochs");
    for (const RankedMeasure& ranked : epoch.ranking)
      requireMeasure(ranked.measure, "evolution.epochs", text);
    if (epoch.until == Epoch::Until::reached)
      requireMeasure(epoch.measure, "evolution.epochs", text);
  }

  // seed genomes (rank 0 only), checked against the encoding's limits
  if (read_seeds) {
    for (const std::string& path : s.evolution.seed_genomes) {
      Genotype genome = readGenomeFile(path);
      try {
        s.worker.creature.encoding().validate(genome);
      } catch (const Error& e) {
        throw InputError(path + ": " + e.what());
      }
      setup.seeds.push_back(std::move(genome));
    }
    // a sequence of fitness tests: the best of a previous run's last generation
    if (!s.evolution.seed_history.empty())
      setup.seeds.push_back(
          bestOfLastGeneration(s.evolution.seed_history, s.worker.creature.encoding()));
  }
}

// whether the command line asks for help (--help, -h, --help-markdown)
bool asksForHelp(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word(argv[i]);
    if (word == "--help" || word == "-h" || word == "--help-markdown")
      return true;
  }
  return false;
}

// the help, without starting MPI (its threads add nothing to a help text, and a leak checker
// that stops them at exit has been seen to crash): printed once, by the first rank of an
// mpirun job (Open MPI, MPICH and Slurm name it in the environment) or by a lone process
int printHelp(int argc, char** argv) {
  for (const char* rank : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "SLURM_PROCID"}) {
    const char* value = std::getenv(rank);
    if (value && std::string_view(value) != "0")
      return 0;
  }
  Setup setup;
  try {
    parse(argc, argv, true, setup);
  } catch (const Error& e) {
    std::cerr << "cambrian evolve: error: " << e.what() << std::endl;
    return static_cast<int>(e.code());
  }
  std::cout << setup.help_text;
  return 0;
}

// Whether what rank 0 prints reaches a terminal. Under mpirun rank 0 writes to a pseudo-terminal
// of the launcher's whatever the launcher itself writes to (a log file, a pipe), so there the
// launcher's own standard output decides: a terminal device, or not.
bool outputReachesATerminal() {
  if (isatty(STDOUT_FILENO) != 1)
    return false;
  const bool launched =
      std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
  if (!launched)
    return true;
  std::error_code error;
  const std::string target =
      std::filesystem::read_symlink("/proc/" + std::to_string(getppid()) + "/fd/1", error).string();
  return !error && (target.rfind("/dev/pts/", 0) == 0 || target.rfind("/dev/tty", 0) == 0);
}

// every breeding rank's `text`, in island order, at island 0 (empty elsewhere)
std::vector<std::string> gatherText(MpiContext& breeders, const std::string& text) {
  std::vector<std::string> texts;
  if (breeders.rank() != 0) {
    breeders.send(0, Tag::result, std::vector<std::uint8_t>(text.begin(), text.end()));
    return texts;
  }
  texts.resize(static_cast<std::size_t>(breeders.size()));
  texts[0] = text;
  for (int k = 1; k < breeders.size(); ++k) {
    Message message = breeders.receive(Tag::result);
    texts[static_cast<std::size_t>(message.source)].assign(message.bytes.begin(),
                                                           message.bytes.end());
  }
  return texts;
}

// the run's digest over its islands' (in island order)
std::string archipelagoDigest(const std::vector<std::string>& digests) {
  Fnv1a hash;
  for (const std::string& digest : digests)
    hash.add(digest.data(), digest.size());
  return hex16(hash.value());
}

}  // namespace

int runEvolve(int argc, char** argv) {
  if (asksForHelp(argc, argv))
    return printHelp(argc, argv);

  // SIGTERM / SIGUSR1 (first, so an early one ends nothing): rank 0 stops cleanly after the
  // generation, workers carry on until rank 0 tells them to stop
  installStopSignals();
  MpiContext mpi(&argc, &argv);
  bool root = mpi.rank() == 0;

  // every rank parses; the worst code decides for all of them, before any evaluation
  Setup setup;
  int code = 0;
  try {
    parse(argc, argv, root, setup);
  } catch (const Error& e) {
    code = static_cast<int>(e.code());
    if (root) {
      std::cerr << "cambrian evolve: error: " << e.what() << std::endl;
    } else if (e.code() != ExitCode::config && e.code() != ExitCode::usage) {
      std::cerr << ("cambrian evolve: rank " + std::to_string(mpi.rank()) + ": error: " + e.what() +
                    "\n")
                << std::flush;
    }
  }
  code = mpi.allReduceMax(code);
  if (code != 0)
    return code;

  // the creature settings every evaluation uses
  const EvolveSettings& s = setup.settings;
  const WorkerSettings& worker = s.worker;
  const CreatureSettings& creature = worker.creature;

  // islands: the job's ranks in blocks, each breeding a population of its own over a context of
  // its own; the islands' breeding ranks share one more (every rank computes the same layout)
  const int island_count = s.islands.islands;
  IslandPlace place;
  try {
    place = islandPlace(mpi.rank(), mpi.size(), island_count);
  } catch (const Error& e) {
    if (root)
      std::cerr << "cambrian evolve: error: " << e.what() << std::endl;
    return static_cast<int>(e.code());
  }
  std::unique_ptr<MpiContext> island_context, breeders;
  if (island_count > 1) {
    island_context = mpi.split(place.island);
    breeders = mpi.split(place.rank == 0 ? 0 : -1);
  }
  MpiContext& here = island_context ? *island_context : mpi;
  const bool breeding = here.rank() == 0;

  try {
    if (!breeding) {
      runWorker(here, worker);
      // the workers' peak memory for their breeding rank's summary
      here.allReduceMax(processPeakResidentBytes());
      return 0;
    }
    // rank 0: schedule over the workers, or evaluate in process with one rank
    std::unique_ptr<PopulationEvaluator> evaluator;
    MpiScheduler* scheduler = nullptr;
    if (here.size() > 1) {
      auto owned = std::make_unique<MpiScheduler>(here, s.dispatch);
      scheduler = owned.get();
      evaluator = std::move(owned);
    } else {
      evaluator = std::make_unique<InProcessEvaluator>(worker, s.dispatch);
    }
    // each island's own seed, output directory and (but for island 0's) output
    EvolutionSettings evolution = s.evolution;
    RunSettings run = s.run;
    if (island_count > 1) {
      evolution.seed = islandSeed(s.evolution.seed, place.island);
      run.out_dir = s.run.out_dir + "/" + islandDirectoryName(place.island, island_count);
      // a steady archipelago follows each island's own recorded order
      if (!run.arrival_order.empty())
        run.arrival_order = s.run.arrival_order + "/" +
                            islandDirectoryName(place.island, island_count) + "/history.h5";
    }
    // the other islands' lines go to DIR/island_K/evolve.log, appended (a resume adds to it;
    // where it cannot be written, the run's own writes there fail with the reason)
    std::ofstream island_log;
    if (place.island != 0) {
      std::error_code error;
      std::filesystem::create_directories(run.out_dir, error);
      island_log.open(run.out_dir + "/evolve.log", std::ios::app);
    }
    std::ostream& out = place.island == 0 ? std::cout : island_log;
    if (!run.quiet) {
      if (island_count > 1 && place.island == 0)
        out << "cambrian evolve: " << island_count << " islands of " << place.size << " to "
            << (mpi.size() + island_count - 1) / island_count << " ranks, in " << s.run.out_dir
            << "/island_* (the others' lines in their evolve.log); island 0:\n";
      out << "cambrian evolve: " << here.size() << " rank(s), " << evaluator->workers()
          << " evaluating; task " << creature.task().name() << ", encoding "
          << creature.encoding().name() << ", population " << s.evolution.population
          << ", generations " << s.evolution.generations << ", seed " << evolution.seed
          << std::endl;
    }
    // Chaumont 5.5: new bodies that overlap themselves are redrawn before evaluation
    run.rank_count = here.size();
    run.terminal = place.island == 0 && outputReachesATerminal();
    run.stop_requested = stopRequested;
    run.stop_reason = stopSignalName;
    if (creature.task().needsBody()) {
      run.viable = [&creature](const Genotype& genome) { return isViable(genome, creature); };
    }
    // the archipelago's index, by the first island
    if (island_count > 1 && place.island == 0)
      writeArchipelagoIndex(s.run.out_dir, s.islands, mpi.size(), s.evolution.seed);
    // islands that trade: this island's side of the migrations
    std::optional<Archipelago> archipelago;
    if (breeders && s.islands.migrants > 0) {
      archipelago.emplace(*breeders, s.islands, s.evolution.seed, stopRequested);
      run.migrations = &*archipelago;
    }
    // rank 0 keeps the memory it frees (glibc): every generation builds megabytes of genome
    // bytes, messages and history rows, and handing them back to the kernel only to fault them in
    // again cost ~3 ms of serial and ~7 ms of CPU time per generation at population 300
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    RunResult result =
        runEvolution(evolution, creature.encoding(), setup.seeds, *evaluator, run, out);
    // the breeding rank's and the largest worker's peak memory (one process when evaluating in
    // process)
    std::uint64_t rank0_peak = processPeakResidentBytes();
    std::uint64_t worker_peak = rank0_peak;
    if (scheduler) {
      scheduler->stopWorkers();
      worker_peak = here.allReduceMax(std::uint64_t{0});
    }

    // the run digest (so far, when stopped) and rank 0's cost; with islands each island's
    // digest, and the run's over them, the breeding ranks' largest figures
    std::string digest = result.digest;
    bool stopped = result.stopped;
    if (breeders) {
      std::vector<std::string> digests = gatherText(*breeders, result.digest);
      stopped = breeders->allReduceMax(result.stopped ? 1 : 0) != 0;
      rank0_peak = breeders->allReduceMax(rank0_peak);
      worker_peak = breeders->allReduceMax(worker_peak);
      if (place.island != 0)
        return 0;
      digest = archipelagoDigest(digests);
      for (std::size_t k = 0; k < digests.size(); ++k)
        std::cout << "island " << k << " digest " << digests[k] << "\n";
    }
    std::cout << (stopped ? "digest_so_far " : "digest ") << digest << "\n"
              << "rank0_cpu_seconds " << result.rank0_cpu_seconds << "\n"
              << "wall_seconds " << result.wall_seconds << "\n"
              << "rank0_peak_rss_mb " << rank0_peak / 1e6 << "\n"
              << "worker_peak_rss_mb " << worker_peak / 1e6 << "\n"
              << "history " << run.out_dir << "/history.h5\n"
              << "tables " << run.out_dir << "/individuals.tsv " << run.out_dir
              << "/generations.tsv" << std::endl;
    return 0;
  } catch (const Error& e) {
    mpi.abort(breeding ? e.code() : ExitCode::worker_failure, e.what());
  } catch (const std::exception& e) {
    mpi.abort(breeding ? ExitCode::failure : ExitCode::worker_failure, e.what());
  }
}

}  // namespace cambrian
