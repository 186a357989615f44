#!/usr/bin/env bash
# The README's test command: sets up, builds and runs every test (unit and integration), then
# a short fuzzing run of every libFuzzer target (15 s each; scripts/fuzz.sh for longer runs).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
(cd build && ctest --output-on-failure --parallel "$(nproc)")
./scripts/fuzz.sh "${CHATSIM_FUZZ_SECONDS:-15}"
