#!/usr/bin/env bash
# Checkpoint / resume checks of `cambrian evolve`, run by CTest at several rank counts.
# usage: resume_check.sh MODE CAMBRIAN MPIEXEC NPFLAG NP WORKDIR COMPARE
#   kill_resume:  a straight run vs the same run SIGKILLed (run.test_kill_at) mid-generation,
#                 after the history append, mid-checkpoint-write, before the rename and after it,
#                 then resumed: identical histories (compare_histories.py), digests and tables,
#                 nothing before the last checkpoint lost
#   other_ranks:  killed at NP ranks, resumed at 1 rank (and a 1-rank kill resumed at NP)
#   signal:       SIGUSR1 stops cleanly (exit 0, checkpoint, workers survive), rerun finishes it
#   max_hours:    --max-hours stops cleanly before the limit, rerun finishes it
#   settings:     a changed result setting is refused (exit 6, key and values named, nothing
#                 overwritten); run-only keys may change; --fresh starts over; raising
#                 evolution.generations extends a finished run; a corrupt checkpoint is refused
#   walk:         a tiny walk run killed and resumed equals the straight one
#   islands:      islands trading every generation (islands.count = NP, at least 2, each in
#                 process or with workers), killed at several points (each island resumes from
#                 its own last checkpoint, the batches its neighbours may have lost sent again),
#                 stopped by SIGUSR1 and continued, resumed at another rank count, and extended
#                 by raising evolution.generations: every island's digest and history as the
#                 straight run's; an island whose older checkpoint was put back, so that a
#                 neighbour no longer holds the migrants it needs, is refused (exit 6 naming it)
#   disk_full:    the output on a small tmpfs that fills at eleven points of the run (history
#                 appends, checkpoints): exit 5 naming the file, the system's reason and the way
#                 on; with room again the same command finishes identical to the straight run.
#                 Skipped (exit 77) where the test may not mount a tmpfs; a file size limit
#                 (ulimit -f) cannot stand in: it stops Open MPI's own shared-memory files
#   worker_killed: a worker rank SIGKILLed mid-run: the job ends within a minute, the launcher's
#                 message naming the rank, and the same command resumes to the straight run
#   lost_files:   history.h5 deleted mid-run: written back from the open file, the run goes on to
#                 the straight run's end; replaced mid-run by another file: exit 5, the run's own
#                 history saved as history.h5.own, the other file untouched, and after moving it
#                 back the same command finishes; the output directory made read-only mid-run
#                 (checked as an unprivileged user): exit 5 with the reason, and the same command
#                 finishes once it is writable again
#   kill_at_once: kill -9 at random moments (a seeded draw: the job's process group, which
#                 leaves the ranks to die on their own, or every process of the job), each time
#                 the same command again at once (it waits for the dying run's lock), until
#                 done: identical to the straight run
# NP 1 runs the binary without mpiexec (in-process evaluation).
set -euo pipefail
mode=$1 cambrian=$2 mpiexec=$3 npflag=$4 np=$5 work=$6 compare=$7
rm -rf "$work" && mkdir -p "$work"

# one evolve job at N ranks (exec: in a background subshell, $! is then the job itself)
job() {
  local n=$1
  shift
  if [ "$n" -eq 1 ]; then
    "$cambrian" evolve "$@"
  else
    "$mpiexec" "$npflag" "$n" --oversubscribe "$cambrian" evolve "$@"
  fi
}
job_exec() {
  local n=$1
  shift
  if [ "$n" -eq 1 ]; then
    exec "$cambrian" evolve "$@"
  else
    exec "$mpiexec" "$npflag" "$n" --oversubscribe "$cambrian" evolve "$@"
  fi
}

cat > "$work/run.ini" <<INI
[task]
name = synthetic
synthetic_cost_us = 300
synthetic_cost_per_gene_us = 20
synthetic_noise = 0.3
[evolution]
population = 12
generations = 6
selection = tournament
[run]
seed = 11
quiet = true
checkpoint_every = 1
INI

# the straight run every other run must reproduce
straight() {
  job "${2:-$np}" --config "$work/run.ini" --out "$work/$1" "${@:3}" > "$work/$1.txt"
}

