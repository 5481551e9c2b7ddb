// cambrian: outcome names, lookups and the one byte form of an outcome.
#include "cambrian/outcome.hpp"

#include "core/outcome_bytes.hpp"

#include <limits>
#include <string>

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
    case EvalStatus::joint_error:
      return "joint_error";
    case EvalStatus::self_contact:
      return "self_contact";
    case EvalStatus::too_tall:
      return "too_tall";
    case EvalStatus::dismembered:
      return "dismembered";
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

void writeOutcome(ByteWriter& w, const Outcome& o) {
  w.u64(static_cast<std::uint64_t>(o.status));
  w.f64(o.fitness);
  w.u64(o.steps);
  w.f64(o.wall_seconds);
  w.i64(o.parts);
  w.i64(o.joints);
  w.i64(o.neurons);
  w.text(o.message);
  w.u64(o.measures.size());
  for (const Measure& m : o.measures) {
    w.text(m.name);
    w.f64(m.value);
  }
}

Outcome readOutcome(ByteReader& r) {
  Outcome o;
  r.context("status");
  std::uint64_t status = r.u64();
  if (status >= static_cast<std::uint64_t>(kEvalStatusKinds))
    r.fail("status = " + std::to_string(status) + " is unknown");
  o.status = static_cast<EvalStatus>(status);
  r.context("fitness");
  o.fitness = r.f64();
  r.context("steps");
  o.steps = r.u64();
  r.context("wall_seconds");
  o.wall_seconds = r.f64();
  // a body count is an int: a larger one would not be written back to the same bytes
  auto bodyCount = [&r](const char* field) {
    r.context(field);
    std::int64_t count = r.i64();
    if (count < std::numeric_limits<int>::min() || count > std::numeric_limits<int>::max())
      r.fail(std::string(field) + " = " + std::to_string(count) + " is out of range");
    return static_cast<int>(count);
  };
  o.parts = bodyCount("parts");
  o.joints = bodyCount("joints");
  o.neurons = bodyCount("neurons");
  r.context("message");
  o.message = r.text();
  r.context("measures");
  std::uint64_t measures = r.u64();
  // each measure needs at least a length word and a value
  if (measures > r.remaining() / 16)
    r.fail("measures = " + std::to_string(measures) + " is more than the bytes hold");
  for (std::uint64_t i = 0; i < measures; ++i) {
    r.context("measure " + std::to_string(i));
    Measure m;
    m.name = r.text();
    m.value = r.f64();
    o.measures.push_back(std::move(m));
  }
  return o;
}

}  // namespace cambrian
