#include "parallel/messages.hpp"

#include "cambrian/error.hpp"

#include <cstring>

namespace cambrian {

namespace {

// appends little-endian words and strings
class Writer {
 public:
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
      bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u64(bits);
  }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void blob(const void* data, std::size_t size) {
    u64(size);
    const auto* p = static_cast<const std::uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
};

// reads what Writer wrote; throws InputError naming the field when bytes run out
class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, const char* what) : bytes_(bytes), what_(what) {}
  std::uint64_t u64(const char* field) {
    need(8, field);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
      v |= std::uint64_t(bytes_[at_ + i]) << (8 * i);
    at_ += 8;
    return v;
  }
  double f64(const char* field) {
    std::uint64_t bits = u64(field);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  std::int64_t i64(const char* field) { return static_cast<std::int64_t>(u64(field)); }
  std::vector<std::uint8_t> bytes(const char* field) {
    std::uint64_t size = u64(field);
    need(size, field);
    std::vector<std::uint8_t> out(bytes_.begin() + static_cast<std::ptrdiff_t>(at_),
                                  bytes_.begin() + static_cast<std::ptrdiff_t>(at_ + size));
    at_ += size;
    return out;
  }
  std::string text(const char* field) {
    std::vector<std::uint8_t> raw = bytes(field);
    return std::string(raw.begin(), raw.end());
  }
  void finish() {
    if (at_ != bytes_.size()) {
      throw InputError(std::string(what_) + ": " + std::to_string(bytes_.size() - at_) +
                       " trailing bytes");
    }
  }

 private:
  void need(std::uint64_t size, const char* field) {
    if (size > bytes_.size() - at_) {
      throw InputError(std::string(what_) + ": truncated at field '" + field + "' (offset " +
                       std::to_string(at_) + " of " + std::to_string(bytes_.size()) + ")");
    }
  }
  const std::vector<std::uint8_t>& bytes_;
  const char* what_;
  std::size_t at_ = 0;
};

}  // namespace

std::vector<std::uint8_t> encodeRequest(const EvalRequest& request) {
  Writer w;
  w.u64(request.id);
  w.u64(request.eval_seed);
  w.blob(request.genome.data(), request.genome.size());
  return w.take();
}

EvalRequest decodeRequest(const std::vector<std::uint8_t>& bytes) {
  Reader r(bytes, "evaluation request");
  EvalRequest request;
  request.id = r.u64("id");
  request.eval_seed = r.u64("eval_seed");
  request.genome = r.bytes("genome");
  r.finish();
  return request;
}

std::vector<std::uint8_t> encodeResult(const EvalResult& result) {
  // every field of the outcome, doubles as their bits
  const Outcome& o = result.outcome;
  Writer w;
  w.u64(result.id);
  w.u64(static_cast<std::uint64_t>(o.status));
  w.f64(o.fitness);
  w.u64(o.steps);
  w.f64(o.wall_seconds);
  w.i64(o.parts);
  w.i64(o.joints);
  w.i64(o.neurons);
  w.blob(o.message.data(), o.message.size());
  w.u64(o.measures.size());
  for (const Measure& m : o.measures) {
    w.blob(m.name.data(), m.name.size());
    w.f64(m.value);
  }
  return w.take();
}

EvalResult decodeResult(const std::vector<std::uint8_t>& bytes) {
  Reader r(bytes, "evaluation result");
  EvalResult result;
  Outcome& o = result.outcome;
  result.id = r.u64("id");
  std::uint64_t status = r.u64("status");
  if (status > static_cast<std::uint64_t>(EvalStatus::failed)) {
    throw InputError("evaluation result: status = " + std::to_string(status) + " is unknown");
  }
  o.status = static_cast<EvalStatus>(status);
  o.fitness = r.f64("fitness");
  o.steps = r.u64("steps");
  o.wall_seconds = r.f64("wall_seconds");
  o.parts = static_cast<int>(r.i64("parts"));
  o.joints = static_cast<int>(r.i64("joints"));
  o.neurons = static_cast<int>(r.i64("neurons"));
  o.message = r.text("message");
  std::uint64_t measures = r.u64("measures");
  if (measures > bytes.size()) {
    throw InputError("evaluation result: measures = " + std::to_string(measures) +
                     " is more than the message holds");
  }
  for (std::uint64_t i = 0; i < measures; ++i) {
    Measure m;
    m.name = r.text("measure name");
    m.value = r.f64("measure value");
    o.measures.push_back(std::move(m));
  }
  r.finish();
  return result;
}

}  // namespace cambrian
