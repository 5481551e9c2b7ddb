#include "cambrian/genome.hpp"

namespace cambrian {

int neuronArity(NeuronFunction function) {
  switch (function) {
    case NeuronFunction::constant:
      return 0;
    case NeuronFunction::sign_of:
    case NeuronFunction::abs:
    case NeuronFunction::sin:
    case NeuronFunction::cos:
    case NeuronFunction::atan:
    case NeuronFunction::log:
    case NeuronFunction::expt:
    case NeuronFunction::sigmoid:
    case NeuronFunction::integrate:
    case NeuronFunction::differentiate:
    case NeuronFunction::smooth:
    case NeuronFunction::memory:
    case NeuronFunction::oscillate_wave:
    case NeuronFunction::oscillate_saw:
      return 1;
    case NeuronFunction::sum:
    case NeuronFunction::product:
    case NeuronFunction::divide:
    case NeuronFunction::sum_threshold:
    case NeuronFunction::greater_than:
    case NeuronFunction::min:
    case NeuronFunction::max:
      return 2;
    case NeuronFunction::if_positive:
    case NeuronFunction::interpolate:
      return 3;
    case NeuronFunction::count_:
      break;
  }
  return 0;
}

const char* neuronFunctionName(NeuronFunction function) {
  static constexpr const char* kNames[] = {"constant",
                                           "sum",
                                           "product",
                                           "divide",
                                           "sum_threshold",
                                           "greater_than",
                                           "sign_of",
                                           "min",
                                           "max",
                                           "abs",
                                           "if",
                                           "interpolate",
                                           "sin",
                                           "cos",
                                           "atan",
                                           "log",
                                           "expt",
                                           "sigmoid",
                                           "integrate",
                                           "differentiate",
                                           "smooth",
                                           "memory",
                                           "oscillate_wave",
                                           "oscillate_saw"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) ==
                static_cast<std::size_t>(NeuronFunction::count_));
  auto i = static_cast<std::size_t>(function);
  return i < static_cast<std::size_t>(NeuronFunction::count_) ? kNames[i] : "unknown";
}

}  // namespace cambrian
