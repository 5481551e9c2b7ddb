// cambrian: the run driver — rank 0's loop over generations, with the history, checkpoints and
// resume, progress lines and the tables.
#include "run/evolution_run.hpp"

#include "cambrian/error.hpp"
#include "cambrian/version.hpp"

#include "core/process_usage.hpp"
#include "core/test_kill.hpp"
#include "evolution/breeder.hpp"
#include "evolution/competitive_ranking.hpp"
#include "evolution/epochs.hpp"
#include "evolution/migration.hpp"
#include "evolution/outcome_reuse.hpp"
#include "evolution/statistics.hpp"
#include "evolution/steady_state.hpp"
#include "evolution/wwd_breeding.hpp"
#include "physics/physics_settings.hpp"
#include "run/arrival_order.hpp"
#include "run/resume.hpp"
#include "run/tables.hpp"
#include "store/checkpoint.hpp"
#include "store/history.hpp"
#include "store/run_lock.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <ostream>

namespace cambrian {

namespace {

using Clock = std::chrono::steady_clock;

// h:mm:ss
std::string clockText(double seconds) {
  auto total = static_cast<long long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, (total / 60) % 60,
                total % 60);
  return text;
}

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// the output directory
void makeOutputDirectory(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw Error(ExitCode::output_file, dir + ": cannot create directory: " + error.message());
}

// an individual as the tables keep it: the record without its genome (the history has it)
Individual tableRecord(Individual individual) {
  individual.genome = Genotype();
  return individual;
}

// individuals.tsv and generations.tsv, atomically
void writeTables(const std::string& dir, const RunResult& result,
                 const std::vector<MeasureInfo>& measures) {
  makeOutputDirectory(dir);
  std::string individuals = individualsTsvHeader(measures);
  for (const Individual& r : result.individuals)
    individuals += individualsTsvRow(r, measures);
  writeTextFileAtomically(dir + "/individuals.tsv", individuals);
  std::string generations = generationsTsvHeader();
  for (const GenerationRecord& r : result.generations)
    generations += generationsTsvRow(r);
  writeTextFileAtomically(dir + "/generations.tsv", generations);
}

// one run, from its output directory's state to its tables
class EvolutionRun {
 public:
  EvolutionRun(const EvolutionSettings& settings, const Encoding& encoding,
               const std::vector<Genotype>& seeds, PopulationEvaluator& evaluator,
               const RunSettings& run, std::ostream& out)
      : settings_(settings),
        seeds_(seeds),
        evaluator_(evaluator),
        run_(run),
        out_(out),
        breeder_(settings, encoding),
        total_(static_cast<std::uint64_t>(std::max(settings.generations, 0))),
        steady_(settings.mode == EvolutionMode::steady_state),
        members_(settings_) {
    setTestKillPoint(run.test_kill_at);
    for (const std::string& text : settings.ranking)
      ranking_.push_back(parseRankedMeasure(text, "evolution.ranking"));
    epochs_ = parseEpochs(settings.epochs, "evolution.epochs");
    if (run.viable)
      breeder_.setViabilityCheck(run.viable);
  }

  // a steady state's writer thread ends before the members it reads go
  ~EvolutionRun() {
    if (writer_.valid())
      writer_.wait();
  }

  RunResult run() {
    // a steady state's recorded order, read before the output directory is touched
    if (steady_ && !run_.arrival_order.empty())
      arrivals_ = readArrivalRecord(run_.arrival_order, historyAttributes());
    openOutput();
    if (run_.migrations)
      run_.migrations->start(start_, run_.out_dir);
    if (!epochs_.empty() && start_ < total_)
      announceEpoch();
    std::string stop_reason;
    std::uint64_t g = start_;
    if (steady_) {
      g = runSteadyState(stop_reason);
      joinWriter();
    }
    for (; !steady_ && g < total_; ++g) {
      // a clean stop: the last generation written and checkpointed, then out
      stop_reason = stopReason(g);
      if (!stop_reason.empty())
        break;
      // islands: the immigrants this generation takes in (none: a stop while waiting for them)
      std::vector<Individual> immigrants;
      if (last_ && run_.migrations) {
        std::optional<std::vector<Individual>> arrived = run_.migrations->exchange(*last_);
        if (!arrived) {
          stop_reason = anotherIslandStopped(g);
          break;
        }
        immigrants = std::move(*arrived);
      }
      runGeneration(g, immigrants);
    }
    if (run_.migrations)
      run_.migrations->close();

    // the last generation into the history, checkpointed (a resume that stops at once has none)
    finishPending(true);

    // digest, timings and the tables
    result_.stopped = !stop_reason.empty();
    result_.next_generation = std::max(g, start_);
    if (result_.stopped)
      out_ << "cambrian evolve: " << stop_reason << " after " << result_.next_generation
           << " generation(s); run the same command again to continue from "
           << checkpointPath(run_.out_dir) << std::endl;
    result_.digest = digest_.hex();
    result_.rank0_cpu_seconds = processCpuSeconds() - cpu_start_;
    result_.wall_seconds = secondsSince(run_start_);
    if (history_) {
      history_->close();
      clearHistoryStarting(run_.out_dir);
    }
    try {
      writeTables(run_.out_dir, result_, run_.measures);
    } catch (const Error& e) {
      throw Error(e.code(), std::string(e.what()) + "; the run itself is complete in " +
                                run_.out_dir +
                                "/history.h5 and its checkpoint: make room and run the same "
                                "command again to write the tables");
    }
    return std::move(result_);
  }

