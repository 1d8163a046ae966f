#!/usr/bin/env bash
# Renders the pictures of docs/scene-format.md (docs/images/*.png) from their scenes
# (docs/images/*.lua) with the options each scene's "Render:" line names, and the bouncing
# ball's GIF. Look at them before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target mjray_app
for scene in docs/images/*.lua; do
  options=$(sed -n 's/^-- Render: build\/mjray \(.*\)docs\/images\/.*/\1/p' "$scene")
  # shellcheck disable=SC2086  # the options are words
  build/mjray --quiet $options "$scene"
done
# The bouncing ball of README.md and docs/scene-format.md, as a GIF: every other frame at
# 240x135, at 12 frames per second (the animation's own pace).
frames=$(mktemp -d)
build/mjray --quiet -s 2 --size 240x135 --frames 1-96:2 --fps 12 --outdir "$frames" \
  --video docs/images/bouncing_ball.gif scenes/animation/bouncing_ball.lua
rm -rf "$frames"
git status --short docs/images
