#!/usr/bin/env bash
# Where a time step's instructions go, loop by loop: callgrind on bench/step_cost.cpp's program
# (bare, matched, cambrian; docs/performance.md, "Per-step cost against a bare Bullet loop"),
# instructions per time step of each loop's step and of the parts of Bullet's step that the
# constraints, contacts and cambrian's own code cost. Instruction counts repeat exactly, so two
# configurations compare without the timing noise of a shared machine. Needs valgrind.
# usage: bash jobs/bench/step_cost_profile.sh [BUILD_DIR] [--parts N] [physics.KEY=VALUE ...]
#   BUILD_DIR   default build/ci (its bench/cambrian_step_cost); N default 5
set -euo pipefail
cd "$(dirname "$0")/../.."

if [ "${1:-}" = --help ] || [ "${1:-}" = -h ]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
build=build/ci
if [ $# -gt 0 ] && [[ $1 != *=* ]] && [[ $1 != --* ]]; then
  build=$1
  shift
fi
parts=5
settings=()
while [ $# -gt 0 ]; do
  case $1 in
    --parts) parts=${2:?--parts needs a value}; shift 2 ;;
    *=*) settings+=("$1"); shift ;;
    *) echo "step_cost_profile.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
bench=$build/bench/cambrian_step_cost
[ -x "$bench" ] || { echo "step_cost_profile.sh: $bench not found; build it first" >&2; exit 2; }
command -v valgrind > /dev/null || { echo "step_cost_profile.sh: needs valgrind" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# what is reported: label, then the function whose inclusive cost it is
rows=(
  "loop step (all of it)|STEP"
  "  Bullet's step (stepSimulation)|btDiscreteDynamicsWorld::stepSimulation"
  "    forward dynamics (solveExternalForces)|btMultiBodyDynamicsWorld::solveExternalForces"
  "    solver setup (convertContacts)|btMultiBodyConstraintSolver::convertContacts"
  "      motor rows|btMultiBodyJointMotor::createConstraintRows"
  "      joint-limit rows|btMultiBodyJointLimitConstraint::createConstraintRows"
  "      contact rows (normal + friction)|btMultiBodyConstraintSolver::convertMultiBodyContact"
  "    solver iterations|btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations"
  "      motor, limit and normal rows|btMultiBodyConstraintSolver::resolveSingleConstraintRowGeneric"
  "      friction rows|btMultiBodyConstraintSolver::resolveConeFrictionConstraintRows"
  "    collision detection|btCollisionWorld::performDiscreteCollisionDetection"
  "      cambrian's collider filter|PartCollider::checkCollideWithOverride"
  "    integration|btMultiBodyDynamicsWorld::integrateTransforms"
  "  cambrian: sensors|cambrian::Simulation::readSensors"
  "  cambrian: controller|cambrian::SineOscillators::step"
  "  cambrian: damping torques, motor targets|cambrian::FeatherstoneWorld::applyTorques"
  "  cambrian: monitors|cambrian::Simulation::monitor"
)

# one callgrind run per loop: inclusive costs and call counts
unsound=()
for loop in bare matched cambrian; do
  valgrind --tool=callgrind --callgrind-out-file="$work/$loop.out" "$bench" --parts "$parts" \
    --loops "$loop" --rounds 1 --seconds 1 --warmup 1 ${settings[@]+"${settings[@]}"} \
    > "$work/$loop.txt" 2> /dev/null || unsound+=("$loop")
  callgrind_annotate --inclusive=yes --threshold=100 "$work/$loop.out" > "$work/$loop.incl" 2> /dev/null
  callgrind_annotate --inclusive=yes --tree=calling --threshold=100 "$work/$loop.out" \
    > "$work/$loop.tree" 2> /dev/null
done

# inclusive Ir of a function (its first listing), and the calls of a function (summed over callers)
inclusive() {
  awk -v name="$2" 'index($0, ":" name "(") || index($0, "::" name "(") {
      gsub(",", "", $1); print $1; found = 1; exit } END { if (!found) print 0 }' "$1"
}
calls() {
  awk -v name="$2" '$3 == ">" && index($0, name "(") && match($0, /\(([0-9,]+)x\)/) {
      n = substr($0, RSTART + 1, RLENGTH - 3); gsub(",", "", n); total += n }
    END { print total + 0 }' "$1"
}

configuration="cambrian's default physics"
[ ${#settings[@]} -eq 0 ] || configuration="${settings[*]}"
echo "instructions per time step, chain of $parts parts (callgrind; $configuration)"
printf "%-48s %12s %12s %12s\n" "" bare matched cambrian
declare -A steps
steps[bare]=$(calls "$work/bare.tree" "BareLoop::step")
steps[matched]=$(calls "$work/matched.tree" "BareLoop::step")
steps[cambrian]=$(calls "$work/cambrian.tree" "cambrian::Simulation::step")
for row in "${rows[@]}"; do
  label=${row%%|*} function=${row#*|}
  printf "%-48s" "$label"
  for loop in bare matched cambrian; do
    name=$function
    if [ "$name" = STEP ]; then
      [ "$loop" = cambrian ] && name=cambrian::Simulation::step || name=BareLoop::step
    fi
    cost=$(inclusive "$work/$loop.incl" "$name")
    awk -v c="$cost" -v s="${steps[$loop]}" 'BEGIN { if (c > 0) printf " %12.0f", c / s; else printf " %12s", "-" }'
  done
  echo
done
printf "%-48s" "row solves per step (motor, limit, normal)"
for loop in bare matched cambrian; do
  n=$(calls "$work/$loop.tree" "btMultiBodyConstraintSolver::resolveSingleConstraintRowGeneric")
  awk -v n="$n" -v s="${steps[$loop]}" 'BEGIN { printf " %12.1f", n / s }'
done
echo
printf "%-48s" "steps profiled"
for loop in bare matched cambrian; do printf " %12s" "${steps[$loop]}"; done
echo
if [ ${#unsound[@]} -gt 0 ]; then
  echo "not sound (exploded, still or not born; its figures mean little): ${unsound[*]}"
  for loop in "${unsound[@]}"; do grep -E "^ *$parts +$loop " "$work/$loop.txt" || true; done
  exit 1
fi
