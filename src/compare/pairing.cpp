#include "compare/pairing.hpp"

#include <filesystem>
#include <map>
#include <tuple>

#include "compare/compare_image.hpp"
#include "core/error.hpp"
#include "output/manifest.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

using KeyTuple = std::tuple<std::string, std::string, int, std::string>;

std::map<KeyTuple, ManifestFile> manifest_files(const std::string& dir) {
    const fs::path manifest = fs::path(dir) / "manifest.json";
    std::error_code ec;
    if (!fs::is_regular_file(manifest, ec)) {
        std::string hint;
        for (const auto& entry : fs::directory_iterator(dir, ec))
            if (fs::is_regular_file(entry.path() / "manifest.json", ec)) {
                hint = "; did you mean " + entry.path().string() +
                       " (facet render writes into OUT/SCENE/)?";
                break;
            }
        throw Error(ExitCode::io_failure, dir + ": no manifest.json in this folder" + hint);
    }
    // A manifest that cannot be read is an I/O failure (exit 4); one that is
    // not facet's is bad input (exit 2), as in merge and video.
    Manifest m = read_manifest(manifest.string());
    std::map<KeyTuple, ManifestFile> files;
    for (ManifestFile& f : m.files) {
        // Compare would otherwise read (and an update write or delete)
        // files outside the folder.
        f.path = manifest_file_path(dir, f.path);
        files[{f.camera, f.pass, f.frame, f.format}] = f;
    }
    return files;
}

std::string format_of(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext.empty() ? "" : ext.substr(1);
}

}  // namespace

std::vector<FilePair> pair_files(const std::string& ref, const std::string& candidate) {
    std::error_code ec;
    const bool ref_dir = fs::is_directory(ref, ec), new_dir = fs::is_directory(candidate, ec);
    for (const std::string& path : {ref, candidate})
        if (!fs::exists(path, ec))
            throw Error(ExitCode::io_failure, path + ": no such file or folder");
    if (ref_dir != new_dir)
        throw Error(ExitCode::invalid_input,
                    "compare two output folders or two image files, not a folder and a file (" +
                        ref + ", " + candidate + ")");
    std::vector<FilePair> pairs;
    if (!ref_dir) {
        FilePair pair;
        pair.kind = guess_image_kind(ref);
        const ImageKind other = guess_image_kind(candidate);
        if (other != pair.kind)
            throw Error(ExitCode::comparison_failed,
                        "the files hold different kinds of image: " + ref + " is " +
                            image_kind_name(pair.kind) + ", " + candidate + " is " +
                            image_kind_name(other));
        pair.key = {"", image_kind_name(pair.kind), 0, format_of(candidate)};
        pair.ref_path = ref;
        pair.new_path = candidate;
        pairs.push_back(pair);
        return pairs;
    }
    const auto ref_files = manifest_files(ref), new_files = manifest_files(candidate);
    std::map<KeyTuple, FilePair> joined;
    for (const auto& [key, f] : ref_files) {
        FilePair& pair = joined[key];
        pair.key = {f.camera, f.pass, f.frame, f.format};
        pair.ref_path = f.path;
        pair.ref_sha256 = f.sha256;
    }
    for (const auto& [key, f] : new_files) {
        FilePair& pair = joined[key];
        pair.key = {f.camera, f.pass, f.frame, f.format};
        pair.new_path = f.path;
        pair.new_sha256 = f.sha256;
    }
    for (auto& [key, pair] : joined) {
        pair.kind = kind_for_pass(pair.key.pass, pair.key.format);
        pairs.push_back(pair);
    }
    return pairs;
}

}  // namespace facet