 private:
  // the history's provenance (the settings hash leaves out run-only settings)
  HistoryAttributes historyAttributes() const {
    HistoryAttributes attributes;
    attributes.config_text = run_.config_text;
    attributes.config_hash = resultConfigHash(run_.config_text, run_.run_only);
    attributes.run_only_settings.assign(run_.run_only.begin(), run_.run_only.end());
    attributes.seed = settings_.seed;
    attributes.rank_count = run_.rank_count;
    attributes.bullet_precision = bulletPrecision();
    return attributes;
  }

  // the output directory locked, then a checkpoint to continue from (checked before anything is
  // overwritten) or a fresh history
  void openOutput() {
    if (!run_.history)
      return;
    makeOutputDirectory(run_.out_dir);
    std::string warning;
    RunLockWait wait;
    wait.seconds = run_.lock_wait;
    wait.say = [this](const std::string& what) {
      out_ << "cambrian evolve: " << what << std::endl;
    };
    lock_.emplace(run_.out_dir, wait, &warning);
    if (!warning.empty())
      out_ << "cambrian evolve: warning: " << warning << std::endl;
    std::optional<CheckpointState> checkpoint;
    const HistoryAttributes attributes = historyAttributes();
    if (!run_.fresh)
      checkpoint = findCheckpoint(run_.out_dir, &attributes);
    if (checkpoint) {
      resume(std::move(*checkpoint));
      return;
    }

    // nothing to continue from: stale checkpoint files go, the history starts empty
    std::error_code error;
    if (!run_.fresh && std::filesystem::exists(run_.out_dir + "/history.h5", error))
      out_ << "cambrian evolve: no checkpoint in " << run_.out_dir << ", starting fresh"
           << std::endl;
    removeCheckpoints(run_.out_dir);
    markHistoryStarting(run_.out_dir, attributes);
    history_ = std::make_unique<HistoryWriter>(
        run_.out_dir + "/history.h5", historyAttributes(), run_.measures,
        historyChunkRows(static_cast<std::uint64_t>(settings_.population)));
  }

  // continues from `checkpoint`: the settings checked, the history cut back to it, the records
  // kept, the breeder and digest state restored
  void resume(CheckpointState checkpoint) {
    const std::string path = checkpointPath(run_.out_dir);
    checkResumeSettings(path, checkpoint.config_text, run_.config_text, run_.earlier_config_text,
                        run_.run_only);
    // another build may evaluate creatures differently: allowed, but said
    if (checkpoint.cambrian_version != kVersion || checkpoint.git_hash != kGitHash)
      out_ << "cambrian evolve: warning: " << path << " was written by cambrian "
           << checkpoint.cambrian_version << " (git " << checkpoint.git_hash << "), this is "
           << kVersion << " (git " << kGitHash
           << "): the run continues exactly only if both evaluate and breed alike" << std::endl;
    start_ = checkpoint.next_generation;
    out_ << "cambrian evolve: resuming from " << path << " at generation " << start_ << " ("
         << start_ << " generation(s) done, written by a run of " << checkpoint.rank_count
         << " rank(s))" << std::endl;
    HistoryRows kept;
    try {
      history_ = resumeHistory(
          run_.out_dir + "/history.h5", start_, historyAttributes(), run_.measures, kept,
          historyChunkRows(static_cast<std::uint64_t>(settings_.population)), checkpoint.digest);
    } catch (const InputError& e) {
      throw Error(ExitCode::checkpoint, std::string(e.what()) + " (needed to resume from " + path +
                                            "); `cambrian evolve --fresh` starts over");
    }
    for (Individual& row : kept.individuals)
      result_.individuals.push_back(tableRecord(std::move(row)));
    for (const GenerationRecord& row : kept.generations) {
      result_.generations.push_back(row);
      walls_.push_back(row.wall_seconds - row.checkpoint_seconds);
    }
    breeder_.setNextId(checkpoint.next_id);
    digest_ = RunDigest(checkpoint.digest);
    last_ = std::move(checkpoint.population);
    if (run_.migrations)
      run_.migrations->resume(checkpoint.migrations);
    // the epoch the next generation is rated in: the last one's (the history's rows say which
    // and since when), moved on if its condition held after it
    if (!epochs_.empty() && !kept.generations.empty()) {
      EpochPlace place{static_cast<std::size_t>(kept.generations.back().epoch), 0};
      for (const GenerationRecord& row : kept.generations) {
        if (row.epoch != place.epoch)
          place.first_generation = row.generation + 1;
      }
      epoch_place_ = nextEpochPlace(epochs_, place, *last_);
    }
    checkpointed_ = start_;
    result_.resumed = true;
  }

