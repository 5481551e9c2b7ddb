// cambrian: steady-state evolution's rule of replacement — where a result taken in goes among
// the members. Its children come from Breeder::steadyChild (steady_state.cpp); the run driver
// (run/evolution_run.cpp) takes results in as they arrive.
#pragma once

#include "evolution/evolution_settings.hpp"
#include "evolution/population.hpp"

#include <cstdint>

namespace cambrian {

/// The counter of the random streams steady-state evolution draws for an individual: (seed,
/// selection, id, kSteadyStream) picks the operator and parents of the child `id`, (seed,
/// variation, id, kSteadyStream) varies it, (seed, selection, id, kSteadyStream + 1) draws the
/// reverse tournament it meets when taken in. No generational stream has this counter (theirs
/// are offspring slots, below a population's size).
constexpr std::uint64_t kSteadyStream = ~std::uint64_t{0} - 1;

/// Takes an evaluated individual into `members` (kept in id order): while they are fewer than
/// evolution.population it joins them; else `replacement_tournament` members are drawn (with
/// replacement) from its stream, and it replaces the worst of them (the lowest fitness, ties: the
/// lowest id, the oldest) when it is at least as fit. A pure function of the members, the
/// individual and the settings. Returns whether it entered.
bool takeIntoMembers(Population& members, Individual individual, const EvolutionSettings& settings);

}  // namespace cambrian
