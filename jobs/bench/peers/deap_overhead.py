#!/usr/bin/python3
"""DEAP's generational loop (eaSimple) on the synthetic cost, for jobs/bench/dispatch_overhead.sh.

Every evaluation spends --cost-us microseconds (a steady-clock spin or a sleep) and returns a
cheap fitness. Maps: a multiprocessing.Pool of --workers processes, or mpi4py.futures (run under
`mpirun -np WORKERS+1 /usr/bin/python3 -m mpi4py.futures deap_overhead.py --map mpi ...`).
Prints one line: evaluations, wall seconds, workers.
"""
import argparse
import random
import time

from deap import algorithms, base, creator, tools

parser = argparse.ArgumentParser()
parser.add_argument("--cost-us", type=float, default=1000)
parser.add_argument("--work", choices=["spin", "sleep"], default="spin")
parser.add_argument("--population", type=int, default=300)
parser.add_argument("--generations", type=int, default=10)
parser.add_argument("--workers", type=int, default=2)
parser.add_argument("--map", choices=["pool", "mpi"], default="pool")
args, _ = parser.parse_known_args()  # mpi4py.futures workers see the script path again

creator.create("FitnessMax", base.Fitness, weights=(1.0,))
creator.create("Individual", list, fitness=creator.FitnessMax)


def evaluate(individual, cost=args.cost_us * 1e-6, work=args.work):
    # the synthetic cost, then a cheap fitness
    end = time.perf_counter() + cost
    if work == "sleep":
        time.sleep(cost)
    else:
        while time.perf_counter() < end:
            pass
    return (sum(individual),)


toolbox = base.Toolbox()
toolbox.register("attribute", random.random)
toolbox.register("individual", tools.initRepeat, creator.Individual, toolbox.attribute, 20)
toolbox.register("population", tools.initRepeat, list, toolbox.individual)
toolbox.register("evaluate", evaluate)
toolbox.register("mate", tools.cxTwoPoint)
toolbox.register("mutate", tools.mutGaussian, mu=0, sigma=0.1, indpb=0.1)
toolbox.register("select", tools.selTournament, tournsize=3)

if __name__ == "__main__":
    random.seed(1)
    if args.map == "mpi":
        from mpi4py.futures import MPIPoolExecutor

        executor = MPIPoolExecutor()
        toolbox.register("map", executor.map)
    else:
        import multiprocessing

        pool = multiprocessing.Pool(args.workers)
        toolbox.register("map", pool.map)
    population = toolbox.population(n=args.population)
    start = time.perf_counter()
    _, log = algorithms.eaSimple(population, toolbox, cxpb=0.5, mutpb=0.2,
                                 ngen=args.generations, verbose=False)
    wall = time.perf_counter() - start
    evaluations = sum(record["nevals"] for record in log)
    print(f"evaluations {evaluations} wall {wall:.6f} workers {args.workers}")
    if args.map == "mpi":
        executor.shutdown()
    else:
        pool.close()