  // the last evaluated generation's checkpoint (`next_id` as it was when that generation ended,
  // `digest` over every generation up to it); returns the seconds it took
  double writeRunCheckpoint(std::uint64_t next_generation, std::uint64_t next_id) {
    auto begin = Clock::now();
    CheckpointState state;
    state.config_text = run_.config_text;
    state.config_hash = resultConfigHash(run_.config_text, run_.run_only);
    state.seed = settings_.seed;
    state.next_generation = next_generation;
    state.next_id = next_id;
    state.digest = digest_.value();
    state.rank_count = run_.rank_count;
    // a steady state: the members and, unevaluated, the creatures handed out (as they were at
    // the generation's end, where the writer thread writes it)
    if (steady_) {
      state.steady_state = true;
      if (pending_ && pending_->steady_snapshot) {
        state.population = std::move(*pending_->steady_snapshot);
        pending_->steady_snapshot.reset();
      } else {
        state.population = steadyCheckpointPopulation();
      }
    } else {
      state.population = *last_;
    }
    if (run_.migrations) {
      if (pending_ && pending_->migrations_snapshot)
        state.migrations = std::move(*pending_->migrations_snapshot);
      else
        state.migrations = run_.migrations->checkpointState();
    }
    writeCheckpoint(run_.out_dir, state, [&](const std::string& stage) {
      testKillPoint("checkpoint_" + stage, next_generation - 1);
    });
    testKillPoint("checkpoint_done", next_generation - 1);
    if (run_.migrations)
      run_.migrations->checkpointed(next_generation);
    clearHistoryStarting(run_.out_dir);
    double seconds = std::max(secondsSince(begin), 1e-9);
    checkpoint_seconds_max_ = std::max(checkpoint_seconds_max_, seconds);
    checkpointed_ = next_generation;
    checkpoint_time_ = Clock::now();
    return seconds;
  }

  // a generation's times run from the start of its breeding to the start of the next one's (the
  // last one's: to the end of its history append and checkpoint), so consecutive rows tile the
  // run; its serial time is what of that lies outside its evaluation span
  void closeTimes(GenerationRecord& record) const {
    record.wall_seconds = secondsSince(generation_start_);
    record.rank0_cpu_seconds = processCpuSeconds() - generation_cpu_start_;
    record.rank0_serial_seconds =
        std::max(0.0, record.wall_seconds - record.evaluation_span_seconds);
  }

  // the last evaluated generation into the history, with its checkpoint when one is due: while
  // the next generation evaluates (the workers never wait for the file system), or at the end or
  // a clean stop, when nothing is left to overlap
  void finishPending(bool final_write) {
    if (!pending_)
      return;
    // the run digest over it and the freeing of the generation before: a millisecond or two of
    // hashing and freeing that the workers need not wait for either
    digest_.add(*last_);
    retired_.reset();
    GenerationRecord& record = result_.generations[pending_->record];
    // (a steady state's: counted from its members at the generation's end)
    if (!steady_)
      record.distinct_genomes = distinctGenomes(*last_);
    if (!history_) {
      pending_.reset();
      return;
    }
    if (final_write)
      closeTimes(record);
    try {
      writePending(record, final_write);
    } catch (const Error& e) {
      if (e.code() == ExitCode::output_file)
        throw outputFailed(e);
      throw;
    }
    pending_.reset();
  }

