#!/usr/bin/env bash
# Regenerates the reference images of tests/golden/references/ from the current build, after
# a change that is meant to change images. Look at the new pictures before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target mjray_tests
MJRAY_UPDATE_REFERENCES=1 build/mjray_tests --gtest_filter='Golden/*Reference.*:BouncingBall.ContactFramesMatchTheirReferences'
git status --short tests/golden/references
