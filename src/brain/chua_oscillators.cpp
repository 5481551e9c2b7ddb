// cambrian: per-joint chaotic (Chua circuit) oscillators.
#include "brain/chua_oscillators.hpp"

#include "cambrian/error.hpp"

#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>

#include <cmath>
#include <string>

namespace cambrian {

ChuaState chuaDerivative(const ChuaCircuit& c, const ChuaState& u) {
  const double x = u[0], y = u[1], z = u[2];
  // the three-segment piecewise-linear resistor (Chua's diode)
  const double g =
      c.outer_slope * x + (c.inner_slope - c.outer_slope) / 2 *
                              (std::abs(x + c.breakpoint) - std::abs(x - c.breakpoint));
  double dx = c.alpha * (y - x - g);
  if (c.limited)
    dx *= (std::tanh(c.limit_softness * (c.limit - x)) + 1) / 2;
  return {dx, x - y + z, -c.beta * y};
}

std::unique_ptr<Controller> ChuaOscillatorsPlan::build(double time_step, std::size_t,
                                                       std::size_t effectors) const {
  if (effectors != oscillators.size()) {
    throw Error(ExitCode::failure, "chaotic oscillators: " + std::to_string(oscillators.size()) +
                                       " oscillators for " + std::to_string(effectors) +
                                       " effectors");
  }
  return std::make_unique<ChuaOscillators>(oscillators, circuit, time_step);
}

ChuaOscillators::ChuaOscillators(std::vector<ChuaOscillator> oscillators, ChuaCircuit circuit,
                                 double time_step)
    : oscillators_(std::move(oscillators)), circuit_(circuit), time_step_(time_step) {
  if (!(time_step > 0) || !std::isfinite(time_step)) {
    throw ConfigError("chaotic oscillators: time_step = " + std::to_string(time_step) +
                      " must be positive and finite");
  }
  if (!(circuit.integration_step > 0) || !std::isfinite(circuit.integration_step)) {
    throw ConfigError("chaotic oscillators: integration_step = " +
                      std::to_string(circuit.integration_step) + " must be positive and finite");
  }
  states_.resize(oscillators_.size());
  grid_steps_.resize(oscillators_.size());
  signals_.resize(3 * oscillators_.size());
  reset();
}

void ChuaOscillators::step(std::span<const double>, std::span<double> drives) {
  boost::numeric::odeint::runge_kutta4<ChuaState> stepper;
  auto system = [this](const ChuaState& u, ChuaState& dudt, double) {
    dudt = chuaDerivative(circuit_, u);
  };
  ++steps_;
  const double seconds = static_cast<double>(steps_) * time_step_;
  for (std::size_t e = 0; e < oscillators_.size(); ++e) {
    const ChuaOscillator& o = oscillators_[e];
    if (!o.enabled) {
      if (e < drives.size())
        drives[e] = 0.0;
      continue;
    }
    ChuaState& u = states_[e];
    if (e < drives.size())
      drives[e] = o.amplitude * u[2] + o.offset;
    // on along the circuit's own grid to where the next step starts (a grid point the rounding
    // of the product puts a hair late still counts as reached)
    const double due =
        std::floor(o.speed * circuit_.rate * seconds / circuit_.integration_step + 1e-9);
    for (; static_cast<double>(grid_steps_[e]) < due; ++grid_steps_[e])
      stepper.do_step(system, u, 0.0, circuit_.integration_step);
    for (int k = 0; k < 3; ++k)
      signals_[3 * e + k] = u[k];
  }
}

void ChuaOscillators::reset() {
  steps_ = 0;
  for (std::size_t e = 0; e < oscillators_.size(); ++e) {
    states_[e] = oscillators_[e].start;
    grid_steps_[e] = 0;
    for (int k = 0; k < 3; ++k)
      signals_[3 * e + k] = states_[e][k];
  }
}

std::span<const double> ChuaOscillators::signals() const {
  return signals_;
}

}  // namespace cambrian