  // an output file that could not be written (a full disk, a quota, a directory gone or made
  // read-only): the error, what is safe and how to go on
  Error outputFailed(const Error& e) const {
    std::error_code error;
    const std::string checkpoint = checkpointPath(run_.out_dir);
    if (checkpointed_ > 0 && !std::filesystem::exists(checkpoint, error))
      return Error(e.code(), std::string(e.what()) + "; " + checkpoint + " is gone too (was " +
                                 run_.out_dir +
                                 " removed?): this run cannot be continued; `--fresh` starts over");
    std::string safe =
        checkpointed_ > 0
            ? checkpoint + " (continues from generation " + std::to_string(checkpointed_) +
                  ") and the history up to it are intact"
            : "no checkpoint was written yet, so the run starts again from generation 0";
    return Error(e.code(), std::string(e.what()) + "; " + safe +
                               ": once that is put right (room on the disk, " + run_.out_dir +
                               " writable), run the same command to continue");
  }

  // the pending generation's history rows, its checkpoint when one is due, its times completed
  void writePending(GenerationRecord& record, bool final_write) {
    std::uint64_t g = record.generation;
    auto warnOfRepairs = [&] {
      if (std::string notice = history_->takeNotice(); !notice.empty())
        out_ << "cambrian evolve: warning: " << notice << std::endl;
    };
    history_->appendGeneration(last_->individuals, record);
    warnOfRepairs();
    testKillPoint("history", g);

    // (a steady state's was decided at its generation's end, where the writer's copy was made)
    const bool due =
        final_write || (steady_ ? pending_->steady_snapshot.has_value() : checkpointDue(g));
    record.checkpoint_seconds = due ? writeRunCheckpoint(g + 1, pending_->next_id) : 0;
    // the last generation's times include its append and checkpoint
    if (final_write)
      closeTimes(record);
    history_->completeLastGeneration(record);
    warnOfRepairs();
  }

  // a checkpoint after generation g every checkpoint_every generations or checkpoint_minutes,
  // after the first (a history never holds generations without one for long) and the last
  bool checkpointDue(std::uint64_t g) const {
    return g == 0 || g + 1 == total_ ||
           (run_.checkpoint_every > 0 &&
            g + 1 - checkpointed_ >= static_cast<std::uint64_t>(run_.checkpoint_every)) ||
           (run_.checkpoint_minutes > 0 &&
            secondsSince(checkpoint_time_) >= run_.checkpoint_minutes * 60);
  }

