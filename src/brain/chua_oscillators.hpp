// cambrian: per-joint chaotic oscillators as a controller (Minemonics' chaotic controllers): each
// effector runs its own Chua circuit and drives amplitude * z + offset.
#pragma once

#include "cambrian/controller.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cambrian {

/// A Chua circuit's state (x, y, z), dimensionless.
using ChuaState = std::array<double, 3>;

/// The circuit all of a run's chaotic oscillators share (Minemonics' constants): the double scroll
///   dx/dt = alpha (y - x - g(x)) * limiter(x),  dy/dt = x - y + z,  dz/dt = -beta y,
///   g(x) = outer_slope x + (inner_slope - outer_slope) / 2 (|x + breakpoint| - |x - breakpoint|),
/// with limiter(x) = (tanh(limit_softness (limit - x)) + 1) / 2 when `limited`, else 1.
struct ChuaCircuit {
  double alpha = 15.6;
  double beta = 28;
  double inner_slope = -1.143;  ///< g's slope within +-breakpoint
  double outer_slope = -0.714;  ///< g's slope outside
  double breakpoint = 1;
  bool limited = false;       ///< the limiter on dx/dt (commented out in Minemonics' last code)
  double limit = 2;           ///< the x the limiter holds the circuit below
  double limit_softness = 7;  ///< how sharply it does
  double rate = 0.24;         ///< circuit time per simulated second at speed 1
  double integration_step = 0.001;  ///< the circuit-time step of the RK4 integration
  friend bool operator==(const ChuaCircuit&, const ChuaCircuit&) = default;
};

/// The circuit's time derivative at `u`.
ChuaState chuaDerivative(const ChuaCircuit& circuit, const ChuaState& u);

/// One effector's chaotic oscillator; a disabled one drives 0.
struct ChuaOscillator {
  bool enabled = false;
  double amplitude = 0;      ///< drive per unit of z (effector units)
  double offset = 0;         ///< effector units
  ChuaState start{0, 0, 0};  ///< the circuit's state when the evaluation starts
  double speed = 1;          ///< circuit time runs speed * ChuaCircuit::rate per second
  friend bool operator==(const ChuaOscillator&, const ChuaOscillator&) = default;
};

/// One oscillator per effector (BodyPlan effector order) and their circuit.
class ChuaOscillatorsPlan : public ControllerPlan {
 public:
  std::vector<ChuaOscillator> oscillators;
  ChuaCircuit circuit;

  std::string kind() const override { return "chaotic"; }
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
};

/// The running oscillators; read no sensors. Each circuit runs on its own grid of RK4 steps of
/// integration_step circuit time from its start, so its states do not depend on the physics
/// step: at simulated time t it has taken floor(speed * rate * t / integration_step) of them, and
/// each controller step drives from the state it has at the step's start.
class ChuaOscillators : public Controller {
 public:
  ChuaOscillators(std::vector<ChuaOscillator> oscillators, ChuaCircuit circuit, double time_step);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override;
  /// Every oscillator's state, x y z in effector order.
  std::span<const double> signals() const override;

 private:
  std::vector<ChuaOscillator> oscillators_;
  ChuaCircuit circuit_;
  double time_step_ = 0;
  std::uint64_t steps_ = 0;                // controller steps taken
  std::vector<std::uint64_t> grid_steps_;  // RK4 steps each circuit has taken
  std::vector<ChuaState> states_;
  std::vector<double> signals_;
};

}  // namespace cambrian
