#!/usr/bin/env bash
# Runs the libFuzzer targets of fuzz/ (doc/fuzzing.md). Not part of CI.
#
#   tools/fuzz.sh [target|all] [executions]      (default: all, 1000000)
#
# Builds with clang into build-fuzz/ (-DFAIR_FUZZ=ON: -fsanitize=fuzzer,address,undefined), then
# for each target, one at a time: runs `executions` inputs starting from fuzz/corpus/<target>/
# (new inputs go to build-fuzz/work/<target>/, crashes to build-fuzz/findings/<target>/), merges
# the new coverage into a minimised fuzz/corpus/<target>/ (-merge=1) and prints the executions,
# the wall time, the coverage (cov, ft) and the findings. Exit status 1 if a target found
# something. Be kind to a shared machine: `nice -n 19 tools/fuzz.sh`.
# Environment: FUZZ_JOBS (build parallelism, default 2), FUZZ_MAX_LEN (default 4096),
# FUZZ_TIMEOUT (seconds per input, default 1), FUZZ_BUILD (default build-fuzz), FUZZ_WORKERS
# (default 0), FUZZ_HANG (the hang limit of the parallel mode, seconds, default 10 x FUZZ_TIMEOUT:
# raise it when the machine is busy, so a load spike does not end the run), FUZZ_RETIME_REPLAY
# (a fuzz_replay of the ASan+UBSan build, build-sanitize/fuzz/fuzz_replay: re-time slow inputs with
# it, the library under the sanitizers without libFuzzer's coverage and comparison tracing, which
# alone makes tight numeric loops 3-5 times slower; doc/fuzzing.md, "The time oracle").
#
# FUZZ_WORKERS=N runs N libFuzzer processes in parallel on one shared corpus (-jobs=N -workers=N,
# executions/N each, logs build-fuzz/logs/<target>/fuzz-<i>.log) with a hang limit of 10 x FUZZ_TIMEOUT
# and -report_slow_units=FUZZ_TIMEOUT: a busy shared machine makes single inputs exceed the
# timeout now and then, and a -timeout of FUZZ_TIMEOUT stops the run at the first one. The slow
# and timed-out inputs are then re-timed alone (three runs, the fastest counts) and are findings
# only if still slower than FUZZ_TIMEOUT; the others move to findings/<target>/loaded/.
# (libFuzzer saves a slow unit only when it beats the slowest of its process so far, in whole
# seconds: after a load spike a later, genuinely slow input can go unsaved; the 10 x hang limit
# still catches real hangs.)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$root/build-fuzz}
build=$(mkdir -p "$build" && cd "$build" && pwd)  # absolute: the parallel mode runs from a log directory
jobs=${FUZZ_JOBS:-2}
max_len=${FUZZ_MAX_LEN:-4096}
timeout=${FUZZ_TIMEOUT:-1}
hang=${FUZZ_HANG:-$(( 10 * timeout ))}
retime_replay=${FUZZ_RETIME_REPLAY:-}
workers=${FUZZ_WORKERS:-0}
which=${1:-all}
runs=${2:-1000000}

all_targets=()
for f in "$root"/fuzz/fuzz_*.cpp; do
  n=$(basename "$f" .cpp); all_targets+=("${n#fuzz_}")
done
if [ "$which" = all ]; then targets=("${all_targets[@]}"); else targets=("$which"); fi

# The compiler is chosen once, when build-fuzz/ is first configured (changing it later would
# make cmake start the build directory afresh).
compiler=()
if [ ! -f "$build/CMakeCache.txt" ]; then
  compiler=(-DCMAKE_CXX_COMPILER="${CXX:-$(command -v clang++ || command -v clang++-14)}")
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${compiler[@]}" -DFAIR_FUZZ=ON \
  -DFAIR_BUILD_TOOLS=OFF -DFAIR_BUILD_EXAMPLES=OFF -DFAIR_BUILD_BENCHMARKS=OFF >/dev/null || exit 2

