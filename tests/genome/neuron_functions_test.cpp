#include "cambrian/genome.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace cambrian {
namespace {

// arities follow Sims' function set
TEST(NeuronFunctions, Arity) {
  EXPECT_EQ(neuronArity(NeuronFunction::constant), 0);
  EXPECT_EQ(neuronArity(NeuronFunction::sin), 1);
  EXPECT_EQ(neuronArity(NeuronFunction::oscillate_wave), 1);
  EXPECT_EQ(neuronArity(NeuronFunction::sum), 2);
  EXPECT_EQ(neuronArity(NeuronFunction::greater_than), 2);
  EXPECT_EQ(neuronArity(NeuronFunction::if_positive), 3);
  EXPECT_EQ(neuronArity(NeuronFunction::interpolate), 3);
  for (int i = 0; i < static_cast<int>(NeuronFunction::count_); ++i) {
    int arity = neuronArity(static_cast<NeuronFunction>(i));
    EXPECT_GE(arity, 0);
    EXPECT_LE(arity, 3);
  }
}

// every function has a distinct lower-case name; out-of-range values are "unknown"
TEST(NeuronFunctions, NamesAreDistinct) {
  std::set<std::string> names;
  for (int i = 0; i < static_cast<int>(NeuronFunction::count_); ++i) {
    std::string name = neuronFunctionName(static_cast<NeuronFunction>(i));
    EXPECT_FALSE(name.empty());
    EXPECT_NE(name, "unknown");
    names.insert(name);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(NeuronFunction::count_));
  EXPECT_STREQ(neuronFunctionName(NeuronFunction::oscillate_wave), "oscillate_wave");
  EXPECT_STREQ(neuronFunctionName(static_cast<NeuronFunction>(200)), "unknown");
}

}  // namespace
}  // namespace cambrian
