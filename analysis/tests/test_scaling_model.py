"""Tests of analysis/scaling_model.py: the discrete-event model against cases with known
answers (zero overhead, pure latency, largest first, barrier), the calibration from the
fixture history, and the command line with a measured sweep."""

import numpy as np
import pytest

import scaling_model as sm

PNG = b"\x89PNG\r\n\x1a\n"


# with no overhead and P divisible by W, the speedup is exactly W
@pytest.mark.parametrize("workers", [1, 2, 4, 5, 10, 20, 100])
def test_zero_overhead_gives_ideal_speedup(workers):
    calibration = sm.Calibration(cost_mean=0.01, serial=0.0, latency=0.0, evaluated_share=1.0)
    rows = sm.project(calibration, [100], [1, workers], samples=2)
    assert rows[-1]["speedup"] == pytest.approx(workers, rel=1e-12)
    assert rows[-1]["efficiency"] == pytest.approx(1.0)


# hand-outs are serial on rank 0: free evaluations take E * L whatever W is
def test_latency_alone_is_the_dispatch_bound():
    for workers in (1, 3, 64):
        assert sm.simulate_span(np.zeros(50), workers, 0.001) == pytest.approx(0.05)
    assert sm.limit_of(np.zeros(50), 8, 0.001, 0.0) == "dispatch"


# largest first: the long evaluation goes first and the rest fill the other worker
def test_largest_first_schedule():
    assert sm.simulate_span([1, 3, 1, 1], 2, 0.0, in_flight=1) == 3.0
    assert sm.simulate_span([2, 2, 2, 2, 2], 2, 0.0) == 6.0  # 3 on one worker, 2 on the other
    # in the tail nothing is queued, so no creature waits behind the long one
    assert sm.simulate_span([1, 3, 1, 1], 2, 0.0, in_flight=2) == 3.0
    assert sm.simulate_span([], 4, 0.1) == 0.0


# a queued evaluation hides the hand-out: one in flight pays L per evaluation; two pay it for
# the first and for the last three, handed one at a time in the tail (< 4 per worker left)
def test_queued_evaluation_hides_the_hand_out():
    costs = np.ones(10)
    assert sm.simulate_span(costs, 1, 0.1, in_flight=1) == pytest.approx(11.0)
    assert sm.simulate_span(costs, 1, 0.1, in_flight=2) == pytest.approx(10.4)
    # unless the hand-out takes longer than the evaluation: then rank 0 is the bound again
    assert sm.simulate_span(np.full(10, 0.05), 1, 0.1, in_flight=2) >= 10 * 0.1 + 0.05
    # two workers: 8 evaluations each, L hidden until the tail
    assert sm.simulate_span(np.ones(16), 2, 0.1, in_flight=1) == pytest.approx(8.9)
    assert sm.simulate_span(np.ones(16), 2, 0.1, in_flight=2) == pytest.approx(8.6)


# the per-evaluation overhead is paid by the worker, in parallel, and never hidden
def test_overhead_is_paid_per_evaluation_by_the_worker():
    assert sm.simulate_span(np.ones(10), 1, 0.0, overhead=0.5) == pytest.approx(15.0)
    assert sm.simulate_span(np.ones(10), 2, 0.0, overhead=0.5) == pytest.approx(7.5)
    assert sm.limit_of(np.ones(10), 2, 0.0, 0.0, overhead=0.5) == "work"


# more workers than evaluations: the slowest creature bounds the generation
def test_barrier_and_serial_bounds():
    costs = np.array([5.0, 1.0, 1.0])
    assert sm.simulate_span(costs, 8, 0.0) == 5.0
    assert sm.limit_of(costs, 8, 0.0, 0.0) == "barrier"
    assert sm.generation_time(costs, 8, 0.0, 2.5) == 7.5
    assert sm.limit_of(costs, 8, 0.0, 10.0) == "serial"
    assert sm.limit_of(np.ones(100), 2, 0.0, 0.0) == "work"
    assert sm.limit_of(np.ones(80), 64, 0.0, 0.0) == "barrier"  # 2 evaluations on some workers, 1 on others


# with overhead, efficiency falls with W and speedup never exceeds W
def test_projection_with_overhead_is_sub_linear():
    calibration = sm.Calibration(cost_mean=0.01, cost_cv=0.5, serial=0.002, latency=1e-4, evaluated_share=0.8)
    rows = sm.project(calibration, [300], [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024], samples=3)
    efficiency = [r["efficiency"] for r in rows]
    assert all(r["speedup"] <= r["workers"] + 1e-9 for r in rows)
    assert efficiency[-1] < 0.5 < efficiency[1]
    assert rows[-1]["limit"] in ("dispatch", "barrier", "serial") and rows[1]["limit"] == "work"


# calibration from the fixture history gives sane figures
def test_calibration_from_history(run_history):
    calibration = sm.calibrate(run_history)
    assert len(calibration.costs) > 0 and np.all(calibration.costs >= 0)
    assert calibration.latency >= 0 and calibration.overhead >= 0 and calibration.in_flight is None
    assert calibration.serial >= 0 and calibration.latency >= 0
    assert 0 < calibration.evaluated_share <= 1
    draws = calibration.draw(100, np.random.default_rng(1))
    assert set(draws) <= set(calibration.costs)


