#include "parallel/worker.hpp"

#include "cambrian/error.hpp"

#include "encodings/directed_graph/encoding.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <tuple>
#include <utility>

namespace cambrian {
namespace {

WorkerSettings synthetic() {
  WorkerSettings settings;
  settings.creature.set("task.name", "synthetic");
  settings.creature.set("task.synthetic_cost_us", "100");
  return settings;
}

EvalRequest requestFor(std::uint64_t id) {
  return EvalRequest{id, 3,
                     graph::serializeGenome(graph::randomGenome(graph::GenomeLimits{}, 1, 0, id))};
}

TEST(Worker, EvaluatesARequest) {
  std::ostringstream log;
  EvalResult result = evaluateRequest(requestFor(4), synthetic(), 2, log);
  EXPECT_EQ(result.id, 4u);
  EXPECT_EQ(result.outcome.status, EvalStatus::ok);
  EXPECT_GT(result.outcome.fitness, 0);
  EXPECT_EQ(log.str(), "");
}

TEST(Worker, AnExceptionBecomesAFailedOutcomeAndALogLine) {
  WorkerSettings settings = synthetic();
  settings.fail_every = 3;
  std::ostringstream log;
  EvalResult result = evaluateRequest(requestFor(6), settings, 2, log);
  EXPECT_EQ(result.id, 6u);
  EXPECT_EQ(result.outcome.status, EvalStatus::failed);
  EXPECT_EQ(result.outcome.fitness, kWorstFitness);
  EXPECT_NE(result.outcome.message.find("injected"), std::string::npos);
  EXPECT_NE(log.str().find("rank 2: creature 6 failed"), std::string::npos);
}

TEST(Worker, UnreadableGenomeBytesBecomeAFailedOutcome) {
  std::ostringstream log;
  EvalResult result = evaluateRequest(EvalRequest{9, 0, {1, 2, 3}}, synthetic(), 1, log);
  EXPECT_EQ(result.outcome.status, EvalStatus::failed);
  EXPECT_NE(log.str().find("creature 9"), std::string::npos);
}

// a request as the worker receives it from rank 0
Message messageFor(const EvalRequest& request) {
  return Message{0, Tag::request, encodeRequest(request)};
}

// the exit code and message of what `serve` throws (ExitCode::ok when it throws nothing)
template <typename Serve>
std::pair<ExitCode, std::string> thrownBy(Serve serve) {
  try {
    serve();
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  return {ExitCode::ok, ""};
}

TEST(Worker, ServesAWellFormedRequest) {
  std::ostringstream log;
  EvalResult result = serveRequest(messageFor(requestFor(4)), synthetic(), 1, log);
  EXPECT_EQ(result.id, 4u);
  EXPECT_EQ(result.outcome.status, EvalStatus::ok);
}

TEST(Worker, AMalformedMessageIsAWorkerFailure) {
  std::ostringstream log;
  // bytes that are no request, and a tag that is no request
  auto [code, message] = thrownBy([&] {
    serveRequest(Message{0, Tag::request, {1, 2, 3}}, synthetic(), 1, log);
  });
  EXPECT_EQ(code, ExitCode::worker_failure);
  std::tie(code, message) = thrownBy([&] {
    serveRequest(Message{0, Tag::result, encodeRequest(requestFor(4))}, synthetic(), 1, log);
  });
  EXPECT_EQ(code, ExitCode::worker_failure);
  EXPECT_NE(message.find("unexpected message tag 2"), std::string::npos) << message;
}

TEST(Worker, TestAbortAtIsUnrecoverableForThatCreatureOnly) {
  WorkerSettings settings = synthetic();
  settings.test_abort_at = 7;
  settings.fail_every = 1;  // even where every evaluation fails and is caught
  std::ostringstream log;
  // other creatures are evaluated (here: fail, caught), creature 7 ends the rank
  EXPECT_EQ(serveRequest(messageFor(requestFor(6)), settings, 3, log).outcome.status,
            EvalStatus::failed);
  auto [code, message] =
      thrownBy([&] { serveRequest(messageFor(requestFor(7)), settings, 3, log); });
  EXPECT_EQ(code, ExitCode::worker_failure);
  EXPECT_NE(message.find("creature 7"), std::string::npos) << message;
  EXPECT_NE(message.find("run.test_worker_abort_at"), std::string::npos) << message;
  // 0 means never
  settings.test_abort_at = 0;
  settings.fail_every = 0;
  EXPECT_EQ(serveRequest(messageFor(requestFor(7)), settings, 3, log).outcome.status,
            EvalStatus::ok);
}

}  // namespace
}  // namespace cambrian
