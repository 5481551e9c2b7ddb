// A springy organism's lengths and its muscles' sinusoids, on the thesis' own numbers.
#include "encodings/springy/organism.hpp"

#include "encodings/springy/organisms.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cambrian::springy {
namespace {

// Fig. A.5: (L_i − L_r)/A = 0.5767, so φ = 0.6147 rad expanding first and 2.5269 shortening
// first; the length starts at L_i either way, and its range is 0.701 .. 1.131 m
TEST(Organism, TheEditorsMuscleHasThePhaseTheThesisImplies) {
  const Organism o = test::screenshotMuscle();
  const Tube& m = o.tubes[0];
  const double initial = initialLength(o, m);
  EXPECT_DOUBLE_EQ(initial, 1.04);
  EXPECT_NEAR(musclePhase(m.muscle, initial), 0.6147, 5e-5);
  EXPECT_NEAR(muscleLength(m.muscle, initial, 0), initial, 1e-12);
  EXPECT_NEAR(m.muscle.rest_length - m.muscle.amplitude, 0.701, 1e-12);
  EXPECT_NEAR(m.muscle.rest_length + m.muscle.amplitude, 1.131, 1e-12);
  // dL/dt(0) = A ω cos φ = +1.986 m/s expanding, −1.986 shortening
  EXPECT_NEAR(muscleSpeed(m.muscle, initial, 0), 1.986, 5e-4);
  Muscle shortening = m.muscle;
  shortening.first_move = FirstMove::shorten;
  EXPECT_NEAR(musclePhase(shortening, initial), 2.5269, 5e-5);
  EXPECT_NEAR(muscleLength(shortening, initial, 0), initial, 1e-12);
  EXPECT_NEAR(muscleSpeed(shortening, initial, 0), -1.986, 5e-4);
}

// the length is the sinusoid: periodic in 1/f, between L_r − A and L_r + A, its speed the
// derivative
TEST(Organism, AMusclesLengthIsItsSinusoid) {
  const Organism o = test::screenshotMuscle();
  const Muscle& m = o.tubes[0].muscle;
  const double initial = initialLength(o, o.tubes[0]);
  const double period = 1 / m.frequency;
  for (double t = 0; t < 2; t += 0.01) {
    const double length = muscleLength(m, initial, t);
    EXPECT_GE(length, m.rest_length - m.amplitude - 1e-12);
    EXPECT_LE(length, m.rest_length + m.amplitude + 1e-12);
    EXPECT_NEAR(muscleLength(m, initial, t + period), length, 1e-9);
    const double h = 1e-6;
    const double slope =
        (muscleLength(m, initial, t + h) - muscleLength(m, initial, t - h)) / (2 * h);
    EXPECT_NEAR(muscleSpeed(m, initial, t), slope, 1e-5);
  }
}

// A = 0 or f = 0: the muscle keeps its initial length (it is a rod)
TEST(Organism, AMuscleWithoutAmplitudeOrFrequencyIsARod) {
  const Organism o = test::screenshotMuscle();
  const double initial = initialLength(o, o.tubes[0]);
  Muscle still = o.tubes[0].muscle;
  still.frequency = 0;
  Muscle flat = o.tubes[0].muscle;
  flat.amplitude = 0;
  for (double t = 0; t < 3; t += 0.25) {
    EXPECT_NEAR(muscleLength(still, initial, t), initial, 1e-12);
    EXPECT_EQ(muscleSpeed(still, initial, t), 0);
    EXPECT_EQ(muscleLength(flat, initial, t), initial);
    EXPECT_EQ(muscleSpeed(flat, initial, t), 0);
  }
}

TEST(Organism, MorphologyIsEverythingButTheMuscles) {
  const Organism a = test::pyramid();
  EXPECT_EQ(muscleIndices(a), (std::vector<int>{3, 4, 5}));
  EXPECT_DOUBLE_EQ(touchingLength(a, a.tubes[0]), 0.2);
  Organism b = a;
  b.tubes[4].muscle.amplitude = 0.1;
  b.tubes[4].muscle.frequency = 1;
  EXPECT_TRUE(sameMorphology(a, b));
  EXPECT_FALSE(a == b);
  b.nodes[3].position.z += 0.01;
  EXPECT_FALSE(sameMorphology(a, b));
  b = a;
  b.tubes[0].kind = TubeKind::muscle;
  EXPECT_FALSE(sameMorphology(a, b));
}

}  // namespace
}  // namespace cambrian::springy
