// cambrian: the sum of several controllers.
#include "brain/controller_sum.hpp"

#include <algorithm>

namespace cambrian {

std::string ControllerSumPlan::kind() const {
  std::string text;
  for (const auto& part : parts)
    text += (text.empty() ? "" : "+") + part->kind();
  return text;
}

std::unique_ptr<Controller> ControllerSumPlan::build(double time_step, std::size_t sensors,
                                                     std::size_t effectors) const {
  std::vector<std::unique_ptr<Controller>> built;
  for (const auto& part : parts)
    built.push_back(part->build(time_step, sensors, effectors));
  return std::make_unique<ControllerSum>(std::move(built), effectors);
}

int ControllerSumPlan::neuronCount() const {
  int total = 0;
  for (const auto& part : parts)
    total += part->neuronCount();
  return total;
}

ControllerSum::ControllerSum(std::vector<std::unique_ptr<Controller>> parts, std::size_t effectors)
    : parts_(std::move(parts)), scratch_(effectors, 0.0) {}

void ControllerSum::step(std::span<const double> sensors, std::span<double> drives) {
  // the first part writes, the others add
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    if (p == 0) {
      parts_[p]->step(sensors, drives);
      continue;
    }
    parts_[p]->step(sensors, scratch_);
    for (std::size_t e = 0; e < drives.size() && e < scratch_.size(); ++e)
      drives[e] += scratch_[e];
  }
}

void ControllerSum::reset() {
  for (auto& part : parts_)
    part->reset();
}

std::span<const double> ControllerSum::signals() const {
  return parts_.empty() ? std::span<const double>{} : parts_.front()->signals();
}

}  // namespace cambrian
