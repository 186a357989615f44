#!/usr/bin/env bash
# Installs the Debian (bookworm) packages ChatSim builds and tests with.
# Idempotent: prints nothing and changes nothing when every package is already there.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config ninja-build
  libzmq3-dev cppzmq-dev
  flatbuffers-compiler libflatbuffers-dev
  libeigen3-dev libopencv-dev libopenimageio-dev libopenexr-dev libembree-dev
  libcurl4-openssl-dev googletest libgtest-dev libgmock-dev
  zlib1g-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libspdlog-dev libcpp-httplib-dev
  libtinygltf-dev libtinyobjloader-dev libzstd-dev
  # OpenImageIO's and Imath's CMake files reference these: find_package fails without them.
  openimageio-tools python3-imath
  procps psmisc
  # English word lists: a word in them is never "corrected" as a typo (agents/language).
  wamerican wbritish
  # The web page's test drives Debian's Chromium (with the npm playwright-core).
  chromium
  # Fuzzing (scripts/fuzz.sh): clang and its libFuzzer runtime.
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# Node.js and npm (the MCAP test reads our recordings with the npm @mcap packages): keep the
# machine's own when it has one (it may not come from Debian), else take Debian's.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  missing+=(nodejs npm)
fi

[ ${#missing[@]} -eq 0 ] && exit 0

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${#missing[@]} package(s): ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done" >&2