  // why the run should stop before generation g ("" to go on)
  std::string stopReason(std::uint64_t g) const {
    if (run_.stop_requested && run_.stop_requested())
      return std::string("stopped by ") + (run_.stop_reason ? run_.stop_reason() : "a signal");
    if (run_.max_hours > 0 && !walls_.empty()) {
      // the slowest of the last five generations plus the slowest checkpoint must still fit
      double predicted =
          *std::max_element(walls_.end() - std::min<std::size_t>(walls_.size(), 5), walls_.end()) +
          checkpoint_seconds_max_;
      double limit = run_.max_hours * 3600;
      if (secondsSince(run_start_) + predicted > limit) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "stopped before the --max-hours %g limit (generation %llu would need about "
                      "%.1f s, %.1f s are left)",
                      run_.max_hours, static_cast<unsigned long long>(g), predicted,
                      std::max(0.0, limit - secondsSince(run_start_)));
        return text;
      }
    }
    return "";
  }

  // breeds generation g (the initial population for g = 0), evaluates it while the previous
  // generation goes to the history, and records it
  void runGeneration(std::uint64_t g, const std::vector<Individual>& immigrants) {
    // the previous generation ends here: its times are complete
    if (pending_) {
      GenerationRecord& previous = result_.generations[pending_->record];
      closeTimes(previous);
      walls_.back() = previous.wall_seconds;
    }
    generation_start_ = Clock::now();
    generation_cpu_start_ = processCpuSeconds();

    Population population =
        last_ ? breeder_.nextGeneration(*last_) : breeder_.initialPopulation(seeds_);
    // islands: the immigrants of this generation take the last bred places
    placeImmigrants(population, immigrants);
    OutcomeReuse reuse;
    if (run_.reuse_outcomes && run_.repeatable)
      reuse = reuseKnownOutcomes(population, last_ ? &*last_ : nullptr);
    const bool live = run_.liveProgress();
    if (live)
      evaluator_.onProgress(
          [this, g](std::size_t done, std::size_t due) { liveLine(g, done, due); });
    EvaluationSpan span =
        evaluator_.evaluate(population, settings_.seed, [&] { finishPending(false); });
    if (live) {
      evaluator_.onProgress({});
      clearLiveLine();
    }
    copySiblingOutcomes(population, reuse);
    // Minemonics' competitive ranking: the fitness is the individual's place in its generation,
    // by the ranking of the run or of the generation's epoch
    const std::vector<RankedMeasure>& ranking =
        epochs_.empty() ? ranking_ : epochs_[epoch_place_.epoch].ranking;
    if (!ranking.empty())
      rankCompetitively(population.individuals, ranking);

    // summarise in id order (the times so far; closed when the next generation starts)
    GenerationRecord record;
    record.generation = population.generation;
    record.stats = computeStats(population);
    record.evaluations = span.evaluations;
    record.workers = span.workers;
    record.evaluation_span_seconds = span.span_seconds;
    record.rank0_dispatch_seconds = span.dispatch_seconds;
    record.worker_busy_seconds = span.busy_seconds;
    record.worker_idle_seconds =
        std::max(0.0, span.workers * span.span_seconds - span.busy_seconds);
    record.epoch = epoch_place_.epoch;
    const MutationScale scale = mutationScale(settings_, population);
    record.fitness_deviation = scale.deviation;
    record.mutation_multiplier = scale.multiplier;
    for (const Individual& individual : population.individuals)
      result_.individuals.push_back(tableRecord(individual));
    closeTimes(record);
    retired_ = std::move(last_);
    last_ = std::move(population);
    result_.generations.push_back(record);
    walls_.push_back(record.wall_seconds);
    pending_ =
        Pending{result_.generations.size() - 1, breeder_.nextId(), std::nullopt, std::nullopt};
    progress(g, record, reuse.from_parents + reuse.siblings.size());

    // the next generation's epoch
    const EpochPlace next = nextEpochPlace(epochs_, epoch_place_, *last_);
    const bool moved = next != epoch_place_;
    epoch_place_ = next;
    if (moved && g + 1 < total_)
      announceEpoch();
  }

  // steady state (evolution.mode = steady_state): no generation barrier. Each result is taken
  // in as it arrives (SteadyMembers::takeIn) and answered with a child bred from the members then
  // (Breeder::steadyChild), so the workers always hold DispatchPace's few milliseconds of work;
  // breeding starts once the first generation is in. Every `population` results taken in make
  // a "generation": its rows (in the order taken in) go to the history, the members' statistics
  // to its row, and a checkpoint (the members and the creatures in flight) when one is due.
  // Returns the generations done; `stop_reason` says why it stopped early.
  std::uint64_t runSteadyState(std::string& stop_reason) {
    const auto P = static_cast<std::uint64_t>(settings_.population);
    const std::uint64_t births = total_ * P;
    // to hand out: the first generation, or a resume's creatures that were in flight
    std::deque<Individual>& unsent = steady_unsent_;
    if (!last_) {
      for (Individual& individual : breeder_.initialPopulation(seeds_).individuals)
        unsent.push_back(std::move(individual));
    } else {
      for (Individual& individual : last_->individuals) {
        if (individual.evaluated)
          members_.takeIn(std::move(individual));
        else
          unsent.push_back(std::move(individual));
      }
      last_.reset();
    }
    std::uint64_t taken = start_ * P;
    members_.setGeneration(start_);
    if (start_ >= total_)
      return start_;
    stop_reason = stopReason(start_);
    if (!stop_reason.empty())
      return start_;  // nothing run: the checkpoint holds what it held
    generation_start_ = Clock::now();
    generation_cpu_start_ = processCpuSeconds();
    const bool live = run_.liveProgress();
    const std::size_t most_in_flight = std::max<std::uint64_t>(1, P / 2);

    std::map<std::uint64_t, Individual>& in_flight = steady_in_flight_;
    std::map<std::uint64_t, StreamedResult> early;  // arrived ahead of the recorded order
    std::vector<Individual> rows;                   // this generation's, in the order taken in
    double busy = 0, dispatch = 0;
    // islands: a resume takes in the immigrants due after its checkpoint's generation first
    if (start_ > 0 && !takeInImmigrants(start_ - 1, taken, rows)) {
      stop_reason = anotherIslandStopped(start_);
      return start_;
    }
    auto handOut = [&](Individual individual) {
      auto start = Clock::now();
      evaluator_.submit(individual, settings_.seed);
      dispatch += secondsSince(start);
      const std::uint64_t id = individual.id;
      in_flight.emplace(id, std::move(individual));
    };
    for (;;) {
      // creatures out: the recorded ones when they were bred, else to the evaluator's depth
      const std::size_t depth = std::min(evaluator_.streamDepth(), most_in_flight);
      auto mayHandOut = [&](std::uint64_t id, std::uint64_t bred_after) {
        std::uint64_t recorded = 0;
        if (arrivals_ && arrivals_->bredAfter(id, recorded))
          return recorded <= bred_after;
        return in_flight.size() < depth;
      };
      while (!unsent.empty() && mayHandOut(unsent.front().id, taken)) {
        handOut(std::move(unsent.front()));
        unsent.pop_front();
      }
      while (unsent.empty() && members_.size() == P && breeder_.nextId() < births &&
             mayHandOut(breeder_.nextId(), taken))
        handOut(breeder_.steadyChild(members_, taken));
      if (in_flight.empty())
        break;

      // the next result: as it arrives, or the one the record took in next
      StreamedResult result = nextResult(taken, in_flight, early);
      dispatch += result.dispatch_seconds;
      auto found = in_flight.find(result.id);
      Individual individual = std::move(found->second);
      in_flight.erase(found);
      individual.outcome = std::move(result.outcome);
      individual.evaluated = true;
      individual.eval_seconds = individual.outcome.wall_seconds;
      individual.worker_rank = result.rank;
      individual.generation = taken / P;
      busy += individual.eval_seconds;
      rows.push_back(individual);
      members_.takeIn(std::move(individual));
      ++taken;
      const std::uint64_t g = (taken - 1) / P;
      if (live)
        liveLine(g, static_cast<std::size_t>(taken - g * P), static_cast<std::size_t>(P));
      // testing aid: a kill in the middle of a generation
      // (the point is defined after the previous generation's writes)
      if (taken - g * P == (P + 1) / 2) {
        if (testKillArmed("evaluation", g))
          joinWriter();
        testKillPoint("evaluation", g);
      }
      if (taken % P != 0)
        continue;

      // a generation's worth taken in: its record, history rows and checkpoint
      joinWriter();
      if (live)
        clearLiveLine();
      members_.setGeneration(g + 1);
      const bool last = g + 1 == total_;
      if (!last)
        stop_reason = stopReason(g + 1);
      endSteadyGeneration(g, std::move(rows), busy, dispatch, last || !stop_reason.empty());
      rows.clear();
      busy = dispatch = 0;
      // islands: the immigrants due now, the next generation's first results (none where the
      // run ends here); a stop while waiting for them is checkpointed as any other
      if (!last && stop_reason.empty() && !takeInImmigrants(g, taken, rows)) {
        stop_reason = anotherIslandStopped(g + 1);
        joinWriter();
        if (history_ && checkpointed_ < g + 1)
          writeRunCheckpoint(g + 1, breeder_.nextId());
      }
      if (last || !stop_reason.empty()) {
        // a stop: the creatures in flight are in the checkpoint; their results are not waited for
        if (!last)
          evaluator_.discardStream();
        return g + 1;
      }
    }
    return taken / P;
  }

  // islands, a steady state: after generation g this island's emigrants go where due (its
  // members are the generation's population), and the immigrants due now are taken in as
  // results, each with the next id, at the same count of results in every run of this layout
  // (at most P - 1 of them, so that a generation keeps one result of its own). False: the run
  // must stop (a stop while waiting for them, or another island stopped).
  bool takeInImmigrants(std::uint64_t g, std::uint64_t& taken, std::vector<Individual>& rows) {
    if (!run_.migrations)
      return true;
    const auto P = static_cast<std::uint64_t>(settings_.population);
    members_.setGeneration(g);
    std::optional<std::vector<Individual>> arrived =
        run_.migrations->exchange(members_.population());
    members_.setGeneration(g + 1);
    if (!arrived)
      return false;
    std::size_t count = std::min<std::size_t>(arrived->size(), static_cast<std::size_t>(P - 1));
    for (std::size_t i = 0; i < count; ++i) {
      Individual immigrant = asImmigrant(std::move((*arrived)[i]), breeder_.nextId(), g + 1);
      breeder_.setNextId(immigrant.id + 1);
      immigrant.bred_after = taken;
      rows.push_back(immigrant);
      members_.takeIn(std::move(immigrant));
      ++taken;
    }
    return true;
  }

  // why a run stops before generation g when another island did (or a stop came meanwhile)
  std::string anotherIslandStopped(std::uint64_t g) const {
    std::string reason = stopReason(g);
    return reason.empty() ? "stopped because another island stopped" : reason;
  }

  // the next result of a steady state: the next to arrive, or where the run follows a record,
  // the one it took in as result `taken` (those arriving ahead of it kept until their turn)
  StreamedResult nextResult(std::uint64_t taken,
                            const std::map<std::uint64_t, Individual>& in_flight,
                            std::map<std::uint64_t, StreamedResult>& early) {
    std::uint64_t expected = 0;
    if (!arrivals_ || !arrivals_->idAt(taken, expected)) {
      if (!early.empty()) {
        StreamedResult result = std::move(early.begin()->second);
        early.erase(early.begin());
        return result;
      }
      return evaluator_.take();
    }
    if (!in_flight.count(expected))
      throw Error(ExitCode::config,
                  "run.arrival_order = " + arrivals_->path + ": its row " + std::to_string(taken) +
                      " takes in individual " + std::to_string(expected) +
                      ", which this run has not bred by then: the history is of another run");
    while (!early.count(expected)) {
      StreamedResult result = evaluator_.take();
      const std::uint64_t id = result.id;
      early.emplace(id, std::move(result));
    }
    StreamedResult result = std::move(early.at(expected));
    early.erase(expected);
    return result;
  }

  // a steady state's generation g (`rows` in the order taken in) ends: its record, history rows,
  // digest and, when due or `final_write`, checkpoint
  void endSteadyGeneration(std::uint64_t g, std::vector<Individual> rows, double busy,
                           double dispatch, bool final_write) {
    GenerationRecord record;
    record.generation = g;
    record.stats = computeStats(members_.population());
    // immigrants are results taken in, not evaluated here
    record.evaluations =
        static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), [](const Individual& row) {
          return row.origin != Origin::migrant;
        }));
    record.workers = evaluator_.workers();
    record.evaluation_span_seconds = secondsSince(generation_start_);
    record.rank0_dispatch_seconds = dispatch;
    record.worker_busy_seconds = busy;
    record.worker_idle_seconds =
        std::max(0.0, record.workers * record.evaluation_span_seconds - busy);
    record.fitness_deviation = mutationScale(settings_, members_.population()).deviation;
    for (const Individual& row : rows)
      result_.individuals.push_back(tableRecord(row));
    closeTimes(record);
    last_ = Population{g, std::move(rows)};
    result_.generations.push_back(record);
    walls_.push_back(record.wall_seconds);
    pending_ =
        Pending{result_.generations.size() - 1, breeder_.nextId(), std::nullopt, std::nullopt};
    result_.generations.back().distinct_genomes = distinctGenomes(members_.population());
    progress(g, result_.generations.back(), 0);
    if (final_write) {
      finishPending(true);
      return;
    }
    // the next generation's time starts here, this one's history append and checkpoint
    // included (the last one's: in its own, as a generational run's)
    generation_start_ = Clock::now();
    generation_cpu_start_ = processCpuSeconds();
    // the history rows and a due checkpoint on a thread beside the stream, as a generational
    // run's beside its hand-outs: what it reads of the run is this generation's and stays put
    // until joinWriter (the members and the creatures out, which move on, copied here)
    if (history_ && checkpointDue(g)) {
      pending_->steady_snapshot = steadyCheckpointPopulation();
      if (run_.migrations)
        pending_->migrations_snapshot = run_.migrations->checkpointState();
    }
    writer_ = std::async(std::launch::async, [this] { finishPending(false); });
  }

  // waits for a steady state's writer thread (rethrowing its error); every read of what it
  // writes (the history, the checkpoint's times, the digest, the last generation) comes after
  void joinWriter() {
    if (writer_.valid())
      writer_.get();
  }

  // a steady state's checkpoint: the members and the creatures in flight, in id order
  Population steadyCheckpointPopulation() const {
    Population population;
    const std::uint64_t next = members_.population().generation;
    population.generation = next == 0 ? 0 : next - 1;
    population.individuals = members_.population().individuals;
    for (const auto& [id, individual] : steady_in_flight_)
      population.individuals.push_back(individual);
    for (const Individual& individual : steady_unsent_)
      population.individuals.push_back(individual);
    std::sort(population.individuals.begin(), population.individuals.end(),
              [](const Individual& a, const Individual& b) { return a.id < b.id; });
    return population;
  }

  // "epoch 2/3 (RANKING@CONDITION) from generation 11" (generations counted from 1, as above)
  void announceEpoch() const {
    if (run_.quiet)
      return;
    out_ << "epoch " << epoch_place_.epoch + 1 << "/" << epochs_.size() << " ("
         << settings_.epochs.at(epoch_place_.epoch) << ") from generation "
         << epoch_place_.first_generation + 1 << std::endl;
  }

  // the live line within generation g, rewritten in place at most every 0.25 s (and at the
  // first and last result): evaluations done of those due, the generation's ETA
  void liveLine(std::uint64_t g, std::size_t done, std::size_t due) {
    const auto now = Clock::now();
    if (live_shown_ && done != 1 && done != due &&
        std::chrono::duration<double>(now - live_time_).count() < 0.25)
      return;
    const double elapsed = secondsSince(generation_start_);
    const double eta =
        done == 0 ? 0 : elapsed / static_cast<double>(done) * static_cast<double>(due - done);
    char line[160];
    std::snprintf(line, sizeof line,
                  "\r\033[K  gen %llu/%d  evaluated %zu/%zu (population %d)  eta %s",
                  static_cast<unsigned long long>(g + 1), settings_.generations, done, due,
                  settings_.population, clockText(eta).c_str());
    out_ << line << std::flush;
    live_shown_ = true;
    live_time_ = now;
  }

  // wipes the live line, so that the generation's line takes its place
  void clearLiveLine() {
    if (live_shown_)
      out_ << "\r\033[K" << std::flush;
    live_shown_ = false;
  }

  // the progress line and, verbose, its details (`reused`: copies that took an outcome)
  void progress(std::uint64_t g, const GenerationRecord& record, std::size_t reused) const {
    double elapsed = secondsSince(run_start_);
    double eta =
        elapsed / static_cast<double>(g + 1 - start_) * static_cast<double>(total_ - g - 1);
    if (!run_.quiet)
      out_ << progressLine(record, settings_.generations, eta) << std::endl;
    if (run_.verbose) {
      char detail[256];
      std::snprintf(detail, sizeof detail,
                    "    evaluated %llu  reused %zu  span %.3f s  busy %.3f s  idle %.3f s  rank0 "
                    "serial %.4f s  "
                    "failed %zu  best id %llu",
                    static_cast<unsigned long long>(record.evaluations), reused,
                    record.evaluation_span_seconds, record.worker_busy_seconds,
                    record.worker_idle_seconds, record.rank0_serial_seconds, record.stats.failed,
                    static_cast<unsigned long long>(record.stats.best_id));
      out_ << detail << std::endl;
    }
  }

  // the last evaluated generation until it is in the history
  struct Pending {
    std::size_t record = 0;  // index into result_.generations
    std::uint64_t next_id = 0;
    // a steady state's checkpoint when one is due: the members and creatures out, and the
    // migrations' state, as they were at the generation's end
    std::optional<Population> steady_snapshot;
    std::optional<std::vector<std::uint8_t>> migrations_snapshot;
  };

  const EvolutionSettings& settings_;
  const std::vector<Genotype>& seeds_;
  PopulationEvaluator& evaluator_;
  const RunSettings& run_;
  std::ostream& out_;
  Breeder breeder_;
  std::vector<RankedMeasure> ranking_;  // evolution.ranking, parsed (empty: the task's fitness)
  std::vector<Epoch> epochs_;           // evolution.epochs, parsed (empty: one epoch, ranking_)
  EpochPlace epoch_place_;              // the epoch the next generation is rated in
  const std::uint64_t total_;
  const bool steady_;                                     // evolution.mode = steady_state
  std::optional<ArrivalRecord> arrivals_;                 // run.arrival_order, read
  SteadyMembers members_;                                 // a steady state's members
  std::map<std::uint64_t, Individual> steady_in_flight_;  // handed out, not yet taken in
  std::deque<Individual> steady_unsent_;                  // to hand out
  double cpu_start_ = processCpuSeconds();
  Clock::time_point run_start_ = Clock::now();

  RunResult result_;
  RunDigest digest_;
  std::optional<RunLock> lock_;
  std::unique_ptr<HistoryWriter> history_;
  std::optional<Population> last_;  // the last evaluated generation
  std::future<void> writer_;        // a steady state's history rows and checkpoint, being written
  std::optional<Population> retired_;  // the generation before `last_`, freed in the same slot
  std::optional<Pending> pending_;
  std::vector<double> walls_;  // generation wall times, for the max-hours prediction
  std::uint64_t start_ = 0;
  std::uint64_t checkpointed_ = 0;
  Clock::time_point checkpoint_time_ = Clock::now();
  double checkpoint_seconds_max_ = 0;
  Clock::time_point generation_start_ = Clock::now();
  double generation_cpu_start_ = 0;
  bool live_shown_ = false;                     // the live line is on the terminal
  Clock::time_point live_time_ = Clock::now();  // when it was last written
};

}  // namespace

std::string progressLine(const GenerationRecord& r, int generations, double eta_seconds) {
  char line[256];
  std::snprintf(line, sizeof line,
                "gen %llu/%d  best %.6g  mean %.6g  median %.6g  evals/s %.1f  util %.0f%%  "
                "eta %s",
                static_cast<unsigned long long>(r.generation + 1), generations, r.stats.best,
                r.stats.mean, r.stats.median, r.evaluationsPerSecond(), 100 * r.utilisation(),
                clockText(eta_seconds).c_str());
  return line;
}

RunResult runEvolution(const EvolutionSettings& settings, const Encoding& encoding,
                       const std::vector<Genotype>& seeds, PopulationEvaluator& evaluator,
                       const RunSettings& run, std::ostream& out) {
  return EvolutionRun(settings, encoding, seeds, evaluator, run, out).run();
}

}  // namespace cambrian
