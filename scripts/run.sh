#!/usr/bin/env bash
# The README's main-job command: sets up and builds, renders the embedded demo street (seeded,
# path traced, cached in build/demo-scene), and runs the flagship command through all eight
# processes: "Remove all cars, add a police car chasing a Porsche that drives the wrong way
# toward me, and move the view 5 m ahead", then "Now make the Porsche yellow and faster."
# (chatsim run starts the processes and stops them after). The first run also trains the
# scene's radiance field (cached in ~/.cache/chatsim); later runs reuse both. The result
# (video, frames, depth, labels, edit.json) lands in output/demo. Pass your own command(s) as
# arguments to replace the example.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
scene=build/demo-scene
if [ ! -f "$scene/scene.json" ] || grep -q '"layout_only": true' "$scene/scene.json"; then
  # The images and LiDAR are enough here; benchmarks render their own copy with plates and views.
  ./build/bin/chatsim scene demo --out "$scene" --seed 1 --no-plates --no-views
fi
if [ "$#" -eq 0 ]; then
  set -- "Remove all cars, add a police car chasing a Porsche that drives the wrong way toward me, and move the view 5 m ahead" \
         "Now make the Porsche yellow and faster."
fi
./build/bin/chatsim run --scene "$scene" --out output/demo "$@"
echo "result: $(pwd)/output/demo (video: $(pwd)/output/demo/video.mp4)"
