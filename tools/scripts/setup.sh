#!/usr/bin/env bash
# Quick start, step 1: install what is missing, build (release), render the showcase scene.
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j"$(nproc)"
mkdir -p out
build/bin/prism-render assets/scenes/showcase.scene -o out/showcase.exr --spp 4 --stats
build/bin/prism-render assets/scenes/showcase.scene -o out/showcase.png --spp 4 --quiet
echo "setup: wrote out/showcase.exr and out/showcase.png"
# `import prism` in Debian's python3: the module's build directory on the user's path.
site=$(/usr/bin/python3 -c 'import site; print(site.getusersitepackages())')
mkdir -p "$site"
echo "$PWD/build/python" >"$site/prism-build.pth"
/usr/bin/python3 -c 'import prism; print("setup: import prism works (prism", prism.__version__ + ")")'

