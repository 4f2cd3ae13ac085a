#pragma once
// manifest.json: what a run wrote, so tools and tests find outputs without
// guessing file names (docs/scene-format.md, "manifest.json").
#include <string>
#include <vector>

namespace facet {

struct ManifestFrame {
    int frame;
    std::string camera;
    double render_ms;
    double encode_ms;
};

struct ManifestFile {
    int frame;
    std::string camera;
    std::string pass;    // color, depth
    std::string format;  // png, exr
    std::string path;    // relative to the manifest
    std::string sha256;
};

struct Manifest {
    std::string scene;
    std::string style;
    int width = 0, height = 0;
    int threads = 0;
    std::vector<ManifestFrame> frames;
    std::vector<ManifestFile> files;
};

// Writes the manifest atomically. Entries of an existing manifest for the
// same scene and size, for (camera, frame) pairs this run did not render, are kept, so a
// sequence rendered in pieces (e.g. on several machines in turn) ends with
// one complete manifest.
void write_manifest(const std::string& path, Manifest manifest);

Manifest read_manifest(const std::string& path);

}  // namespace facet