# Parallel mode: a slow or timed-out input is a finding only if it is slow alone (fastest of
# three runs).
retime_slow_inputs() { # exe findings-dir target
  local exe=$1 dir=$2 target=$3 f best ms i t0 one
  mkdir -p "$dir/loaded"
  for f in "$dir"/timeout-* "$dir"/slow-unit-*; do
    [ -f "$f" ] || continue
    best=
    for i in 1 2 3; do
      t0=$(date +%s%N)
      if [ -n "$retime_replay" ]; then
        one=$(mktemp -d); cp "$f" "$one/"
        timeout "$hang" "$retime_replay" "$target" "$one" >/dev/null 2>&1
        rm -rf "$one"
      else
        "$exe" -runs=1 -timeout="$hang" "$f" >/dev/null 2>&1
      fi
      ms=$(( ($(date +%s%N) - t0) / 1000000 ))
      if [ -z "$best" ] || [ "$ms" -lt "$best" ]; then best=$ms; fi
      [ "$ms" -lt $(( hang * 1000 )) ] || break  # a real hang: once is enough
    done
    if [ "$best" -lt $(( timeout * 1000 )) ]; then
      echo "  $(basename "$f"): ${best} ms alone, under the ${timeout} s limit (timed out under load)"
      mv "$f" "$dir/loaded/"
    else
      echo "  $(basename "$f"): ${best} ms alone: a finding"
    fi
  done
}

status=0
for t in "${targets[@]}"; do
  cmake --build "$build" -j"$jobs" --target "fuzz_${t}_libfuzzer" >/dev/null || { echo "$t: build failed"; exit 2; }
  exe=$build/fuzz/fuzz_$t
  corpus=$root/fuzz/corpus/$t
  work=$build/work/$t
  findings=$build/findings/$t
  mkdir -p "$corpus" "$work" "$findings"
  log=$build/$t.log
  start=$(date +%s)
  if [ "$workers" -gt 0 ]; then
    # libFuzzer writes fuzz-<i>.log into the current directory (not a corpus directory).
    logs=$build/logs/$t
    rm -rf "$logs"; mkdir -p "$logs"
    (cd "$logs" && "$exe" -jobs="$workers" -workers="$workers" -runs=$(( (runs + workers - 1) / workers )) \
      -max_len="$max_len" -timeout="$hang" -report_slow_units="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$findings/" "$work" "$corpus") >"$log" 2>&1
    # The parent's status is 1 after any job's timeout as well: decided here instead. A crash,
    # leak, sanitizer report or oracle failure of a job fails the run; a timeout only if its
    # input stays in findings/ after re-timing (counted below).
    rc=0
    for f in "$logs"/fuzz-*.log; do
      [ -f "$f" ] && grep -v 'ERROR: libFuzzer: timeout' "$f" | grep -q 'ERROR\|FUZZ ORACLE' && rc=1
    done
    # (The parent copies each job's log into $log too: count from the job logs only.)
    execs=$(cat "$logs"/fuzz-*.log 2>/dev/null | sed -n 's/^stat::number_of_executed_units: *//p' | awk '{s += $1} END {print s}')
    retime_slow_inputs "$exe" "$findings" "$t"
  else
    "$exe" -runs="$runs" -max_len="$max_len" -timeout="$timeout" -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$findings/" "$work" "$corpus" >"$log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  fi
  wall=$(( $(date +%s) - start ))
  cov=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1)
  # Merge the new coverage into a minimised corpus (keeps the seeds' coverage, drops redundancy).
  merged=$build/merged/$t
  rm -rf "$merged"; mkdir -p "$merged"
  "$exe" -merge=1 -max_len="$max_len" -timeout="$timeout" -rss_limit_mb=2048 "$merged" "$corpus" "$work" \
    >"$build/$t.merge.log" 2>&1 && {
      # The reproducers of fixed findings (regress-*) stay, under their names, whatever their coverage.
      find "$corpus" -maxdepth 1 -name 'regress-*' -exec cp {} "$merged/" \;
      rm -rf "$corpus"; mv "$merged" "$corpus"; }
  kept=$(find "$corpus" -type f | wc -l)
  found=$(find "$findings" -maxdepth 1 -type f | wc -l)
  echo "$t: executions ${execs:-?}, wall ${wall} s, ${cov:-cov ?}, corpus $kept files ($(cat "$corpus"/* | wc -c) bytes), exit $rc, findings $found"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1
    grep -E 'ERROR|FUZZ ORACLE|SUMMARY|Test unit written' "$log" | head -5
  fi
done
exit $status
