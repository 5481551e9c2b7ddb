#include "brain/chua_oscillators.hpp"

#include "cambrian/error.hpp"

#include "brain/allocation_counter.hpp"

#include <boost/numeric/odeint.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cambrian {
namespace {

// Chua's equations as written in the circuit's literature (alpha 15.6, beta 28, slopes -1.143
// inside +-1 and -0.714 outside), independently of chuaDerivative
void chuaEquations(const ChuaState& u, ChuaState& dudt, double) {
  const double x = u[0], y = u[1], z = u[2];
  const double g = std::abs(x) <= 1 ? -1.143 * x : -0.714 * x + (x > 0 ? -0.429 : 0.429);
  dudt = {15.6 * (y - x - g), x - y + z, -28 * y};
}

// one oscillator with drive = z (amplitude 1, offset 0)
ChuaOscillators single(ChuaState start, double speed, double time_step, ChuaCircuit circuit = {}) {
  return ChuaOscillators({ChuaOscillator{true, 1.0, 0.0, start, speed}}, circuit, time_step);
}

// the drives (z) of `steps` steps
std::vector<double> drives(ChuaOscillators& controller, int steps) {
  std::vector<double> out;
  double drive = 0;
  for (int s = 0; s < steps; ++s) {
    controller.step({}, std::span<double>(&drive, 1));
    out.push_back(drive);
  }
  return out;
}

// the derivative at hand-computed points, in the inner and the outer segment
TEST(ChuaCircuit, TheDerivativeIsChuasEquations) {
  const ChuaCircuit circuit;
  // x = 0.5 (inner): g = -1.143 * 0.5 = -0.5715
  ChuaState d = chuaDerivative(circuit, {0.5, 0.1, -0.2});
  EXPECT_NEAR(d[0], 15.6 * (0.1 - 0.5 + 0.5715), 1e-12);
  EXPECT_NEAR(d[1], 0.5 - 0.1 - 0.2, 1e-12);
  EXPECT_NEAR(d[2], -28 * 0.1, 1e-12);
  // x = 2 (outer): g = -0.714 * 2 - 0.429 = -1.857
  d = chuaDerivative(circuit, {2, -0.3, 1});
  EXPECT_NEAR(d[0], 15.6 * (-0.3 - 2 + 1.857), 1e-12);
  // x = -2: g is odd
  d = chuaDerivative(circuit, {-2, 0.3, -1});
  EXPECT_NEAR(d[0], -15.6 * (-0.3 - 2 + 1.857), 1e-12);
  // the limiter scales dx/dt only, by (tanh(7 (2 - x)) + 1) / 2
  ChuaCircuit limited;
  limited.limited = true;
  const ChuaState free = chuaDerivative(circuit, {1.8, 0.2, 0.4});
  const ChuaState held = chuaDerivative(limited, {1.8, 0.2, 0.4});
  EXPECT_NEAR(held[0], free[0] * (std::tanh(7 * 0.2) + 1) / 2, 1e-12);
  EXPECT_EQ(held[1], free[1]);
  EXPECT_EQ(held[2], free[2]);
}

// the controller's drive follows z of Chua's equations integrated by an adaptive Dormand-Prince
// to 1e-13, within RK4's error at steps of 0.001 (fourth order between the diode's breakpoints,
// second order across them): one second at speed 5 (1.2 units of circuit time), 240 steps, each
// driving from the circuit's state at its start, 5 grid steps (0.005 circuit time) apart
TEST(ChuaOscillators, TheDriveFollowsChuasEquations) {
  const ChuaState start{0.3, -0.2, 0.1};
  ChuaOscillators controller = single(start, 5.0, 1.0 / 240);
  const std::vector<double> got = drives(controller, 240);
  using namespace boost::numeric::odeint;
  auto stepper = make_dense_output(1e-13, 1e-13, runge_kutta_dopri5<ChuaState>());
  ChuaState u = start;
  const double per_step = 0.005;
  for (int s = 0; s < 240; ++s) {
    ASSERT_NEAR(got[s], u[2], 1e-5) << "step " << s;
    integrate_adaptive(stepper, chuaEquations, u, s * per_step, (s + 1) * per_step, per_step);
  }
  EXPECT_EQ(controller.signals().size(), 3u);
  // and it moved: z went somewhere in that time
  EXPECT_GT(std::abs(got.back() - got.front()), 0.05);
}

// chaos: two circuits started 1e-9 apart part ways, each stays on the double scroll (|z| within
// 3.7, |x| within 2.3) and visits both scrolls (x of both signs)
TEST(ChuaOscillators, TheCircuitIsChaoticOnTheDoubleScroll) {
  ChuaOscillators a = single({0.1, 0.2, -0.3}, 10.0, 1.0 / 240);
  ChuaOscillators b = single({0.1 + 1e-9, 0.2, -0.3}, 10.0, 1.0 / 240);
  const int steps = 240 * 40;  // 40 s: 96 units of circuit time
  double largest_gap = 0, largest_z = 0, lowest_x = 0, highest_x = 0;
  double drive = 0;
  for (int s = 0; s < steps; ++s) {
    a.step({}, std::span<double>(&drive, 1));
    const double za = drive;
    b.step({}, std::span<double>(&drive, 1));
    largest_gap = std::max(largest_gap, std::abs(za - drive));
    largest_z = std::max(largest_z, std::abs(za));
    lowest_x = std::min(lowest_x, a.signals()[0]);
    highest_x = std::max(highest_x, a.signals()[0]);
  }
  EXPECT_GT(largest_gap, 1.0);
  EXPECT_LT(largest_z, 3.7);
  EXPECT_GT(largest_z, 2.0);
  EXPECT_LT(highest_x, 2.3);
  EXPECT_LT(lowest_x, -1.0);
  EXPECT_GT(highest_x, 1.0);
}

// the limiter at x = 1.9 holds the circuit on one scroll: after the start x stays below 2 and
// never turns negative again (measured: a cycle within 0.07 < x < 2.0)
TEST(ChuaOscillators, TheLimiterHoldsTheCircuitOnOneScroll) {
  ChuaCircuit circuit;
  circuit.limited = true;
  circuit.limit = 1.9;
  ChuaOscillators controller = single({0.1, 0.2, -0.3}, 10.0, 1.0 / 240, circuit);
  double drive = 0, lowest_x = 10, highest_x = -10;
  for (int s = 0; s < 240 * 60; ++s) {
    controller.step({}, std::span<double>(&drive, 1));
    if (s > 240 * 20) {
      lowest_x = std::min(lowest_x, controller.signals()[0]);
      highest_x = std::max(highest_x, controller.signals()[0]);
    }
  }
  EXPECT_LT(highest_x, 2.0);
  EXPECT_GT(lowest_x, 0.0);
  EXPECT_GT(highest_x - lowest_x, 1.0);  // it still swings
}

// each circuit runs on its own grid, whatever the physics step: 1/120 s and 1/480 s steps reach
// the same state, bit for bit, after half a second (0.84 units of circuit time, 840 grid steps),
// and at speed 0.5 a 1/240 s step advances the circuit every other step or so (0.0005 a step)
TEST(ChuaOscillators, TheCircuitDoesNotDependOnTheTimeStep) {
  ChuaOscillators coarse = single({0.2, 0.1, -0.1}, 7.0, 1.0 / 120);
  ChuaOscillators fine = single({0.2, 0.1, -0.1}, 7.0, 1.0 / 480);
  drives(coarse, 60);
  drives(fine, 240);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(coarse.signals()[k], fine.signals()[k]) << k;
  ChuaOscillators slow = single({0.2, 0.1, -0.1}, 0.5, 1.0 / 240);
  const std::vector<double> z = drives(slow, 4);
  EXPECT_EQ(z[0], z[1]);  // 0.0005 circuit time: no grid step yet
  EXPECT_NE(z[1], z[2]);  // 0.001: the first
  EXPECT_EQ(z[2], z[3]);
}

// amplitude and offset scale and shift z; a disabled oscillator drives 0; reset starts over
TEST(ChuaOscillators, AmplitudeOffsetDisabledAndReset) {
  ChuaOscillatorsPlan plan;
  plan.oscillators = {ChuaOscillator{true, 0.25, 0.1, {0.1, 0.2, 0.4}, 2.0}, ChuaOscillator{}};
  auto controller = plan.build(1.0 / 240, 0, 2);
  std::vector<double> first(2), second(2);
  controller->step({}, first);
  EXPECT_DOUBLE_EQ(first[0], 0.25 * 0.4 + 0.1);
  EXPECT_EQ(first[1], 0.0);
  for (int s = 0; s < 100; ++s)
    controller->step({}, second);
  EXPECT_NE(second[0], first[0]);
  controller->reset();
  controller->step({}, second);
  EXPECT_EQ(second, first);
  EXPECT_EQ(plan.kind(), "chaotic");
  // stepping allocates nothing (controllers run inside the physics loop)
  const long allocations = allocationCount();
  for (int s = 0; s < 100; ++s)
    controller->step({}, second);
  EXPECT_EQ(allocationCount(), allocations);
  EXPECT_THROW(plan.build(1.0 / 240, 0, 3), Error);
  EXPECT_THROW(ChuaOscillators({}, ChuaCircuit{}, 0.0), ConfigError);
}

}  // namespace
}  // namespace cambrian
