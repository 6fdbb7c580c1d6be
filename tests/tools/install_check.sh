#!/bin/sh
# `cmake --install` into a fresh prefix, then the installed prism-render renders an installed
# scene with a mesh from outside the source and build trees, prism-merge puts two tiles of it
# together, and the installed Python module imports and renders too: nothing installed may look
# for files where they were built.
# Usage: install_check.sh BUILD_DIR
set -eu
build=$1
prefix=$(mktemp -d /tmp/prism-install-XXXXXX)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > "$prefix.log" 2>&1 || { cat "$prefix.log"; exit 1; }
rm -f "$prefix.log"
cd /
"$prefix/bin/prism-render" --version
"$prefix/bin/prism-render" "$prefix/share/prism/assets/scenes/bunny.scene" -o "$prefix/bunny.png" \
    --size 32x24 --quiet --no-cache
test -s "$prefix/bunny.png"
# prism-merge loads OpenImageIO late too, from the same installed plugin.
for tile in 0 1; do
    "$prefix/bin/prism-render" "$prefix/share/prism/assets/scenes/bunny.scene" --size 32x24 \
        --tile $tile/2 -o "$prefix/tile$tile.exr" --quiet --no-cache
done
"$prefix/bin/prism-merge" "$prefix/tile0.exr" "$prefix/tile1.exr" -o "$prefix/merged.png" --quiet
test -s "$prefix/merged.png"
for f in LICENSE THIRD_PARTY_NOTICES.md; do test -s "$prefix/share/doc/Prism/$f"; done
site=$(ls -d "$prefix"/lib/python3.*/dist-packages)
PYTHONPATH=$site /usr/bin/python3 -c "
import prism
scene = prism.load('$prefix/share/prism/assets/scenes/bunny.scene')
image = prism.Renderer().render(scene, 16, 12)['rgb']
assert image.shape == (12, 16, 3), image.shape
prism.write('$prefix/bunny.exr', image)
print('installed module', prism.__file__)
"
test -s "$prefix/bunny.exr"
echo "install check: ok ($prefix)"