# run B equals the straight run A: digest, history (timing aside), tables (timing aside)
same() {
  local a=$1 b=$2
  local da db
  da=$(grep '^digest ' "$work/$a.txt") db=$(grep '^digest ' "$work/$b.txt")
  echo "$a: $da   $b: $db"
  [ -n "$da" ] && [ "$da" = "$db" ]
  "$compare" "$work/$a/history.h5" "$work/$b/history.h5"
  diff <(cut -f1-7 "$work/$a/individuals.tsv") <(cut -f1-7 "$work/$b/individuals.tsv")
  diff <(cut -f1-10 "$work/$a/generations.tsv") <(cut -f1-10 "$work/$b/generations.tsv")
}

# the run in DIR/stopped, slow, sent SIGUSR1 once generation 2 is done (mpiexec forwards it to
# every rank): it must exit 0; its output in stopped.first.txt, its errors in stopped.err
stopped_by_signal() {
  (job_exec "$np" --config "$work/run.ini" --out "$work/stopped" --run.quiet false \
    > "$work/stopped.first.txt" 2> "$work/stopped.err") &
  local pid=$! rc
  for _ in $(seq 1 600); do
    grep -q '^gen 2/' "$work/stopped.first.txt" 2> /dev/null && break
    sleep 0.05
  done
  kill -USR1 "$pid"
  set +e
  wait "$pid"
  rc=$?
  set -e
  cat "$work/stopped.first.txt"
  echo "stopped run exit $rc"
  [ "$rc" -eq 0 ]
}

# the run in DIR/NAME SIGKILLed at POINT (run.test_kill_at): it must die of it
killed_at() {
  local name=$1 point=$2 rc
  set +e
  job "$np" --config "$work/run.ini" --out "$work/$name" --run.test_kill_at "$point" \
    > "$work/$name.killed.txt" 2> "$work/$name.killed.err"
  rc=$?
  set -e
  echo "$point: killed run exit $rc"
  [ "$rc" -ne 0 ]
  grep -q "run.test_kill_at $point: SIGKILL" "$work/$name.killed.err"
}

# a run killed at POINT, then resumed (at RESUME_NP ranks) until done: NAME.txt holds the end
kill_and_resume() {
  local name=$1 point=$2 expect_from=$3 resume_np=${4:-$np}
  killed_at "$name" "$point"
  job "$resume_np" --config "$work/run.ini" --out "$work/$name" > "$work/$name.txt"
  # nothing before the last checkpoint lost: it resumes from the expected generation
  grep "resuming from" "$work/$name.txt"
  grep -q "resuming from $work/$name/checkpoint.h5 at generation $expect_from " "$work/$name.txt"
}

