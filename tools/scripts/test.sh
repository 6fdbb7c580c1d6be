#!/usr/bin/env bash
# Quick start, step 2: install what is missing, build (release), run every test on lavapipe
# with Vulkan validation layers on (any validation message fails a test).
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)" "$@"
