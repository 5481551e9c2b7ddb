#include "core/test_kill.hpp"

#include "cambrian/error.hpp"

#include <csignal>
#include <cstdio>
#include <set>

namespace cambrian {

namespace {

// the armed point; empty when disarmed
std::string armed_point;
std::uint64_t armed_generation = 0;

}  // namespace

void setTestKillPoint(const std::string& spec) {
  armed_point.clear();
  if (spec.empty())
    return;
  // POINT:GENERATION with a known point
  static const std::set<std::string> points = {"evaluation", "history", "checkpoint_write",
                                               "checkpoint_rename", "checkpoint_done"};
  std::size_t colon = spec.find(':');
  std::string point = spec.substr(0, colon);
  std::size_t used = 0;
  unsigned long long generation = 0;
  bool ok = colon != std::string::npos && points.count(point) > 0;
  try {
    if (ok)
      generation = std::stoull(spec.substr(colon + 1), &used);
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok || used == 0 || colon + 1 + used != spec.size())
    throw ConfigError("run.test_kill_at: '" + spec +
                      "' is not POINT:GENERATION with POINT one of evaluation, history, "
                      "checkpoint_write, checkpoint_rename, checkpoint_done");
  armed_point = point;
  armed_generation = generation;
}

bool testKillArmed(const std::string& point, std::uint64_t generation) {
  return !armed_point.empty() && point == armed_point && generation == armed_generation;
}

void testKillPoint(const std::string& point, std::uint64_t generation) {
  if (!testKillArmed(point, generation))
    return;
  std::fprintf(stderr, "cambrian evolve: run.test_kill_at %s:%llu: SIGKILL\n", point.c_str(),
               static_cast<unsigned long long>(generation));
  std::fflush(stderr);
  std::raise(SIGKILL);
}

}  // namespace cambrian
