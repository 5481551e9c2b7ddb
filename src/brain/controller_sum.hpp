// cambrian: several controllers driving the same effectors, their drives added (Sims' network
// plus Minemonics' joint oscillators in the directed-graph creatures).
#pragma once

#include "cambrian/controller.hpp"

#include <memory>
#include <vector>

namespace cambrian {

/// The plans whose controllers' drives are added, in order.
class ControllerSumPlan : public ControllerPlan {
 public:
  std::vector<std::shared_ptr<const ControllerPlan>> parts;

  std::string kind() const override;
  std::unique_ptr<Controller> build(double time_step, std::size_t sensors,
                                    std::size_t effectors) const override;
  int neuronCount() const override;
};

/// Steps every part with the same sensors; drive e = part 0's + part 1's + ... (in that order).
class ControllerSum : public Controller {
 public:
  ControllerSum(std::vector<std::unique_ptr<Controller>> parts, std::size_t effectors);
  void step(std::span<const double> sensors, std::span<double> drives) override;
  void reset() override;
  std::span<const double> signals() const override;

 private:
  std::vector<std::unique_ptr<Controller>> parts_;
  std::vector<double> scratch_;
};

}  // namespace cambrian
