#!/usr/bin/env bash
# Installs the Debian 12 packages Prism builds and tests with; does nothing when all are there.
set -euo pipefail
packages=(
    build-essential cmake pkg-config
    libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools
    libglfw3-dev libglm-dev libtinyobjloader-dev libopenimageio-dev openimageio-tools
    libgtest-dev libcli11-dev nlohmann-json3-dev libimgui-dev xvfb xauth
    spirv-tools # its optimizer folds the tracer's specialization (engine/vk/spirv_specialize.h)
    libxxhash-dev # the grid cache's keys and checksums (engine/cache)
    libjemalloc-dev # the tools' allocator: huge pages for big meshes (tools/common/allocator_config.cpp)
    python3 # tools/scripts/mutants.py (the list check is a test) and benchmark.py
    python3-matplotlib python3-numpy python3-openimageio # studies.py and its test
    time # GNU time: first_image.py's peak memory
    libembree-dev # only prism-gridbench's baseline: Prism builds without it
    slurm-wlm munge parallel # tools/farm: its tests start a local Slurm, and run GNU parallel
    pybind11-dev python3-dev python3-pytest # python/: `import prism` and its tests
    clang libclang-rt-14-dev # the fuzz preset (libFuzzer) that CI replays (tools/scripts/fuzz.sh)
    # xauth: xvfb-run (the prism-view tests) needs it; xvfb only recommends it
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all packages present"
    exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
