#!/usr/bin/env bash
# Golden results: digests of whole evolutions and outcomes of single creatures, compared bit for
# bit with the values checked in beside this script (expected.txt). A change that moves one of
# them must say so and why, and update expected.txt in the same commit (`--regenerate` prints
# the new lines).
# usage: golden_check.sh MODE CAMBRIAN MPIEXEC NPFLAG NP WORKDIR [--regenerate]
#   synthetic: a synthetic-task evolution at NP ranks (1: in process)
#   walk:      a walking evolution at NP ranks, in the Featherstone world and in the rigid-body
#              world
#   variants:  at NP ranks, evolutions through the other code paths: jump, explicit torques,
#              self-collision, Chaumont's normalisation and rest rule, tournament / rank / sus
#              selection, unconnected nodes collected, seed genomes, Sims' swimming in water and
#              following a light, Chaumont et al.'s walk (hinges only, their neuron set), the
#              springy Pyramids, Walking with Dinosaurs (its DNA, relaxation and breeding; with
#              dismemberment in the rigid-body world; wwd_short_batches: short batches, and
#              dismemberment in the Featherstone world)
#   simulate:  `cambrian simulate` on the hand-written creatures and random seeds (walk, jump,
#              swim, follow_light, synthetic): status, fitness, every measure and the step count
#   resume_v1: a run checkpointed by the cambrian of before the plug-in renovation
#              (tests/store/data/v1_run: history.h5 and a version-1 checkpoint.h5 after 3 of 5
#              generations) resumed at NP ranks: the digest of the straight run of that cambrian.
#              Its physics predates friction anchors, contact slop, the energy watch, the
#              solved middle axis of spherical joints and the joint speed clamp's 1,000 rad/s:
#              with the
#              defaults of its day but not those, the run is refused (exit 6, naming the values
#              that continue it); with them it continues bit for bit
# Every name's line in expected.txt is "NAME VALUE"; the same NAME must give the same VALUE at
# every rank count and in every build type (Debug and Release).
set -euo pipefail
mode=$1 cambrian=$2 mpiexec=$3 npflag=$4 np=$5 work=$6 regenerate=${7:-}
here=$(cd "$(dirname "$0")" && pwd)
source_dir=$(cd "$here/../.." && pwd)
expected=$here/expected.txt
limit=300
rm -rf "$work" && mkdir -p "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

fail() {
  echo "FAIL: golden $mode at $np ranks: $*" >&2
  exit 1
}

# compares NAME's VALUE with expected.txt (or prints the line with --regenerate)
failures=0
check() {
  local name=$1 value=$2
  if [ "$regenerate" = "--regenerate" ]; then
    echo "$name $value"
    return
  fi
  local want
  want=$(awk -v n="$name" '$1 == n { $1 = ""; sub(/^ /, ""); print; exit }' "$expected")
  if [ -z "$want" ]; then
    echo "golden $name: no expected value in $expected (got '$value')" >&2
    failures=$((failures + 1))
  elif [ "$want" != "$value" ]; then
    echo "golden $name: expected '$want', got '$value'" >&2
    failures=$((failures + 1))
  else
    echo "golden $name: $value"
  fi
}

# `cambrian evolve ARGS` at NP ranks as job NAME; its digest checked against expected.txt
evolve() {
  local name=$1
  shift
  local launch=()
  if [ "$np" -gt 1 ]; then
    launch=("$mpiexec" "$npflag" "$np" --oversubscribe)
  fi
  set +e
  timeout -k 10 "$limit" "${launch[@]}" "$cambrian" evolve --quiet --fresh \
    --out "$work/$name" "$@" > "$work/$name.out" 2> "$work/$name.err"
  local rc=$?
  set -e
  [ "$rc" -eq 0 ] || fail "$name: exit code $rc; stderr: $(head -n 5 "$work/$name.err")"
  local digest
  digest=$(awk '$1 == "digest" { print $2 }' "$work/$name.out")
  [ -n "$digest" ] || fail "$name: no digest line in $(head -n 3 "$work/$name.out")"
  check "$name" "$digest"
}

