// cambrian: the [evolution] keys and the rules their values must keep.
#include "evolution/evolution_settings.hpp"

#include "cambrian/error.hpp"

#include "core/settings.hpp"
#include "evolution/competitive_ranking.hpp"
#include "evolution/epochs.hpp"
#include "evolution/wwd_breeding.hpp"

#include <cmath>
#include <iterator>
#include <sstream>

namespace cambrian {

const char* selectionMethodName(SelectionMethod method) {
  switch (method) {
    case SelectionMethod::truncation:
      return "truncation";
    case SelectionMethod::tournament:
      return "tournament";
    case SelectionMethod::roulette:
      return "roulette";
    case SelectionMethod::sus:
      return "sus";
    case SelectionMethod::rank:
      return "rank";
  }
  return "unknown";
}

const char* reaperShareName(ReaperShare share) {
  static constexpr const char* kNames[kReaperShares] = {
      "elite",     "gene_specification", "gene_split", "gene_purge", "branch_specification",
      "grow_stub", "graft_feature"};
  const auto index = static_cast<std::size_t>(share);
  return index < std::size(kNames) ? kNames[index] : "unknown";
}

void EvolutionSettings::declareSettings(SettingsSchema& s) {
  EvolutionSettings& e = *this;
  s.describeSection("evolution", "[evolution] genetic algorithm");
  auto probability = [&s](const char* key, double& value, const char* help) {
    s.add(key, value, help)
        .require([&value] { return value >= 0 && value <= 1; }, "must be in [0, 1]");
  };

  // sizes
  s.add("evolution.population", e.population, "individuals per generation")
      .require([&e] { return e.population >= 2 && e.population <= 1000000; },
               "must be in 2..1000000");
  s.add("evolution.generations", e.generations, "generations to run, the first included")
      .require([&e] { return e.generations >= 1 && e.generations <= 1000000; },
               "must be in 1..1000000")
      .runOnly();

  // reproduction plan
  s.add("evolution.elite_fraction", e.elite_fraction,
        "share of the best kept unchanged and not re-evaluated (0..1)")
      .require([&e] { return e.elite_fraction >= 0 && e.elite_fraction < 1; },
               "must be in [0, 1): some offspring must be bred");
  probability("evolution.mutation_fraction", e.mutation_fraction,
              "share of offspring made by mutation (the three fractions sum to 1)");
  probability("evolution.crossover_fraction", e.crossover_fraction,
              "share of offspring made by crossover");
  probability("evolution.graft_fraction", e.graft_fraction, "share of offspring made by grafting");
  probability("evolution.mutation_rate", e.mutation_rate,
              "chance each parameter of an asexual offspring is perturbed (0..1)");
  probability("evolution.post_crossover_mutation_chance", e.post_crossover_mutation_chance,
              "chance an offspring of crossover or grafting is then mutated");
  probability("evolution.post_crossover_mutation_rate", e.post_crossover_mutation_rate,
              "per-parameter rate of that mutation");

  // generations or a steady state
  s.addChoice("evolution.mode", e.mode,
              {{"generational", EvolutionMode::generational},
               {"steady_state", EvolutionMode::steady_state}},
              "generational (breed a generation, evaluate all of it, then breed the next) | "
              "steady_state (no generation barrier: each result is taken in as it arrives, "
              "replacing a weaker member, and a child bred from the members then is sent out at "
              "once; a generation is evolution.population results; docs/steady-state.md)");
  s.add("evolution.replacement_tournament", e.replacement_tournament,
        "steady_state: members drawn for a reverse tournament; a new result replaces the worst "
        "of them when it is at least as fit")
      .require(
          [&e] {
            return e.replacement_tournament >= 1 && e.replacement_tournament <= e.population;
          },
          "must be in 1..population");
  s.addCheck([&e] {
    if (e.mode != EvolutionMode::steady_state)
      return;
    auto refuse = [](const std::string& what) {
      throw ConfigError("evolution.mode = steady_state: " + what +
                        " needs whole generations; use evolution.mode = generational");
    };
    if (e.scheme != BreedingScheme::generational)
      refuse(std::string("evolution.scheme = ") +
             (e.scheme == BreedingScheme::reaper ? "reaper" : "wwd"));
    if (e.batch_generations > 0)
      refuse("evolution.batch_generations = " + std::to_string(e.batch_generations));
    if (!e.ranking.empty())
      refuse("evolution.ranking (competitive ranking within a generation)");
    if (!e.epochs.empty())
      refuse("evolution.epochs");
  });

  // the breeding scheme, and the reaper's shares (Minemonics)
  s.addChoice("evolution.scheme", e.scheme,
              {{"generational", BreedingScheme::generational},
               {"reaper", BreedingScheme::reaper},
               {"wwd", BreedingScheme::wwd}},
              "how a generation is bred: generational (elites, mutation, crossover, grafting: "
              "Sims, Chaumont et al.) | reaper (Minemonics: cull the worst, vary the survivors, "
              "sow by crossover and at random) | wwd (Walking with Dinosaurs: the elites kept, "
              "every other place a breeder that received a part of an elite by crossover, then "
              "mutated)");
  ReaperSettings& r = e.reaper;
  s.add("evolution.reap_fraction", r.reap_fraction,
        "reaper: share of the worst culled and sown again (Minemonics: 0.3)")
      .require([&r] { return r.reap_fraction > 0 && r.reap_fraction < 1; }, "must be in (0, 1)");
  for (int k = 0; k < kReaperShares; ++k) {
    const std::string name = reaperShareName(static_cast<ReaperShare>(k));
    double& weight = r.shares[static_cast<std::size_t>(k)];
    s.add("evolution.reaper_" + name + "_share", weight,
          k == 0 ? "reaper: weight of the survivors kept unchanged (elitism; every weight 1: "
                   "Minemonics' 14.28 % each)"
                 : "reaper: weight of the survivors varied by " + name)
        .require([&weight] { return weight >= 0 && std::isfinite(weight); },
                 "must be >= 0 and finite");
  }
  s.addChoice(
      "evolution.reaper_crossover", r.crossover,
      {{"crossover", Variation::crossover}, {"segment_crossover", Variation::segment_crossover}},
      "reaper: the crossover that sows: crossover (Sims', the genes of two parents aligned "
      "by index) | segment_crossover (Minemonics': a run of genes of each parent, joined "
      "and then re-drawn at evolution.segment_branch_redraws connections)");
  probability("evolution.sow_crossover_fraction", r.sow_crossover_fraction,
              "reaper: share of the sown made by crossover, the rest random (Minemonics: 0.5)");
  s.add("evolution.reaper_tournament_size", r.tournament_size,
        "reaper: contestants of a partner's tournament (Minemonics: 10)")
      .require([&r] { return r.tournament_size >= 1 && r.tournament_size <= 1000; },
               "must be in 1..1000");
  probability("evolution.reaper_tournament_chance", r.tournament_chance,
              "reaper: chance a partner is the best of a tournament, else drawn uniformly "
              "(Minemonics: 0.5)");
  s.addCheck([&r] {
    double sum = 0;
    for (double weight : r.shares)
      sum += weight;
    if (!(sum > 0))
      throw ConfigError("evolution.reaper_*_share: every weight is 0; give one a weight");
  });

  // Walking with Dinosaurs' scheme (wwd_breeding.hpp)
  WwdSettings& w = e.wwd;
  s.add("evolution.wwd_elite_fraction", w.elite_fraction,
        "wwd: share of the best kept with their outcomes, each bred child's donor (the seed: "
        "0.2)")
      .require([&w] { return w.elite_fraction > 0 && w.elite_fraction < 1; }, "must be in (0, 1)");
  s.add("evolution.wwd_breeder_fraction", w.breeder_fraction,
        "wwd: share after the elites that receive a part of an elite (the seed: 0.3; the rest "
        "is gene pool waste)")
      .require([&w] { return w.breeder_fraction > 0 && w.breeder_fraction < 1; },
               "must be in (0, 1)");
  s.add("evolution.wwd_adaptive_mutation", w.adaptive_mutation,
        "wwd: scale the mutation of the bred by the spread of the generation's fitnesses, the "
        "less spread the more mutation (the seed's Deviation): multiplier = "
        "clamp(wwd_target_deviation / s, wwd_min_multiplier, wwd_max_multiplier), s the standard "
        "deviation of the fitnesses divided by the largest |fitness| (all 0: s = 0); it scales "
        "the wwd encoding's chance per gene, another encoding's evolution.mutation_rate");
  s.add("evolution.wwd_target_deviation", w.target_deviation,
        "wwd: the normalised fitness deviation at which the mutation is not scaled (0..0.5: the "
        "normalised fitnesses lie in 0..1)")
      .require([&w] { return w.target_deviation > 0 && std::isfinite(w.target_deviation); },
               "must be > 0 and finite");
  s.add("evolution.wwd_min_multiplier", w.min_multiplier,
        "wwd: the least the mutation is scaled by (a wide spread of fitnesses)")
      .require([&w] { return w.min_multiplier > 0 && std::isfinite(w.min_multiplier); },
               "must be > 0 and finite");
  s.add("evolution.wwd_max_multiplier", w.max_multiplier,
        "wwd: the most the mutation is scaled by (no spread of fitnesses)")
      .require([&w] { return w.max_multiplier > 0 && std::isfinite(w.max_multiplier); },
               "must be > 0 and finite");
  s.addCheck([&e, &w] {
    std::ostringstream message;
    if (w.elite_fraction + w.breeder_fraction > 1 + 1e-9) {
      message << "evolution.wwd_elite_fraction + evolution.wwd_breeder_fraction = "
              << w.elite_fraction + w.breeder_fraction
              << ": must be at most 1 (the rest is the gene pool waste)";
      throw ConfigError(message.str());
    }
    if (w.min_multiplier > w.max_multiplier) {
      message << "evolution.wwd_min_multiplier = " << w.min_multiplier
              << " is above evolution.wwd_max_multiplier = " << w.max_multiplier;
      throw ConfigError(message.str());
    }
    if (e.scheme != BreedingScheme::wwd)
      return;
    // the population must hold at least one elite, one breeder and one bred place
    const WwdPlan plan = planWwd(e);
    if (plan.elites < 1) {
      message << "evolution.wwd_elite_fraction = " << w.elite_fraction << ": no elite in "
              << "evolution.population = " << e.population << " (round(" << e.population << " x "
              << w.elite_fraction << ") = 0); the wwd scheme needs at least one";
      throw ConfigError(message.str());
    }
    if (plan.breeders < 1) {
      message << "evolution.wwd_breeder_fraction = " << w.breeder_fraction << ": no breeder in "
              << "evolution.population = " << e.population << " after " << plan.elites
              << " elites; the wwd scheme needs at least one";
      throw ConfigError(message.str());
    }
  });

  // selection
  s.addChoice("evolution.selection", e.selection.method,
              {{"truncation", SelectionMethod::truncation},
               {"tournament", SelectionMethod::tournament},
               {"roulette", SelectionMethod::roulette},
               {"sus", SelectionMethod::sus},
               {"rank", SelectionMethod::rank}},
              "parent selection: truncation | tournament | roulette | sus | rank");
  s.addChoice("evolution.mutation_selection", e.mutation_selection,
              {{"same", MutationSelection::same},
               {"truncation", MutationSelection::truncation},
               {"tournament", MutationSelection::tournament},
               {"roulette", MutationSelection::roulette},
               {"sus", MutationSelection::sus},
               {"rank", MutationSelection::rank}},
              "how the parents of mutation are drawn: same (as evolution.selection, in one "
              "draw with the crossover and graft parents) | truncation | tournament | roulette | "
              "sus | rank (with evolution.selection's parameters)");
  SelectionSettings& sel = e.selection;
  s.add("evolution.truncation_fraction", sel.truncation_fraction,
        "truncation: share of the best that may be parents")
      .require([&sel] { return sel.truncation_fraction > 0 && sel.truncation_fraction <= 1; },
               "must be in (0, 1]");
  s.add("evolution.tournament_size", sel.tournament_size, "tournament: contestants per pick")
      .require(
          [&e] {
            return e.selection.tournament_size >= 1 && e.selection.tournament_size <= e.population;
          },
          "must be in 1..population");
  s.add("evolution.rank_pressure", sel.rank_pressure, "rank: expected picks of the best (1..2)")
      .require([&sel] { return sel.rank_pressure >= 1 && sel.rank_pressure <= 2; },
               "must be in [1, 2]");
  s.add("evolution.seed_genomes", e.seed_genomes,
        "genome files the first generation starts from (repeat the key or separate by spaces)")
      .require([&e] { return static_cast<int>(e.seed_genomes.size()) <= e.population; },
               "more seed genomes than the population");
  s.add("evolution.seed_history", e.seed_history,
        "a previous run's history.h5: the best individual (status ok; ties: lowest id) of its "
        "last generation seeds the first generation, after any seed genomes, the rest mutated "
        "copies (a sequence of fitness tests; empty: none)");
  s.addCheck([&e] {
    if (!e.seed_history.empty() && static_cast<int>(e.seed_genomes.size()) + 1 > e.population)
      throw ConfigError("evolution.seed_history = " + e.seed_history +
                        ": more seed genomes (evolution.seed_genomes and the history's best) "
                        "than evolution.population = " +
                        std::to_string(e.population));
  });
  s.add("evolution.batch_generations", e.batch_generations,
        "short batches (Walking with Dinosaurs' stops): after every this many generations the "
        "next starts from the best creature (status ok; ties: lowest id), kept with its outcome, "
        "and mutated copies of it, as from a seed genome; 0: one batch")
      .require([&e] { return e.batch_generations >= 0; }, "must be >= 0");
  s.add("evolution.ranking", e.ranking,
        "competitive ranking (Minemonics): measures NAME[:WEIGHT[:higher|lower]]; the fitness "
        "becomes the weighted count of individuals each one beats on each (empty: the task's)");
  s.addCheck([&e] {
    for (const std::string& text : e.ranking)
      parseRankedMeasure(text, "evolution.ranking");
  });
  s.add("evolution.epochs", e.epochs,
        "epochs (Minemonics): each RANKING[@CONDITION], RANKING the measures "
        "NAME[:WEIGHT[:higher|lower]] joined by + and ranked as evolution.ranking, CONDITION "
        "N (generations) or NAME>=X / NAME<=X (reached by the best of a generation); every epoch "
        "but the last has one (empty: one epoch, evolution.ranking or the task's fitness)");
  s.addCheck([&e] {
    parseEpochs(e.epochs, "evolution.epochs");
    if (!e.epochs.empty() && !e.ranking.empty())
      throw ConfigError(
          "evolution.epochs and evolution.ranking are both set: give the ranking of "
          "each epoch in evolution.epochs");
  });
  s.addSeed("run.seed", e.seed, "run seed, 0..2^64-1 (same seed, same run)");

  // the rule across keys: the offspring shares add up
  s.addCheck([&e] {
    double sum = e.mutation_fraction + e.crossover_fraction + e.graft_fraction;
    if (!(std::fabs(sum - 1) <= 1e-9)) {
      std::ostringstream message;
      message << "evolution.mutation_fraction + evolution.crossover_fraction + "
                 "evolution.graft_fraction = "
              << sum << ": must sum to 1";
      throw ConfigError(message.str());
    }
  });
}

void validateEvolutionSettings(const EvolutionSettings& settings) {
  EvolutionSettings copy = settings;
  SettingsSchema schema;
  copy.declareSettings(schema);
  schema.check();
}

}  // namespace cambrian
