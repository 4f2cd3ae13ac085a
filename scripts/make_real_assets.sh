#!/usr/bin/env bash
# Makes the real-world glTF test files in tests/assets/ from the demo assets
# with gltfpack (Debian's gltfpack, meshoptimizer 0.18), as web pipelines
# make them. The files are small and committed; this script says how they
# were made, and makes them again:
#   - *-quantized.glb: gltfpack's defaults (KHR_mesh_quantization);
#   - *-meshopt.glb:   gltfpack -cc (EXT_meshopt_compression, with its
#                      fallback buffer left empty, and quantization).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/tests/assets"
command -v gltfpack >/dev/null || { echo "make_real_assets: install gltfpack (apt-get install gltfpack)" >&2; exit 1; }
mkdir -p "$out"
for name in knot tentacle; do
    gltfpack -i "$root/scenes/assets/$name.glb" -o "$out/$name-quantized.glb"
    gltfpack -i "$root/scenes/assets/$name.glb" -o "$out/$name-meshopt.glb" -cc
done
ls -l "$out"