# `cambrian simulate ARGS` as NAME: status, fitness, measures and steps on one line
simulate() {
  local name=$1
  shift
  set +e
  "$cambrian" simulate "$@" > "$work/$name.out" 2> "$work/$name.err"
  local rc=$?
  set -e
  [ "$rc" -eq 0 ] || fail "$name: exit code $rc; stderr: $(head -n 5 "$work/$name.err")"
  local summary
  summary=$(awk '$1 == "creature" || $1 == "body" || $1 == "task" || $1 == "wall" { next }
                 $1 == "status" { printf "status=%s ", $2; next }
                 { printf "%s=%s ", $1, $2 }' "$work/$name.out")
  check "$name" "${summary% }"
}

creatures=$source_dir/jobs/creatures
case $mode in
  synthetic)
    evolve synthetic --task.name synthetic --task.synthetic_cost_us 100 \
      --task.synthetic_cost_per_gene_us 10 --task.synthetic_noise 0.3 \
      --evolution.population 24 --evolution.generations 6 --seed 11
    # a steady state: in process (one creature out at a time: deterministic), and at NP ranks
    # following that run's recorded order (docs/steady-state.md), which repeats it
    steady=(--task.name synthetic --task.synthetic_cost_us 100 --task.synthetic_cost_per_gene_us 10
      --task.synthetic_noise 0.3 --evolution.population 24 --evolution.generations 6 --seed 11
      --evolution.mode steady_state)
    np=1 evolve steady_synthetic "${steady[@]}"
    evolve steady_synthetic_followed "${steady[@]}" \
      --run.arrival_order "$work/steady_synthetic/history.h5"
    # islands of steady states trading every 2 generations: each island in process (2 ranks,
    # 2 islands), and at NP ranks (2 or more) following those islands' recorded orders
    islands=("${steady[@]}" --islands.count 2 --islands.interval 2)
    np=2 evolve steady_islands "${islands[@]}"
    if [ "$np" -gt 1 ]; then
      evolve steady_islands_followed "${islands[@]}" --run.arrival_order "$work/steady_islands"
    fi
    ;;
  walk)
    evolve walk --config "$source_dir/jobs/experiments/walk.ini" --evolution.population 16 \
      --evolution.generations 4 --task.evaluation_time 2 --seed 3
    evolve walk_rigid_bodies --config "$source_dir/jobs/experiments/walk.ini" \
      --physics.world rigid_bodies --evolution.population 16 --evolution.generations 4 \
      --task.evaluation_time 2 --seed 3
    ;;
  variants)
    common=(--evolution.population 12 --evolution.generations 3 --task.evaluation_time 1.5)
    evolve jump --task.name jump "${common[@]}" --seed 4
    evolve torque_self_collision --physics.actuation torque --physics.self_collision true \
      --evolution.selection tournament "${common[@]}" --seed 5
    evolve chaumont_rest --config "$source_dir/jobs/experiments/chaumont.ini" \
      --task.rest_check true --evolution.selection rank "${common[@]}" --seed 6
    evolve collected_sus --evolution.keep_unconnected false --evolution.selection sus \
      --task.normalisation volume "${common[@]}" --seed 7
    evolve seeded --evolution.seed_genomes "$creatures/walker4.genome $creatures/snake.genome" \
      --evolution.selection roulette "${common[@]}" --seed 8
    evolve synthetic_lognormal --task.name synthetic --task.synthetic_cost_us 50 \
      --task.synthetic_distribution lognormal --task.synthetic_cv 0.8 \
      --evolution.population 20 --evolution.generations 4 --seed 9
    evolve swim --config "$source_dir/jobs/experiments/sims/swim.ini" "${common[@]}" --seed 10
    evolve follow_light --config "$source_dir/jobs/experiments/sims/follow-light.ini" \
      "${common[@]}" --seed 11
    evolve chaumont_walk --config "$source_dir/jobs/experiments/chaumont/walk.ini" \
      "${common[@]}" --seed 12
    evolve catapult_distance --config "$source_dir/jobs/experiments/chaumont/catapult-distance.ini" \
      "${common[@]}" --seed 13
    evolve catapult_aim_flat --config "$source_dir/jobs/experiments/chaumont/catapult-aim.ini" \
      --genome.projectile_mutation true "${common[@]}" --seed 14
    evolve walk_hills --config "$source_dir/jobs/experiments/minemonics/walk-hills.ini" \
      "${common[@]}" --seed 15
    evolve juries_ranked --config "$source_dir/jobs/experiments/minemonics/juries.ini" \
      "${common[@]}" --seed 16
    evolve walk_chaotic --config "$source_dir/jobs/experiments/minemonics/walk-chaotic.ini" \
      "${common[@]}" --seed 17
    evolve epochs --task.name juries --evolution.epochs maximum_height@1 \
      --evolution.epochs average_velocity+ground_contact_ratio:0.5:lower "${common[@]}" --seed 18
    evolve springy_pyramids --config "$source_dir/jobs/experiments/springy/pyramids-parametric.ini" \
      --springy.organism "$creatures/springy/pyramid.organism" "${common[@]}" --seed 19
    evolve wwd_turtle --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" \
      --evolution.seed_genomes "$creatures/wwd/turtle.genome" "${common[@]}" --seed 20
    evolve wwd_dismemberment --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" \
      --evolution.seed_genomes "$creatures/wwd/pole.genome" --physics.world rigid_bodies \
      --physics.joint_breaking 1.05 --task.wwd_condition box_loving "${common[@]}" --seed 21
    evolve wwd_short_batches --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" \
      --evolution.seed_genomes "$creatures/wwd/pole.genome" --evolution.batch_generations 2 \
      --physics.joint_breaking 1.05 "${common[@]}" --seed 22
    ;;
  simulate)
    for creature in walker4 snake pole single_block; do
      simulate "simulate_${creature}_walk" --genome "$creatures/$creature.genome" --task walk \
        --task.evaluation_time 3
    done
    simulate simulate_walker4_jump --genome "$creatures/walker4.genome" --task jump \
      --task.evaluation_time 2
    simulate simulate_walker4_hills --genome "$creatures/walker4.genome" --task walk \
      --environment.name hills --environment.hill_height 1.5 --task.evaluation_time 3
    for creature in leg snake pod ragdoll; do
      simulate "simulate_minemonics_${creature}_chaotic" \
        --genome "$creatures/minemonics/$creature.genome" \
        --config "$source_dir/jobs/experiments/minemonics/walk-chaotic.ini" \
        --task.evaluation_time 2
    done
    for creature in walker4 snake; do
      simulate "simulate_${creature}_walk_rigid_bodies" --genome "$creatures/$creature.genome" \
        --task walk --physics.world rigid_bodies --task.evaluation_time 3
    done
    simulate simulate_minemonics_leg_rigid_bodies --genome "$creatures/minemonics/leg.genome" \
      --config "$source_dir/jobs/experiments/minemonics/walk-sine.ini" \
      --physics.world rigid_bodies --task.evaluation_time 2
    simulate simulate_snake_swim_rigid_bodies --genome "$creatures/snake.genome" --task swim \
      --environment.name water --physics.world rigid_bodies --task.evaluation_time 2
    simulate simulate_snake_torque --genome "$creatures/snake.genome" --task walk \
      --physics.actuation torque --physics.self_collision true --task.evaluation_time 2
    for seed in 1 2 3 4 5 6; do
      simulate "simulate_random${seed}_walk" --random --seed "$seed" --task walk \
        --task.evaluation_time 3 --task.rest_check true
      simulate "simulate_random${seed}_jump" --random --seed "$seed" --task jump \
        --task.evaluation_time 2
    done
    simulate simulate_snake_swim --genome "$creatures/snake.genome" --task swim \
      --environment.name water --task.evaluation_time 2
    simulate simulate_walker4_follow_light --genome "$creatures/walker4.genome" \
      --task follow_light --task.evaluation_time 2
    for seed in 1 2; do
      simulate "simulate_random${seed}_swim" --random --seed "$seed" --task swim \
        --environment.name water --task.evaluation_time 2
    done
    for seed in 1 6; do
      simulate "simulate_random${seed}_catapult" --random --seed "$seed" --task catapult \
        --genome.catapult true --task.evaluation_time 3
    done
    for organism in pyramid snake; do
      simulate "simulate_springy_${organism}" --random --seed 5 \
        --config "$source_dir/jobs/experiments/springy/snake-frozen.ini" \
        --springy.organism "$creatures/springy/$organism.organism" --task.evaluation_time 3
    done
    for creature in block defdino pole turtle; do
      simulate "simulate_wwd_${creature}" --genome "$creatures/wwd/$creature.genome" \
        --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" --task.evaluation_time 3
    done
    simulate simulate_wwd_random --random --seed 6 \
      --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" --task.evaluation_time 3
    simulate simulate_wwd_jump --genome "$creatures/wwd/turtle.genome" \
      --config "$source_dir/jobs/experiments/wwd/jump.ini" --task.evaluation_time 3
    simulate simulate_wwd_combination --genome "$creatures/wwd/turtle.genome" \
      --config "$source_dir/jobs/experiments/wwd/iterative-move.ini" --task.name combination \
      --task.evaluation_time 3
    simulate simulate_random3_synthetic --random --seed 3 --task synthetic \
      --task.synthetic_cost_us 10 --task.synthetic_distribution lognormal
    ;;
  resume_v1)
    cp -r "$source_dir/tests/store/data/v1_run" "$work/resume_v1"
    # the run's own settings, and the defaults of its day that have changed since
    evolve_args=(--task.name walk --task.evaluation_time 0.5 --evolution.population 8
                 --evolution.generations 5 --seed 21 --run.checkpoint_every 1
                 --physics.self_collision false --task.rest_check false
                 --task.rest_speed 0.2)
    launch=()
    if [ "$np" -gt 1 ]; then
      launch=("$mpiexec" "$npflag" "$np" --oversubscribe)
    fi
    code=0
    timeout -k 10 "$limit" "${launch[@]}" "$cambrian" evolve --quiet --out "$work/resume_v1" \
      "${evolve_args[@]}" > /dev/null 2> "$work/resume_v1.refused" || code=$?
    [ "$code" -eq 6 ] && grep -q "set physics.contact_slop = 0, physics.friction_anchors = false, physics.implicit_damping = false, physics.joint_speed_clamp = 100, physics.max_energy_gain = 0, physics.solve_every_dof = false, physics.solver_tolerance = 0 to continue" \
      "$work/resume_v1.refused" ||
      fail "resume_v1 under today's physics: exit $code, not 6 naming physics.friction_anchors: $(head -n 3 "$work/resume_v1.refused")"
    evolve_args+=(--physics.friction_anchors false --physics.contact_slop 0
                  --physics.implicit_damping false --physics.joint_speed_clamp 100
                  --physics.max_energy_gain 0 --physics.solve_every_dof false
                  --physics.solver_tolerance 0)
    timeout -k 10 "$limit" "${launch[@]}" "$cambrian" evolve --quiet --out "$work/resume_v1" \
      "${evolve_args[@]}" > "$work/resume_v1.out" 2> "$work/resume_v1.err" ||
      fail "resume_v1: exit code $?; stderr: $(head -n 5 "$work/resume_v1.err")"
    grep -q "resuming from" "$work/resume_v1.out" ||
      fail "resume_v1: did not resume: $(head -n 3 "$work/resume_v1.out")"
    check resume_v1 "$(awk '$1 == "digest" { print $2 }' "$work/resume_v1.out")"
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
[ "$failures" -eq 0 ] || fail "$failures value(s) differ from $expected"
