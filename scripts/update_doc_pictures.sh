#!/usr/bin/env bash
# Renders the pictures of docs/scene-format.md (docs/images/*.png) from their scenes
# (docs/images/*.lua) with the options each scene's "Render:" line names. Look at them before
# committing.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target mjray_app
for scene in docs/images/*.lua; do
  options=$(sed -n 's/^-- Render: build\/mjray \(.*\)docs\/images\/.*/\1/p' "$scene")
  # shellcheck disable=SC2086  # the options are words
  build/mjray --quiet $options "$scene"
done
git status --short docs/images
