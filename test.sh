#!/usr/bin/env bash
# Set up (packages, build) and run every test through ctest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