case $mode in
  kill_resume)
    straight straight
    # mid-generation 2: the checkpoint after generation 1 continues from 2
    kill_and_resume mid_generation evaluation:2 2
    same straight mid_generation
    # rows of generation 3 in the history, no checkpoint of it yet: they are recomputed
    kill_and_resume after_history history:3 3
    same straight after_history
    # the checkpoint after generation 1 half written: the one after generation 0 is used
    kill_and_resume mid_write checkpoint_write:1 1
    same straight mid_write
    # complete but not renamed into place
    kill_and_resume before_rename checkpoint_rename:4 4
    same straight before_rename
    # in place, its time not yet in the history
    kill_and_resume after_rename checkpoint_done:2 3
    same straight after_rename
    ;;
  other_ranks)
    straight straight 1
    # killed at NP ranks, resumed in one process
    kill_and_resume np_to_one evaluation:3 3 1
    same straight np_to_one
    # a checkpoint of a single-rank run, resumed at NP ranks
    np_saved=$np
    np=1 kill_and_resume one_to_np history:2 2 "$np_saved"
    same straight one_to_np
    ;;
  signal)
    straight straight
    # slower generations, so the signal lands mid-run; SIGUSR1 to the job (mpiexec forwards it)
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 20000/' "$work/run.ini"
    straight slow_straight
    stopped_by_signal
    grep -q "stopped by SIGUSR1 after .* run the same command again" "$work/stopped.first.txt"
    grep -q '^digest_so_far ' "$work/stopped.first.txt"
    [ -s "$work/stopped/checkpoint.h5" ]
    # workers survived: no error from any rank, no rank ended by the signal
    if grep -i -e "error" -e "terminated" -e "exited on signal" "$work/stopped.err"; then
      exit 1
    fi
    job "$np" --config "$work/run.ini" --out "$work/stopped" > "$work/stopped.txt"
    same slow_straight stopped
    ;;
  max_hours)
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 40000/' "$work/run.ini"
    sed -i 's/^generations = 6/generations = 10/' "$work/run.ini"
    straight straight
    # about 1.1 s allowed; 10 generations need 2 s or more even on 3 workers: it stops early, exit 0
    job "$np" --config "$work/run.ini" --out "$work/limited" --max-hours 0.0003 \
      > "$work/limited.first.txt"
    cat "$work/limited.first.txt"
    grep -q "stopped before the --max-hours 0.0003 limit" "$work/limited.first.txt"
    grep -q "run the same command again to continue" "$work/limited.first.txt"
    job "$np" --config "$work/run.ini" --out "$work/limited" > "$work/limited.txt"
    same straight limited
    ;;
  settings)
    straight straight
    set +e
    job "$np" --config "$work/run.ini" --out "$work/changed" --run.test_kill_at history:3 \
      > /dev/null 2>&1
    set -e
    cp "$work/changed/checkpoint.h5" "$work/saved_checkpoint.h5"
    # a setting that changes results: exit 6 naming key and values, nothing overwritten
    set +e
    job "$np" --config "$work/run.ini" --out "$work/changed" --task.synthetic_noise 0.5 \
      > "$work/changed.out" 2> "$work/changed.err"
    rc=$?
    set -e
    cat "$work/changed.err"
    [ "$rc" -eq 6 ]
    grep -q "task.synthetic_noise was '0.3' .* is '0.5' now" "$work/changed.err"
    cmp "$work/changed/checkpoint.h5" "$work/saved_checkpoint.h5"
    # run-only keys may change (quiet, checkpoint cadence); the rest goes on exactly
    job "$np" --config "$work/run.ini" --out "$work/changed" --run.quiet false \
      --run.checkpoint_every 2 > "$work/changed.txt"
    grep -q '^gen 6/6' "$work/changed.txt"
    same straight changed
    # the finished run again: nothing to do, same digest
    job "$np" --config "$work/run.ini" --out "$work/changed" > "$work/again.txt"
    grep -q "resuming from .* at generation 6 " "$work/again.txt"
    cp -r "$work/changed" "$work/again"
    same straight again
    # --fresh starts over
    job "$np" --config "$work/run.ini" --out "$work/changed" --fresh > "$work/fresh.txt"
    if grep "resuming" "$work/fresh.txt"; then
      exit 1
    fi
    rm -rf "$work/fresh" && cp -r "$work/changed" "$work/fresh"
    same straight fresh
    # raising evolution.generations extends a finished run
    sed 's/^generations = 6/generations = 8/' "$work/run.ini" > "$work/long.ini"
    job "$np" --config "$work/long.ini" --out "$work/long_straight" > "$work/long_straight.txt"
    job "$np" --config "$work/long.ini" --out "$work/changed" > "$work/extended.txt"
    grep -q "resuming from .* at generation 6 " "$work/extended.txt"
    rm -rf "$work/extended" && cp -r "$work/changed" "$work/extended"
    same long_straight extended
    # a corrupt checkpoint: exit 6 naming the file, the good previous one offered, untouched
    head -c 900 "$work/changed/checkpoint.h5" > "$work/cut.h5"
    cp "$work/cut.h5" "$work/changed/checkpoint.h5"
    set +e
    job "$np" --config "$work/long.ini" --out "$work/changed" > /dev/null 2> "$work/corrupt.err"
    rc=$?
    set -e
    cat "$work/corrupt.err"
    [ "$rc" -eq 6 ]
    grep -q "$work/changed/checkpoint.h5: .*checkpoint.prev.h5 is good .*--fresh" \
      "$work/corrupt.err"
    cmp "$work/changed/checkpoint.h5" "$work/cut.h5"
    ;;
  islands)
    islands=$((np < 2 ? 2 : np))
    [ "$np" -ge 2 ] || np=2
    cat >> "$work/run.ini" <<INI
