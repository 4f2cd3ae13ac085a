#!/usr/bin/env bash
# Makes the real-world test files in tests/assets/ as exporters and web
# pipelines make them: Blender 3.4's glTF and OBJ exporters (Debian's
# blender, run headless on scripts/blender_real_assets.py) write the files in
# tests/assets/blender/, and gltfpack (Debian's, meshoptimizer 0.18) packs
# those and the demo assets. The files are small and committed, so the tests
# need neither tool; this script says how they were made, and makes them
# again:
#   - blender/suzanne.{glb,obj}: a subdivided, triangulated Suzanne;
#   - blender/textured-sphere.glb: a checker through a Mapping node (scale 2);
#   - blender/keyed.glb: BoxAction, RigAction (armature), KeyAction (shape key);
#   - blender/features.glb: vertex colours, emission, an animated camera, lights;
#   - *-quantized.glb: gltfpack's defaults (KHR_mesh_quantization), -kn -km
#                      for the Blender files so names and materials stay;
#   - *-meshopt.glb:   gltfpack -cc (EXT_meshopt_compression, with its
#                      fallback buffer left empty, and quantization).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/tests/assets"
command -v gltfpack >/dev/null || { echo "make_real_assets: install gltfpack (apt-get install gltfpack)" >&2; exit 1; }
command -v blender >/dev/null || { echo "make_real_assets: install blender (apt-get install blender)" >&2; exit 1; }
mkdir -p "$out/blender"
blender -b --factory-startup --python "$root/scripts/blender_real_assets.py" -- "$out/blender" >/dev/null
for name in suzanne textured-sphere keyed features; do
    gltfpack -i "$out/blender/$name.glb" -o "$out/blender/$name-quantized.glb" -kn -km
    gltfpack -i "$out/blender/$name.glb" -o "$out/blender/$name-meshopt.glb" -kn -km -cc
done
for name in knot tentacle; do
    gltfpack -i "$root/scenes/assets/$name.glb" -o "$out/$name-quantized.glb"
    gltfpack -i "$root/scenes/assets/$name.glb" -o "$out/$name-meshopt.glb" -cc
done
ls -l "$out" "$out/blender"
