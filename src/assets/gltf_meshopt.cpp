#include "assets/gltf_meshopt.hpp"

#include <meshoptimizer.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "assets/gltf_accessors.hpp"
#include "core/limits.hpp"

namespace facet::gltf_detail {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";
// A decoded view may be as large as the largest file facet reads, no more:
// a hostile count must not allocate the machine away.
constexpr uint64_t kMaxDecodedBytes = kMaxImageFileBytes;

// A whole number from an extension object, or -1 when it is missing or not one.
int64_t whole(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key)) return -1;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) return -1;
    const double d = v.GetNumberAsDouble();
    if (!(d >= 0 && d <= 9.0e15) || d != static_cast<double>(static_cast<int64_t>(d))) return -1;
    return static_cast<int64_t>(d);
}

std::string text(const tinygltf::Value& object, const char* key, const char* fallback) {
    if (!object.Has(key) || !object.Get(key).IsString()) return fallback;
    return object.Get(key).Get<std::string>();
}

// One compressed view decoded (the extension's fields, checked first:
// libmeshoptimizer asserts rather than checks its sizes).
std::vector<uint8_t> decode_view(const tinygltf::Model& model, const tinygltf::Value& e,
                                 const std::string& path, const std::string& what) {
    const int64_t buffer = whole(e, "buffer"),
                  offset = std::max<int64_t>(0, whole(e, "byteOffset"));
    const int64_t length = whole(e, "byteLength"), stride = whole(e, "byteStride");
    const int64_t count = whole(e, "count");
    const std::string mode = text(e, "mode", ""), filter = text(e, "filter", "NONE");
    if (buffer < 0 || static_cast<size_t>(buffer) >= model.buffers.size())
        bad(path, what + ": no such buffer");
    const std::vector<unsigned char>& source = model.buffers[static_cast<size_t>(buffer)].data;
    if (length < 0 || offset + length > static_cast<int64_t>(source.size()))
        bad(path, what + ": its compressed bytes lie outside buffer " + std::to_string(buffer));
    if (count < 0 || stride < 1 || stride > 256)
        bad(path, what + ": count and byteStride (1 to 256) are required");
    if (static_cast<uint64_t>(count) * static_cast<uint64_t>(stride) > kMaxDecodedBytes)
        bad(path, what + ": decodes to more than the limit for a buffer");
    std::vector<uint8_t> out(static_cast<size_t>(count * stride));
    const unsigned char* bytes = source.data() + offset;
    const size_t size = static_cast<size_t>(length);
    int result = -1;
    if (mode == "ATTRIBUTES") {
        if (stride % 4 != 0)
            bad(path, what + ": ATTRIBUTES need a byteStride that is a multiple of 4");
        result = meshopt_decodeVertexBuffer(out.data(), static_cast<size_t>(count),
                                            static_cast<size_t>(stride), bytes, size);
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) bad(path, what + ": indices need a byteStride of 2 or 4");
        if (mode == "TRIANGLES" && count % 3 != 0)
            bad(path, what + ": TRIANGLES need a count that is a multiple of 3");
        result = mode == "TRIANGLES"
                     ? meshopt_decodeIndexBuffer(out.data(), static_cast<size_t>(count),
                                                 static_cast<size_t>(stride), bytes, size)
                     : meshopt_decodeIndexSequence(out.data(), static_cast<size_t>(count),
                                                   static_cast<size_t>(stride), bytes, size);
    } else {
        bad(path, what + ": unknown mode '" + mode + "' (ATTRIBUTES, TRIANGLES or INDICES)");
    }
    if (result != 0) bad(path, what + ": the compressed data does not decode");
    if (filter == "OCTAHEDRAL") {
        if (stride != 4 && stride != 8)
            bad(path, what + ": OCTAHEDRAL needs a byteStride of 4 or 8");
        meshopt_decodeFilterOct(out.data(), static_cast<size_t>(count),
                                static_cast<size_t>(stride));
    } else if (filter == "QUATERNION") {
        if (stride != 8) bad(path, what + ": QUATERNION needs a byteStride of 8");
        meshopt_decodeFilterQuat(out.data(), static_cast<size_t>(count),
                                 static_cast<size_t>(stride));
    } else if (filter == "EXPONENTIAL") {
        if (stride % 4 != 0)
            bad(path, what + ": EXPONENTIAL needs a byteStride that is a multiple of 4");
        meshopt_decodeFilterExp(out.data(), static_cast<size_t>(count),
                                static_cast<size_t>(stride));
    } else if (filter != "NONE") {
        bad(path, what + ": unknown filter '" + filter + "'");
    }
    return out;
}

}  // namespace

std::string without_fallback_buffers(const std::string& json) {
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("buffers") ||
        !doc["buffers"].is_array())
        return json;  // tinygltf reports what is wrong
    bool changed = false;
    for (auto& buffer : doc["buffers"]) {
        if (!buffer.is_object() || buffer.contains("uri")) continue;
        const auto ext = buffer.find("extensions");
        if (ext == buffer.end() || !ext->is_object() || !ext->contains(kExtension)) continue;
        // Three zero bytes: tinygltf refuses an empty data URI.
        buffer["uri"] = "data:application/octet-stream;base64,AAAA";
        buffer["byteLength"] = 3;
        changed = true;
    }
    return changed ? doc.dump() : json;
}

void decode_meshopt_views(tinygltf::Model& model, const std::string& path) {
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        const auto it = view.extensions.find(kExtension);
        if (it == view.extensions.end()) continue;
        const std::string what = "bufferView " + std::to_string(v) + " " + kExtension;
        if (!it->second.IsObject()) bad(path, what + " is not an object");
        std::vector<uint8_t> decoded = decode_view(model, it->second, path, what);
        tinygltf::Buffer plain;
        plain.data.assign(decoded.begin(), decoded.end());
        model.buffers.push_back(std::move(plain));
        view.buffer = static_cast<int>(model.buffers.size() - 1);
        view.byteOffset = 0;
        view.byteLength = decoded.size();
    }
}

}  // namespace facet::gltf_detail