[islands]
count = $islands
interval = 1
migrants = 2
INI
    # the archipelago's runs equal: the run's and every island's digest and history
    same_islands() {
      local a=$1 b=$2
      diff <(grep -e '^island ' -e '^digest ' "$work/$a.txt") \
        <(grep -e '^island ' -e '^digest ' "$work/$b.txt")
      [ "$(grep -c '^island ' "$work/$b.txt")" -eq "$islands" ]
      for dir in "$work/$a"/island_*; do
        "$compare" "$dir/history.h5" "$work/$b/$(basename "$dir")/history.h5"
        diff <(cut -f1-7 "$dir/individuals.tsv") \
          <(cut -f1-7 "$work/$b/$(basename "$dir")/individuals.tsv")
      done
    }
    islands_killed() {
      local name=$1 point=$2 resume_np=${3:-$np}
      killed_at "$name" "$point"
      job "$resume_np" --config "$work/run.ini" --out "$work/$name" > "$work/$name.txt"
      grep "resuming from" "$work/$name.txt"
      # the other islands' lines in their own logs
      grep -q "resuming from $work/$name/island_1/checkpoint.h5" "$work/$name/island_1/evolve.log"
      same_islands straight "$name"
    }
    straight straight
    # migrants were placed: the islands trade
    [ "$(awk -F'\t' '$4 == "migrant"' "$work/straight/island_0/individuals.tsv" | wc -l)" -gt 0 ]
    islands_killed mid_generation evaluation:3
    islands_killed after_history history:4
    islands_killed after_checkpoint checkpoint_done:2
    islands_killed mid_write checkpoint_write:3
    # at another rank count (as many islands need as many ranks)
    islands_killed other_ranks evaluation:4 $((np + 1))
    # an island's checkpoint put back by hand to an older one: its neighbour no longer holds the
    # migrants it would take in first, so the job is refused (exit 6, naming both) instead of
    # waiting for them for ever, before any island runs a generation
    sed -i 's/^generations = 6/generations = 3/' "$work/run.ini"
    job "$np" --config "$work/run.ini" --out "$work/restored" > /dev/null
    cp "$work/restored/island_1/checkpoint.h5" "$work/restored_island_1_at_3.h5"
    sed -i 's/^generations = 3/generations = 6/' "$work/run.ini"
    job "$np" --config "$work/run.ini" --out "$work/restored" > /dev/null
    cp "$work/restored_island_1_at_3.h5" "$work/restored/island_1/checkpoint.h5"
    for k in $(seq 0 $((islands - 1))); do
      cp "$work/restored/island_$k/checkpoint.h5" "$work/restored_island_$k.h5"
    done
    set +e
    job "$np" --config "$work/run.ini" --out "$work/restored" --evolution.generations 8 \
      > "$work/restored.txt" 2> "$work/restored.err"
    rc=$?
    set -e
    echo "an older checkpoint put back: exit $rc, $(grep -m1 'no longer holds' "$work/restored.err" || true)"
    [ "$rc" -eq 6 ]
    grep -q "island 1 continues from generation 3, but island 0 ($work/restored/island_0" \
      "$work/restored.err"
    # no island ran a generation: every checkpoint as it was
    for k in $(seq 0 $((islands - 1))); do
      cmp "$work/restored/island_$k/checkpoint.h5" "$work/restored_island_$k.h5"
    done
    # a finished run extended: the batches of its last generations were kept for it
    sed -i 's/^generations = 6/generations = 4/' "$work/run.ini"
    job "$np" --config "$work/run.ini" --out "$work/extended" > "$work/extended.first.txt"
    sed -i 's/^generations = 4/generations = 6/' "$work/run.ini"
    job "$np" --config "$work/run.ini" --out "$work/extended" > "$work/extended.txt"
    same_islands straight extended
    # SIGUSR1 to the job: every island stops cleanly, the same command finishes the run
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 20000/' "$work/run.ini"
    straight slow_straight
    stopped_by_signal
    grep -q "stopped .* run the same command again" "$work/stopped.first.txt"
    job "$np" --config "$work/run.ini" --out "$work/stopped" > "$work/stopped.txt"
    same_islands slow_straight stopped
    ;;
  walk)
    cat > "$work/run.ini" <<INI
