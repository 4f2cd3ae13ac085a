#include "fuzz_targets.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "assets/mesh.hpp"
#include "assets/texture.hpp"
#include "core/error.hpp"
#include "scene/scene_desc.hpp"

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

bool run_target(const std::string& target, const uint8_t* data, size_t size) {
    if (target == "scene")
        fuzz_scene(data, size);
    else if (target == "obj")
        fuzz_obj(data, size);
    else if (target == "gltf")
        fuzz_gltf(data, size);
    else if (target == "texture")
        fuzz_texture(data, size);
    else
        return false;
    return true;
}

}  // namespace facet::fuzz
