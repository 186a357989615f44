#!/usr/bin/env bash
# The README's main-job command: sets up and builds, generates the embedded demo street
# (seeded, cached in build/demo-scene), and runs the flagship command through the process graph
# (chatsim plan starts the bus and the decision agents, and stops them after). The edit state
# is written to output/demo/edit.json. Pass your own command(s) as arguments to replace it.
# Rendering the result (background, deletion, foreground) is not built yet: see the README.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
scene=build/demo-scene
if [ ! -f "$scene/scene.json" ]; then
  ./build/bin/chatsim scene demo --out "$scene" --seed 1 --layout-only
fi
if [ "$#" -eq 0 ]; then
  set -- "Remove all cars, add a police car chasing a Porsche that drives the wrong way toward me, and move the view 5 m ahead" \
         "Now make the Porsche yellow and faster."
fi
mkdir -p output/demo
./build/bin/chatsim plan --scene "$scene" "$@" > output/demo/edit.json.tmp
mv output/demo/edit.json.tmp output/demo/edit.json
echo "edit state: $(pwd)/output/demo/edit.json"