# the command line compares the model with the fixture sweep
def test_command_line_with_sweep(sweep_dir, run_script, tmp_path):
    result = run_script("scaling_model", "--sweep", sweep_dir, "--max-workers", 64, "--populations", 100, 300,
                        "--samples", 2, "--output", tmp_path / "m.png", "--table", tmp_path / "m.tsv")
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "m.png").read_bytes()[:8] == PNG
    assert "model vs measured" in result.stdout
    compared = result.stdout.split("model vs measured")[1].splitlines()[2:4]
    assert [line.split("\t")[0] for line in compared] == ["1", "2"]
    assert len((tmp_path / "m.tsv").read_text().splitlines()) == 1 + 2 * 7


def test_parameters_and_errors(sweep_dir, tmp_path, capsys):
    assert sm.main(["--cost-mean", "0.01", "--max-workers", "4", "--output", str(tmp_path / "p.png")]) == 0
    assert "efficiency below 50 %" in capsys.readouterr().out
    with pytest.raises(SystemExit) as exit_:
        sm.main([])  # nothing to calibrate from
    assert exit_.value.code == 2
    with pytest.raises(SystemExit) as exit_:
        sm.main(["--cost-mean", "-1"])
    assert exit_.value.code == 2
    assert sm.main(["--history", str(tmp_path / "nope.h5")]) == 4
    assert "nope.h5" in capsys.readouterr().err


# the comparison of a weak sweep uses scaled speedups: p * T(1) / T(p)
def test_compare_weak_sweep_uses_scaled_speedup():
    calibration = sm.Calibration(cost_mean=0.01, serial=0.0, latency=0.0, evaluated_share=1.0)
    runs = [{"path": f"w{p}", "workers": p, "population": 10 * p, "generations": 3, "time": 0.1,
             "times": np.array([0.1]), "rank0_share": 0.0, "evaluations": 10.0 * p, "rank0_serial": 0.0}
            for p in (1, 2, 4)]
    out = sm.compare(calibration, runs, samples=1, mode="weak")
    assert [o["model_speedup"] for o in out] == pytest.approx([1.0, 2.0, 4.0])
    assert [o["measured_speedup"] for o in out] == pytest.approx([1.0, 2.0, 4.0])
    assert all(abs(o["error"]) < 1e-9 for o in out)


# a run under mpirun records rank 0's dispatch time: L is measured, positive and far below a
# 10 ms evaluation; the overhead is what the model cannot otherwise explain, never negative
def test_calibration_from_a_measured_mpi_run(sweep_dir):
    import scaling

    runs = scaling.load_sweep([sweep_dir], 1)
    calibration = sm.calibrate(min(runs, key=lambda r: r["workers"])["path"])
    assert 0.0 < calibration.latency < 0.5 * float(np.mean(calibration.costs))
    assert calibration.overhead >= 0.0


def test_the_depth_is_the_schedulers():
    # DispatchPace::held: 4 ms of work queued, at least 2, at most 64, a share of what is left
    assert sm.held(0.010, 1000, 2) == 2
    assert sm.held(0.010, 7, 2) == 1  # the tail: one at a time
    assert sm.held(0.001, 1000, 2) == 5
    assert sm.held(0.0001, 10000, 2) == 41
    assert sm.held(0.0001, 40, 2) == 6  # 1 + 40 / (4 x 2)
    assert sm.held(0.0001, 3, 2) == 2  # short creatures keep two to the end
    assert sm.held(0.0, 1000, 2) == 2  # no mean yet
    assert sm.held(0.0001, 10000, 2, in_flight=3) == 3  # fixed


def test_deep_queues_hide_the_hand_outs_of_short_creatures():
    # 100 us creatures, 30 us per hand-out, 2 workers: rank 0 keeps up (60 us of hand-outs per
    # 100 us of work), and a worker never waits for its next one behind the other's hand-out
    costs = np.full(400, 1e-4)
    span = sm.simulate_span(costs, 2, 3e-5)
    work = costs.sum() / 2
    assert span == pytest.approx(work, rel=0.02)
    # held two at a time in the tail too: no round trip per creature at the end
    assert sm.simulate_span(costs, 2, 3e-5) <= sm.simulate_span(costs, 2, 3e-5, in_flight=2)


# islands whose generations all last the same never wait for each other, whatever the topology
@pytest.mark.parametrize("topology", ["ring", "full", "random"])
def test_islands_of_equal_generations_do_not_wait(topology):
    assert sm.archipelago_time([2.0], 8, 1, topology) == pytest.approx(2.0)
    assert sm.archipelago_time([2.0], 8, 5, topology, generations=37) == pytest.approx(2.0)


