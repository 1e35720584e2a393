#!/usr/bin/env bash
# Builds the libFuzzer targets with Clang (ASan + UBSan, every library instrumented) and runs
# each for a bounded time on a scratch copy of its seed corpus. Exit status non-zero on any
# finding (crash, unexpected exception, sanitizer report, timeout, out-of-memory) or build error.
#
#   tests/fuzz/run.sh                     # 60 s per target (CI: FUZZ_TIME=40, .ci/run)
#   FUZZ_TIME=600 tests/fuzz/run.sh       # longer local run
#   FUZZ_TARGETS="fuzz_csv fuzz_sweep" tests/fuzz/run.sh
# Environment: FUZZ_BUILD_DIR (default build-fuzz), FUZZ_TIME (seconds per target, 60),
# FUZZ_JOBS (build parallelism, default: Ninja's), FUZZ_PARALLEL (targets fuzzed at once,
# default: number of cores), FUZZ_TARGETS (default: all nine), CC / CXX (default: clang-14 /
# clang++-14 if installed, else clang / clang++).
# Findings are written to $FUZZ_BUILD_DIR/fuzz-findings/<target>/ (crash-*, timeout-*, oom-*,
# leak-*) with the log beside them; the seed corpus in tests/fuzz/corpus is never modified
# (each run starts from a scratch copy in $FUZZ_BUILD_DIR/fuzz-work).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD

build=${FUZZ_BUILD_DIR:-build-fuzz}
time_per_target=${FUZZ_TIME:-60}
targets=(${FUZZ_TARGETS:-fuzz_csv fuzz_config fuzz_hammer fuzz_measurements fuzz_sweep fuzz_rheology fuzz_uff58 fuzz_frf_csv fuzz_tir})

pick() { for c in "$@"; do command -v "$c" >/dev/null 2>&1 && { echo "$c"; return; }; done; echo "$1"; }
export CC=${CC:-$(pick clang-14 clang)}
export CXX=${CXX:-$(pick clang++-14 clang++)}
if [[ -z ${ASAN_SYMBOLIZER_PATH:-} ]]; then
  for s in /usr/lib/llvm-14/bin/llvm-symbolizer "$(command -v llvm-symbolizer || true)"; do
    if [[ -n $s && -x $s ]]; then export ASAN_SYMBOLIZER_PATH=$s; break; fi
  done
fi

# -O1 with line tables, as OSS-Fuzz builds: half the compile time of -O2 -g, the same coverage.
# The libraries are unity translation units here too (cmake/unity.cmake).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMODALTYRE_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DMODALTYRE_BUILD_TESTS=OFF -DMODALTYRE_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target "${targets[@]}" ${FUZZ_JOBS:+-j "$FUZZ_JOBS"}

# UBSan reports are fatal (-fno-sanitize-recover) and come with a stack; ASan (leak checks
# included) keeps libFuzzer's defaults.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

findings_root=$build/fuzz-findings
work=$build/fuzz-work
rm -rf "$work" "$findings_root"
mkdir -p "$work" "$findings_root"

dict_of() {
  case $1 in
    fuzz_config | fuzz_sweep) echo "$root/tests/fuzz/dict/yaml.dict" ;;
    fuzz_uff58) echo "$root/tests/fuzz/dict/uff.dict" ;;
    fuzz_tir) echo "$root/tests/fuzz/dict/tir.dict" ;;
    *) echo "$root/tests/fuzz/dict/csv.dict" ;;
  esac
}

# One target: a scratch copy of its seeds (libFuzzer adds the inputs it finds there), its own
# scratch-file folder (TMPDIR) and its findings folder. Status 0: no finding.
fuzz_one() {
  local t=$1 corpus=$work/$1 findings=$findings_root/$1
  mkdir -p "$corpus" "$findings" "$work/tmp-$t"
  cp "$root/tests/fuzz/corpus/$t"/* "$corpus"/ && chmod u+w "$corpus"/*
  TMPDIR=$work/tmp-$t "$build/fuzz/$t" -max_total_time="$time_per_target" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -dict="$(dict_of "$t")" \
    -artifact_prefix="$findings/" "$corpus" >"$findings/log" 2>&1
}

report() {
  local t=$1 status=$2 log=$findings_root/$1/log
  if ((status == 0)); then
    echo "== $t: ok, $(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}') inputs in ${time_per_target}s, corpus $(ls "$work/$t" | wc -l) files"
  else
    echo "== $t: FINDING (exit $status; artifacts and full log in $findings_root/$t)"
    grep -E 'ERROR|SUMMARY|what\(\)|terminate|^ *#[0-9]+ .* in modaltyre|Test unit written|Base64' "$log" \
      | head -n 40 || tail -n 40 "$log"
    failed+=("$t")
  fi
}

# Up to FUZZ_PARALLEL targets at once (default: one per core); each uses one core.
parallel=${FUZZ_PARALLEL:-$(nproc 2>/dev/null || echo 1)}
echo "fuzzing ${#targets[@]} targets, ${time_per_target}s each, $parallel at a time"
failed=()
declare -A pid_target=()
for t in "${targets[@]}"; do
  while ((${#pid_target[@]} >= parallel)); do
    set +e; wait -n -p done_pid "${!pid_target[@]}"; status=$?; set -e
    report "${pid_target[$done_pid]}" "$status"; unset "pid_target[$done_pid]"
  done
  fuzz_one "$t" &
  pid_target[$!]=$t
done
while ((${#pid_target[@]})); do
  set +e; wait -n -p done_pid "${!pid_target[@]}"; status=$?; set -e
  report "${pid_target[$done_pid]}" "$status"; unset "pid_target[$done_pid]"
done

if ((${#failed[@]})); then
  echo "fuzzing found problems in: ${failed[*]} (reproduce: $build/fuzz/<target> <artifact>)" >&2
  exit 1
fi
echo "fuzzing: no findings in ${targets[*]}"
