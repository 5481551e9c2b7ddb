#include "evolution/evolution_settings.hpp"

#include "cambrian/error.hpp"

#include <cmath>
#include <sstream>

namespace cambrian {

namespace {

// throws ConfigError "evolution.<key> = value: rule"
void require(bool ok, const std::string& key, double value, const std::string& rule) {
  if (!ok || std::isnan(value)) {
    std::ostringstream message;
    message << "evolution." << key << " = " << value << ": " << rule;
    throw ConfigError(message.str());
  }
}

// a probability: finite and in [0, 1]
void requireProbability(const std::string& key, double value) {
  require(value >= 0 && value <= 1, key, value, "must be in [0, 1]");
}

}  // namespace

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

SelectionMethod selectionMethodFromName(const std::string& name) {
  // every method by its name
  for (SelectionMethod method :
       {SelectionMethod::truncation, SelectionMethod::tournament, SelectionMethod::roulette,
        SelectionMethod::sus, SelectionMethod::rank}) {
    if (name == selectionMethodName(method))
      return method;
  }
  throw ConfigError("evolution.selection = " + name +
                    ": must be truncation, tournament, roulette, sus or rank");
}

void validateEvolutionSettings(const EvolutionSettings& s) {
  // sizes
  require(s.population >= 2 && s.population <= 1000000, "population", s.population,
          "must be in 2..1000000");
  require(s.generations >= 1 && s.generations <= 1000000, "generations", s.generations,
          "must be in 1..1000000");

  // reproduction plan
  require(s.elite_fraction >= 0 && s.elite_fraction < 1, "elite_fraction", s.elite_fraction,
          "must be in [0, 1): some offspring must be bred");
  requireProbability("mutation_fraction", s.mutation_fraction);
  requireProbability("crossover_fraction", s.crossover_fraction);
  requireProbability("graft_fraction", s.graft_fraction);
  double sum = s.mutation_fraction + s.crossover_fraction + s.graft_fraction;
  require(std::fabs(sum - 1) <= 1e-9,
          "mutation_fraction + evolution.crossover_fraction + evolution.graft_fraction", sum,
          "must sum to 1");
  requireProbability("post_crossover_mutation_chance", s.post_crossover_mutation_chance);
  requireProbability("post_crossover_mutation_rate", s.post_crossover_mutation_rate);

  // mutation
  const MutationSettings& m = s.mutation;
  requireProbability("mutation_rate", m.parameter_rate);
  require(m.perturbation > 0 && m.perturbation <= 10, "mutation_perturbation", m.perturbation,
          "must be in (0, 10]");
  requireProbability("add_node_rate", m.add_node_rate);
  requireProbability("remove_node_rate", m.remove_node_rate);
  requireProbability("add_connection_rate", m.add_connection_rate);
  requireProbability("remove_connection_rate", m.remove_connection_rate);
  requireProbability("repoint_rate", m.repoint_rate);
  requireProbability("add_neuron_rate", m.add_neuron_rate);
  requireProbability("remove_neuron_rate", m.remove_neuron_rate);

  // selection
  const SelectionSettings& sel = s.selection;
  require(sel.truncation_fraction > 0 && sel.truncation_fraction <= 1, "truncation_fraction",
          sel.truncation_fraction, "must be in (0, 1]");
  require(sel.tournament_size >= 1 && sel.tournament_size <= s.population, "tournament_size",
          sel.tournament_size, "must be in 1..population");
  require(sel.rank_pressure >= 1 && sel.rank_pressure <= 2, "rank_pressure", sel.rank_pressure,
          "must be in [1, 2]");
  require(static_cast<int>(s.seed_genomes.size()) <= s.population, "seed_genomes",
          static_cast<double>(s.seed_genomes.size()), "more seed genomes than the population");
}

}  // namespace cambrian
