#!/usr/bin/env bash
# The CPU-side tests (scene text, OBJ and MTL readers, grid build and walk, the reference
# renderer, the cache) built with AddressSanitizer and UndefinedBehaviorSanitizer and run: any
# out-of-bounds access, leak or undefined behaviour fails. Vulkan is left out: the GPU tests run
# in the release build (tools/scripts/test.sh) with validation layers instead. CI runs this.
set -euo pipefail
cd "$(dirname "$0")/../.."
cmake --preset sanitize > /dev/null
cmake --build --preset sanitize -j"$(nproc)"
# detect_leaks: on by default on Linux, named so that it stays on.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 ctest --preset sanitize -j"$(nproc)" "$@"