# uneven generations: the archipelago is slower than an island alone, more so the more often and
# the more widely it trades, and never slower than lock-step (each generation the slowest island's)
def test_migration_waits_grow_with_coupling():
    times = [1.0, 1.0, 1.0, 3.0]
    mean = np.mean(times)
    ring_rare = sm.archipelago_time(times, 16, 10, "ring", rng=np.random.default_rng(3))
    ring_often = sm.archipelago_time(times, 16, 1, "ring", rng=np.random.default_rng(3))
    full_often = sm.archipelago_time(times, 16, 1, "full", rng=np.random.default_rng(3))
    assert mean < ring_rare <= ring_often <= full_often <= 3.0
    # the sources are as evolution/migration.cpp names them
    assert sm.migration_sources(0, 4, 9, "ring", None) == [3]
    assert sm.migration_sources(2, 4, 9, "full", None) == [0, 1, 3]
    drawn = sm.migration_sources(1, 4, 9, "random", np.random.default_rng(1))
    assert drawn and 1 not in drawn


# islands of w workers: from 2w workers on the archipelago's throughput is K islands' (equal
# costs: exactly K times one island's speedup), below that one population
def test_projection_with_islands():
    calibration = sm.Calibration(cost_mean=0.01, serial=0.001, latency=0.0, evaluated_share=1.0)
    rows = sm.project(calibration, [64], [1, 4, 8, 16, 64], samples=2, island_workers=8)
    by_workers = {r["workers"]: r for r in rows}
    assert [by_workers[w]["islands"] for w in (1, 4, 8, 16, 64)] == [1, 1, 1, 2, 8]
    assert by_workers[16]["speedup"] == pytest.approx(2 * by_workers[8]["speedup"])
    assert by_workers[64]["speedup"] == pytest.approx(8 * by_workers[8]["speedup"])
    assert by_workers[64]["efficiency"] == pytest.approx(by_workers[8]["efficiency"])
    # one population of 64 on 64 workers is barrier-bound; 8 islands of 8 workers are not
    alone = sm.project(calibration, [64], [1, 64], samples=2)
    assert by_workers[64]["efficiency"] > alone[-1]["efficiency"]


# a steady state on one worker with nothing else to pay: a generation is P costs, and the
# serial time of each generation's end is added in full (nothing queued to cover it)
def test_steady_state_on_one_worker():
    costs = np.full(5 * 40, 0.01)
    assert sm.steady_time(costs, 1, 40, 0.0, 0.0) == pytest.approx(0.4)
    # a worker holds two (the one it evaluates and the next): rank 0's serial time is hidden
    # up to one cost
    # (but for the last generation's, which nothing follows)
    assert sm.steady_time(costs, 1, 40, 0.0, 0.005) == pytest.approx(0.4 + 0.005 / 4)
    # longer than the queued cost: the rest of it idles the worker at every generation's end
    assert sm.steady_time(costs, 1, 40, 0.0, 0.03) == pytest.approx(0.4 + (3 * 0.02 + 0.03) / 4)
    with pytest.raises(ValueError):
        sm.steady_time(costs[:50], 1, 40, 0.0, 0.0)


# no barrier: with spread costs the steady state keeps the workers busier than generations do,
# and at most P / 2 are out: more workers than that add nothing
def test_steady_state_has_no_barrier_and_caps_what_is_out():
    rng = np.random.default_rng(3)
    costs = rng.lognormal(np.log(0.01), 1.0, 300 * 20)
    steady = sm.steady_time(costs, 60, 300, 0.0, 0.0)
    generational = np.mean([sm.generation_time(costs[i * 300:(i + 1) * 300], 60, 0.0, 0.0)
                            for i in range(1, 20)])
    ideal = 300 * np.mean(costs) / 60
    assert ideal <= steady < 0.9 * generational
    capped = sm.steady_time(costs, 300, 300, 0.0, 0.0)
    assert capped == pytest.approx(sm.steady_time(costs, 150, 300, 0.0, 0.0), rel=0.05)
    assert capped >= 0.95 * 300 * np.mean(costs) / 150


# islands of steady states: K islands of w workers give K times one island's throughput (equal
# costs), each island's generation is steady_time's, and a population spread over more workers
# than the half it keeps out is "cap"-bound
def test_projection_with_islands_of_steady_states():
    calibration = sm.Calibration(cost_mean=0.01, serial=0.001, latency=0.0, evaluated_share=0.8)
    rows = sm.project(calibration, [64], [1, 8, 64], samples=2, island_workers=8, steady=True)
    by_workers = {r["workers"]: r for r in rows}
    assert [by_workers[w]["islands"] for w in (1, 8, 64)] == [1, 1, 8]
    # every result is evaluated: no elites in a steady state
    assert all(r["evaluations"] == 64 for r in rows)
    assert by_workers[64]["speedup"] == pytest.approx(8 * by_workers[8]["speedup"])
    assert by_workers[8]["limit"] == "work"
    capped = sm.project(calibration, [64], [1, 64], samples=2, steady=True)
    assert capped[-1]["limit"] == "cap" and capped[-1]["efficiency"] < 0.6
    # the generational islands of the same layout wait for their slowest creature; these do not
    generational = sm.project(calibration, [64], [1, 64], samples=2, island_workers=8)
    assert by_workers[64]["efficiency"] >= generational[-1]["efficiency"] - 1e-9
