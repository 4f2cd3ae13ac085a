#include "fuzz_targets.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "assets/mesh.hpp"
#include "assets/texture.hpp"
#include "core/error.hpp"
#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"
#include "render/environment_file.hpp"
#include "scene/scene_desc.hpp"
#include "shade/environment_map.hpp"

namespace facet::fuzz {
namespace {

// Memory a fuzzed texture may claim: enough for real images, small enough
// that libFuzzer's RSS limit is never the one that stops it.
constexpr uint64_t kFuzzTextureBudget = uint64_t(256) << 20;

// A private folder for this process's inputs, made once. Files the input
// names (an OBJ's mtllib, a glTF's buffers) resolve inside it.
const std::string& work_folder() {
    static const std::string folder = [] {
        std::string base = (std::filesystem::temp_directory_path() / "facet-fuzz-XXXXXX").string();
        if (!::mkdtemp(base.data())) std::abort();
        return base;
    }();
    return folder;
}

std::string write_input(const std::string& name, const uint8_t* data, size_t size) {
    const std::string path = work_folder() + "/" + name;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

// Loads and drops the result: only errors other than facet::Error escape.
template <typename Load>
void expect_loaded_or_error(Load&& load) {
    try {
        load();
    } catch (const Error&) {
    }
}

}  // namespace

void fuzz_scene(const uint8_t* data, size_t size) {
    const std::string path = write_input("scene.yaml", data, size);
    SceneOptions options;
    options.style_dirs = {FACET_STYLES_DIR};
    expect_loaded_or_error([&] { load_scene(path, options); });
    expect_loaded_or_error([&] { load_style_file(path, options.style_dirs); });
}

void fuzz_obj(const uint8_t* data, size_t size) {
    const std::string path = write_input("input.obj", data, size);
    TextureBudget budget(kFuzzTextureBudget);
    AssetContext context;
    context.textures = &budget;
    expect_loaded_or_error([&] { load_mesh(path, context); });
}

void fuzz_gltf(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::string(reinterpret_cast<const char*>(data), 4) == "glTF";
    const std::string path = write_input(binary ? "input.glb" : "input.gltf", data, size);
    TextureBudget budget(kFuzzTextureBudget);
    AssetContext context;
    context.textures = &budget;
    expect_loaded_or_error([&] { load_mesh(path, context); });
}

void fuzz_texture(const uint8_t* data, size_t size) {
    const std::string path = write_input("input.png", data, size);
    TextureBudget budget(kFuzzTextureBudget);
    expect_loaded_or_error([&] { load_texture(path, &budget); });
}

void fuzz_environment(const uint8_t* data, size_t size) {
    // Told by content, never by name: a Radiance .hdr or an OpenEXR file.
    const std::string path = write_input("environment.img", data, size);
    Warnings warnings;
    expect_loaded_or_error([&] { pbr::read_environment_image(path, warnings); });
}

void fuzz_ply(const uint8_t* data, size_t size) {
    const std::string path = write_input("input.ply", data, size);
    TextureBudget budget(kFuzzTextureBudget);
    AssetContext context;
    context.textures = &budget;
    expect_loaded_or_error([&] { load_mesh(path, context); });
}

void fuzz_assimp(const uint8_t* data, size_t size) {
    // The first byte names the file (its bytes decide the reader first,
    // then the name); the rest is the file.
    if (size == 0) return;
    static const char* const names[] = {"input.stl", "input.fbx", "input.dae", "input.3ds"};
    const std::string path = write_input(names[data[0] % 4], data + 1, size - 1);
    TextureBudget budget(kFuzzTextureBudget);
    AssetContext context;
    context.textures = &budget;
    expect_loaded_or_error([&] { load_mesh(path, context); });
}

void fuzz_manifest(const uint8_t* data, size_t size) {
    const std::string path = write_input("manifest.json", data, size);
    expect_loaded_or_error([&] {
        // What facet reads back it must write back the same: the manifest
        // of a render that resumes, merges or is compared.
        const Manifest read = read_manifest(path);
        const std::string written = manifest_json(read, true);
        if (manifest_json(parse_manifest(written, path), true) != written) std::abort();
        if (!manifest_settings_difference(read, read).empty()) std::abort();
    });
    // The same bytes as a run's journal (a header line, then one line per image).
    expect_loaded_or_error([&] { read_journal(path); });
}

void fuzz_override(const uint8_t* data, size_t size) {
    // One -D per line, as a farm front-end would pass them, over a scene
    // with a keyed value, a light, an object and a style to walk into.
    SceneOptions options;
    options.style_dirs = {FACET_STYLES_DIR};
    const std::string text(reinterpret_cast<const char*>(data), size);
    expect_loaded_or_error([&] {
        size_t start = 0;
        while (start <= text.size()) {
            const size_t end = std::min(text.find('\n', start), text.size());
            options.overrides.push_back(parse_define(text.substr(start, end - start)));
            start = end + 1;
        }
        load_scene(FACET_OVERRIDE_SCENE, options);
    });
}

bool run_target(const std::string& target, const uint8_t* data, size_t size) {
    if (target == "scene")
        fuzz_scene(data, size);
    else if (target == "obj")
        fuzz_obj(data, size);
    else if (target == "gltf")
        fuzz_gltf(data, size);
    else if (target == "texture")
        fuzz_texture(data, size);
    else if (target == "environment")
        fuzz_environment(data, size);
    else if (target == "ply")
        fuzz_ply(data, size);
    else if (target == "assimp")
        fuzz_assimp(data, size);
    else if (target == "manifest")
        fuzz_manifest(data, size);
    else if (target == "override")
        fuzz_override(data, size);
    else
        return false;
    return true;
}

}  // namespace facet::fuzz
