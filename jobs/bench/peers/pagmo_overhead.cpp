// pagmo2's thread batch evaluator on the synthetic cost, for jobs/bench/dispatch_overhead.sh:
// generations of a population of decision vectors evaluated by pagmo::thread_bfe (one thread per
// core), each evaluation a steady-clock spin or a sleep of the cost, with a cheap fitness.
// usage: pagmo_overhead COST_US spin|sleep POPULATION GENERATIONS
// prints: evaluations E wall W workers T
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <pagmo/batch_evaluators/thread_bfe.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// the synthetic cost, then the sum of the decision vector
struct SyntheticProblem {
  double cost_us = 1000;
  bool sleep = false;
  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double, std::micro>(cost_us));
    if (sleep)
      std::this_thread::sleep_until(end);
    else
      while (Clock::now() < end) {
      }
    double sum = 0;
    for (double v : x)
      sum += v;
    return {-sum};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(20, 0.0), pagmo::vector_double(20, 1.0)};
  }
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::constant; }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: pagmo_overhead COST_US spin|sleep POPULATION GENERATIONS\n");
    return 2;
  }
  SyntheticProblem synthetic;
  synthetic.cost_us = std::atof(argv[1]);
  synthetic.sleep = std::string(argv[2]) == "sleep";
  const int population = std::atoi(argv[3]), generations = std::atoi(argv[4]);
  pagmo::problem problem{synthetic};
  pagmo::thread_bfe evaluator;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(0, 1);

  // each generation: a new batch of vectors (population x 20, flattened) evaluated at once
  auto start = Clock::now();
  long evaluations = 0;
  for (int g = 0; g < generations; ++g) {
    pagmo::vector_double batch(static_cast<std::size_t>(population) * 20);
    for (double& v : batch)
      v = uniform(rng);
    pagmo::vector_double fitnesses = evaluator(problem, batch);
    evaluations += static_cast<long>(fitnesses.size());
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("evaluations %ld wall %.6f workers %u\n", evaluations, wall,
              std::thread::hardware_concurrency());
  return 0;
}
