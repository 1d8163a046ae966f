#!/usr/bin/env bash
# Installs the Debian packages mjray needs (only those missing), then configures and builds
# into build/. Used by render.sh and test.sh; safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build pkg-config liblua5.4-dev libpng-dev libjpeg-dev zlib1g-dev libgtest-dev libembree-dev
          libopenexr-dev ffmpeg openmpi-bin libopenmpi-dev libxxhash-dev nlohmann-json3-dev)
# --watch: the HTTP server (header-only), and the browser that its test drives
packages+=(libcpp-httplib-dev chromium)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

build_type=${MJRAY_BUILD_TYPE:-Release}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$build_type" >/dev/null
cmake --build build --parallel "$(nproc)"
