#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each, from seed corpora copied into a temporary
# folder: small meshes of ../shared/models, the corpus and project scenes, and tests/fuzz/seeds.
#
#   tests/fuzz/run.sh SECONDS [TARGET...]     (default targets: fuzz_obj fuzz_image fuzz_scene)
#
# Environment: MJRAY_FUZZ_BUILD (build folder, default build-fuzz; configured and built here
# with clang when needed), MJRAY_FUZZ_OUT (logs and crash inputs, default $MJRAY_FUZZ_BUILD/fuzz-out),
# MJRAY_FUZZ_JOBS (targets run at once, default the number of cores), MJRAY_SHARED_DIR.
# Prints one line of figures per target; exits 1 when a target found a crash, leak or timeout.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD

seconds=${1:?usage: tests/fuzz/run.sh SECONDS [TARGET...]}
shift
targets=("$@")
((${#targets[@]})) || targets=(fuzz_obj fuzz_image fuzz_scene)
build=${MJRAY_FUZZ_BUILD:-build-fuzz}
out=${MJRAY_FUZZ_OUT:-$build/fuzz-out}
jobs=${MJRAY_FUZZ_JOBS:-$(nproc)}
shared=${MJRAY_SHARED_DIR:-$root/../shared}

# Build the targets (instrumented with ASan + UBSan and libFuzzer coverage).
if [ ! -f "$build/CMakeCache.txt" ]; then
  clang=$(command -v clang++ || command -v clang++-14 || true)
  [ -n "$clang" ] || { echo "fuzz: clang++ is missing (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 2; }
  cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$clang" -DMJRAY_FUZZ=ON -DBUILD_TESTING=OFF \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build" --target "${targets[@]}" --parallel "$(nproc)" >/dev/null

work=$(mktemp -d "${TMPDIR:-/tmp}/mjray-fuzz-XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# Copies the files that `find ARGS` lists into corpus folder $1 (names made unique).
seed() {
  local corpus=$1
  shift
  mkdir -p "$corpus"
  local n=0
  while IFS= read -r -d '' file; do
    n=$((n + 1))
    cp "$file" "$corpus/seed-$n-$(basename "$file")"
  done < <(find "$@" -print0 2>/dev/null)
}

seed_corpus() {
  local target=$1 corpus=$work/$1
  case $target in
    fuzz_obj)
      seed "$corpus" "$shared/models" "$shared/corpus" scenes -name '*.obj' -size -50k -type f ;;
    fuzz_image)
      seed "$corpus" tests/fuzz/seeds/image scenes "$shared/models" -type f -size -200k \
        \( -name '*.png' -o -name '*.jpg' -o -name '*.jpeg' -o -name '*.ppm' \) ;;
    fuzz_scene)
      seed "$corpus" "$shared/corpus" scenes tests/fuzz/seeds/scene -name '*.lua' -size -50k -type f ;;
  esac
  mkdir -p "$corpus"
}

# Runs one target; its log is $out/TARGET.log, crash inputs $out/TARGET-crash-*.
run_target() {
  local target=$1
  local -a extra=()
  [ -f "tests/fuzz/$target.dict" ] && extra+=("-dict=tests/fuzz/$target.dict")
  seed_corpus "$target"
  rm -f "$out/$target"-{crash,leak,timeout,oom,slow-unit}-*
  # -timeout: an input running longer than 20 s is a hang; -rss_limit_mb: more than 2 GiB
  # for one input is a finding (the scene target's own Lua cap is far lower).
  "$build/$target" "$work/$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$out/$target-" "${extra[@]}" >"$out/$target.log" 2>&1 || true
}

summarise() {
  local target=$1 log=$out/$1.log
  local runs cov ft corpus findings
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | cut -d' ' -f2)
  corpus=$(grep -oE 'corp: [0-9]+/[0-9]+[a-zA-Z]*' "$log" | tail -1 | cut -d' ' -f2)
  findings=$(find "$out" -maxdepth 1 -name "$target-*" ! -name '*.log' | wc -l)
  printf '%-11s %4ss  executions %-10s cov %-6s ft %-7s corpus %-12s findings %s\n' \
    "$target" "$seconds" "${runs:-?}" "${cov:-?}" "${ft:-?}" "${corpus:-?}" "$findings"
  if ((findings)); then
    find "$out" -maxdepth 1 -name "$target-*" ! -name '*.log' | sed 's/^/  finding: /'
    grep -m3 -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | sed 's/^/  /' || true
    return 1
  fi
  if [ -z "$runs" ]; then
    echo "  $target did not finish; see $log"
    return 1
  fi
}

running=0
for target in "${targets[@]}"; do
  run_target "$target" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

status=0
for target in "${targets[@]}"; do summarise "$target" || status=1; done
exit $status
