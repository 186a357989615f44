#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (in build-fuzz/) and runs each for SECONDS (default
# 60), starting from its corpus in fuzz/corpus/<target> (seeds and every crash ever fixed, so
# old crashes are re-checked first). A crash stops the run with its input in build-fuzz/crashes/.
#   scripts/fuzz.sh [SECONDS] [TARGET ...]      targets: message interpreter launch_file scene
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(message interpreter launch_file scene)
./scripts/install-deps.sh
if [ ! -f build-fuzz/build.ninja ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCHATSIM_FUZZ=ON -DCHATSIM_BUILD_TESTS=OFF >/dev/null
fi
ninja -C build-fuzz $(printf 'fuzz_%s ' "${targets[@]}")
mkdir -p build-fuzz/crashes
for t in "${targets[@]}"; do
  mkdir -p "fuzz/corpus/$t" "build-fuzz/corpus/$t"
  echo "fuzz: $t for ${seconds}s" >&2
  # New inputs go to the build tree's corpus; the committed corpus is read only.
  ASAN_OPTIONS=detect_leaks=0 ./build-fuzz/bin/"fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/crashes/$t-" -print_final_stats=0 \
    "build-fuzz/corpus/$t" "fuzz/corpus/$t" 2>&1 | grep -E "^(#[0-9]+.*DONE|==[0-9]+==|SUMMARY|artifact_prefix)|Done [0-9]+ runs" || true
  if ls build-fuzz/crashes/"$t"-* >/dev/null 2>&1; then
    echo "fuzz: $t CRASHED; inputs in build-fuzz/crashes/ (fix, then add them to fuzz/corpus/$t)" >&2
    exit 1
  fi
done
echo "fuzz: no crashes" >&2
