// The test morphologies of jobs/creatures/springy/: each reads, keeps the rules, has the thesis'
// muscle count, rests on the ground, and its muscles can be drawn.
#include "cambrian/rng.hpp"

#include "core/small_file.hpp"
#include "encodings/springy/muscle_operators.hpp"
#include "encodings/springy/organism_forms.hpp"
#include "encodings/springy/rules.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace cambrian::springy {
namespace {

Organism creature(const std::string& name) {
  const std::string path =
      std::string(CAMBRIAN_SOURCE_DIR) + "/jobs/creatures/springy/" + name + ".organism";
  const SmallFile file = readSmallFile(path, 1 << 20);
  EXPECT_EQ(file.problem, "") << path;
  return parseOrganismText(file.bytes, path);
}

// Fig. 4.1: Pyramids 3 muscles, Snake 6, Round Ladder 8, Horse 16
TEST(SpringyCreatures, TheFourMorphologiesKeepTheRulesWithTheThesisMuscleCounts) {
  const std::pair<const char*, std::size_t> expected[] = {
      {"pyramid", 3}, {"snake", 6}, {"round_ladder", 8}, {"horse", 16}};
  for (const auto& [name, muscles] : expected) {
    const Organism o = creature(name);
    EXPECT_EQ(muscleIndices(o).size(), muscles) << name;
    EXPECT_NO_THROW(checkOrganism(o, MuscleLimits{})) << name;
    // standing on the ground: the lowest node touches z = 0
    double lowest = 1e9;
    for (const Node& node : o.nodes)
      lowest = std::min(lowest, node.position.z - 0.5 * node.diameter);
    EXPECT_NEAR(lowest, 0, 1e-6) << name;
    // written again, the same organism
    EXPECT_EQ(parseOrganismText(organismToText(o), name), o) << name;
    // every creature of a run: the morphology with its muscles drawn
    for (std::uint64_t i = 0; i < 20; ++i) {
      Rng rng(1, RngPurpose::test, 0, i);
      EXPECT_NO_THROW(
          checkOrganism(randomControl(o, MuscleOperatorSettings{}, rng), MuscleLimits{}))
          << name;
    }
  }
}

}  // namespace
}  // namespace cambrian::springy
