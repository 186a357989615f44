#!/usr/bin/env bash
# The README's test command: sets up, builds and runs every test (unit and integration).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)"
