#include "parallel/worker.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace cambrian {
namespace {

WorkerSettings synthetic() {
  WorkerSettings settings;
  settings.task.kind = TaskKind::synthetic;
  settings.task.synthetic_cost_us = 100;
  return settings;
}

EvalRequest requestFor(std::uint64_t id) {
  return EvalRequest{id, 3, serializeGenome(randomGenome(GenomeLimits{}, 1, 0, id))};
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

}  // namespace
}  // namespace cambrian
