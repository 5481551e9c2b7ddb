#include "cambrian/outcome.hpp"

#include <limits>

namespace cambrian {

const char* statusName(EvalStatus status) {
  switch (status) {
    case EvalStatus::ok:
      return "ok";
    case EvalStatus::invalid_body:
      return "invalid_body";
    case EvalStatus::self_penetration:
      return "self_penetration";
    case EvalStatus::exploded:
      return "exploded";
    case EvalStatus::non_finite:
      return "non_finite";
    case EvalStatus::unstable:
      return "unstable";
    case EvalStatus::timeout:
      return "timeout";
    case EvalStatus::failed:
      return "failed";
  }
  return "unknown";
}

double Outcome::measure(const std::string& name) const {
  for (const Measure& m : measures) {
    if (m.name == name)
      return m.value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace cambrian
