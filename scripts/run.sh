#!/usr/bin/env bash
# The README's main-job command: sets up, builds, and starts the whole process graph
# (bus + seven agents) from launch/local.yaml on an OS-chosen loopback port. Ctrl-C stops it.
# Extra arguments go to `chatsim launch` (e.g. --mock motion=launch/mocks/motion.yaml).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
exec ./build/bin/chatsim launch launch/local.yaml --bus tcp://127.0.0.1:0 "$@"