[task]
name = walk
evaluation_time = 0.5
settle_time = 0.1
[evolution]
population = 6
generations = 3
[run]
seed = 4
quiet = true
checkpoint_every = 1
INI
    straight straight
    kill_and_resume walk_killed evaluation:1 1
    same straight walk_killed
    ;;
  kill_at_once)
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 8000/; s/^generations = 6/generations = 50/;
            s/^population = 12/population = 16/' "$work/run.ini"
    straight straight
    command=("$cambrian" evolve)
    if [ "$np" -gt 1 ]; then
      command=("$mpiexec" "$npflag" "$np" --oversubscribe "$cambrian" evolve)
    fi
    RANDOM=$((np * 1000 + 7))
    killed=0
    for trial in $(seq 1 12); do
      delay=$(printf '%d.%03d' $((RANDOM % 2)) $((RANDOM % 1000 / 2 + 100)))
      whole=$((RANDOM % 2))
      # its own session, whose id the job writes first
      rm -f "$work/session"
      setsid bash -c 'echo $$ > "$0"; exec "${@}"' "$work/session" "${command[@]}" \
        --config "$work/run.ini" --out "$work/trials" > "$work/trial$trial.txt" 2>&1 &
      runner=$!
      sleep "$delay"
      for _ in $(seq 1 100); do
        [ -s "$work/session" ] && break
        sleep 0.01
      done
      session=$(cat "$work/session")
      if [ "$whole" -eq 1 ]; then
        pkill -KILL -s "$session" || true
      else
        kill -KILL -- "-$session" 2> /dev/null || true
      fi
      set +e
      wait "$runner" 2> /dev/null
      rc=$?
      set -e
      what="job's process group"
      [ "$whole" -eq 1 ] && what="whole job"
      # (what the ranks printed is lost with mpiexec: only a finished run's lines are kept)
      echo "trial $trial: killed the $what after ${delay} s: exit $rc"
      if grep -q '^digest ' "$work/trial$trial.txt"; then
        break
      fi
      killed=$((killed + 1))
      grep -q "another cambrian evolve is writing" "$work/trial$trial.txt" && exit 1
    done
    echo "$killed run(s) killed before the end"
    [ "$killed" -ge 3 ]
    job "$np" --config "$work/run.ini" --out "$work/trials" > "$work/trials.txt"
    grep "resuming from" "$work/trials.txt" || true
    same straight trials
    ;;
  worker_killed)
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 20000/; s/^generations = 6/generations = 12/' \
      "$work/run.ini"
    straight straight
    (job_exec "$np" --config "$work/run.ini" --out "$work/lost" > "$work/lost.first.txt" \
      2> "$work/lost.err") &
    launcher=$!
    # a checkpoint after generation 1 or later, then a worker (any rank but the lock's holder)
    for _ in $(seq 1 600); do
      [ -s "$work/lost/checkpoint.prev.h5" ] && break
      sleep 0.05
    done
    holder=$(sed -n 's/^host .* pid \([0-9]*\)$/\1/p' "$work/lost/run.lock")
    victim=$(pgrep -P "$launcher" | grep -v -x "$holder" | head -1)
    echo "rank 0 is pid $holder; killing worker pid $victim"
    [ -n "$victim" ]
    kill -KILL "$victim"
    # the job ends on its own, never a hang
    for _ in $(seq 1 600); do
      kill -0 "$launcher" 2> /dev/null || break
      sleep 0.1
    done
    if kill -0 "$launcher" 2> /dev/null; then
      echo "the job still runs a minute after its worker was killed" >&2
      kill -KILL "$launcher"
      exit 1
    fi
    set +e
    wait "$launcher"
    rc=$?
    set -e
    echo "job exit $rc"
    cat "$work/lost.err"
    [ "$rc" -ne 0 ]
    grep -q "process rank [1-9][0-9]* .* exited on signal 9" "$work/lost.err"
    job "$np" --config "$work/run.ini" --out "$work/lost" > "$work/lost.txt"
    grep "resuming from" "$work/lost.txt"
    same straight lost
    ;;
  lost_files)
    sed -i 's/^synthetic_cost_us = 300/synthetic_cost_us = 20000/; s/^generations = 6/generations = 12/' \
      "$work/run.ini"
    straight straight
    # a run in the background, and the moment its checkpoint after generation 1 is in place
    start() {
      (job_exec "$np" --config "$work/run.ini" --out "$work/$1" --run.quiet false \
        > "$work/$1.first.txt" 2>&1) &
      background=$!
      for _ in $(seq 1 600); do
        [ -s "$work/$1/checkpoint.prev.h5" ] && break
        sleep 0.05
      done
    }
    finish() {
      set +e
      wait "$background"
      rc=$?
      set -e
      echo "$1: exit $rc: $(grep -e 'warning: ' -e 'rank 0: ' "$work/$1.first.txt" | head -1)"
    }
    # deleted: the run notices at its next append, writes it back and goes on
    start deleted
    rm "$work/deleted/history.h5"
    finish deleted
    [ "$rc" -eq 0 ]
    grep -q "history.h5: deleted while this run was writing it; written back" \
      "$work/deleted.first.txt"
    grep '^digest ' "$work/deleted.first.txt" > "$work/deleted.txt"
    same straight deleted
    # replaced: the other file is left alone, the run's own is saved beside it
    start replaced
    cp "$work/straight/individuals.tsv" "$work/other_file"
    mv "$work/other_file" "$work/replaced/history.h5"
    finish replaced
    [ "$rc" -eq 5 ]
    grep -q "history.h5: replaced by another file while this run was writing it; the run's own" \
      "$work/replaced.first.txt"
    cmp "$work/straight/individuals.tsv" "$work/replaced/history.h5"
    mv "$work/replaced/history.h5.own" "$work/replaced/history.h5"
    job "$np" --config "$work/run.ini" --out "$work/replaced" > "$work/replaced.txt"
    same straight replaced
    # read-only: root writes anyway, so this part runs as nobody (skipped where that is impossible)
    as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
    if [ "$(id -u)" -eq 0 ] && command -v setpriv > /dev/null && id nobody > /dev/null 2>&1 &&
      "${as_user[@]}" test -x "$cambrian"; then
      mkdir -p "$work/readonly"
      chown nobody "$work/readonly"
      chmod o+rx "$work" "$work/run.ini"
      set +e
      (exec "${as_user[@]}" bash -c "$(declare -f job_exec); cambrian=$cambrian mpiexec=$mpiexec \
        npflag=$npflag; job_exec $np --config $work/run.ini --out $work/readonly \
        --run.quiet false" > "$work/readonly.first.txt" 2>&1) &
      background=$!
      set -e
      for _ in $(seq 1 600); do
        [ -s "$work/readonly/checkpoint.prev.h5" ] && break
        sleep 0.05
      done
      chmod a-w "$work/readonly"
      finish readonly
      chmod u+w "$work/readonly"
      [ "$rc" -eq 5 ]
      grep -q "Permission denied.*run the same command to continue" "$work/readonly.first.txt"
      job "$np" --config "$work/run.ini" --out "$work/readonly" > "$work/readonly.txt"
      same straight readonly
    else
      echo "the read-only directory part needs root and a cambrian that nobody may run" \
        "(a build folder under a private directory is not): skipped"
    fi
    ;;
  disk_full)
    sed -i 's/^population = 12/population = 60/; s/^generations = 6/generations = 10/' \
      "$work/run.ini"
    straight straight
    final=$(du -sk "$work/straight" | cut -f1)
    disk="$work/disk"
    mkdir -p "$disk"
    if ! mount -t tmpfs -o size=64k tmpfs "$disk" 2> /dev/null; then
      echo "resume_check disk_full: skipped: this machine does not let the test mount a tmpfs"
      exit 77
    fi
    trap 'umount "$disk" 2> /dev/null || true' EXIT
    echo "the straight run's directory: $final KB"
    stopped=0
    for percent in 4 8 12 17 23 30 38 47 58 70 85; do
      kb=$((final * percent / 100 + 16))
      name=full_$percent
      rm -rf "${disk:?}"/*
      mount -o remount,size=${kb}k "$disk"
      set +e
      job "$np" --config "$work/run.ini" --out "$disk/run" > "$work/$name.first.txt" 2>&1
      rc=$?
      set -e
      echo "$kb KB: exit $rc: $(grep -o 'rank 0: .*' "$work/$name.first.txt" | head -1 | cut -c1-300)"
      if [ "$rc" -ne 0 ]; then
        [ "$rc" -eq 5 ]
        grep -q "No space left on device" "$work/$name.first.txt"
        grep -q -e "run the same command to continue" \
          -e "run the same command again to write the tables" "$work/$name.first.txt"
        stopped=$((stopped + 1))
      fi
      # room again: the same command finishes the run
      mount -o remount,size=$((final * 3))k "$disk"
      job "$np" --config "$work/run.ini" --out "$disk/run" > "$work/$name.txt"
      rm -rf "${work:?}/$name" && cp -r "$disk/run" "$work/$name"
      same straight "$name"
    done
    echo "$stopped run(s) stopped by the full disk"
    [ "$stopped" -ge 8 ]
    ;;
  *)
    echo "unknown mode $mode" >&2
    exit 2
    ;;
esac
echo "resume_check $mode at $np rank(s): ok"
