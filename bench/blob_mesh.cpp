// The benchmark's blobs: an icosphere subdivided `levels` times (20 * 4^levels
// triangles), each vertex moved along its direction by a smooth function of
// it, so the surface is round but no two blobs are alike. A seed picks the
// function; scripts/bench.sh --seed makes meshes no earlier run has seen.
// Written as OBJ with texture coordinates (a spherical map), and a
// procedural texture for the textured case.
#include "blob_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "output/atomic_file.hpp"
#include "output/encoders.hpp"

namespace facet_bench {
namespace {

struct Icosphere {
    std::vector<glm::dvec3> directions;  // unit
    std::vector<uint32_t> indices;       // counter-clockwise seen from outside
};

Icosphere icosphere(int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Icosphere s;
    for (glm::dvec3 v :
         {glm::dvec3(-1, t, 0), glm::dvec3(1, t, 0), glm::dvec3(-1, -t, 0), glm::dvec3(1, -t, 0),
          glm::dvec3(0, -1, t), glm::dvec3(0, 1, t), glm::dvec3(0, -1, -t), glm::dvec3(0, 1, -t),
          glm::dvec3(t, 0, -1), glm::dvec3(t, 0, 1), glm::dvec3(-t, 0, -1), glm::dvec3(-t, 0, 1)})
        s.directions.push_back(glm::normalize(v));
    s.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
            auto [it, inserted] = midpoints.try_emplace(key, 0);
            if (inserted) {
                it->second = static_cast<uint32_t>(s.directions.size());
                s.directions.push_back(glm::normalize(s.directions[a] + s.directions[b]));
            }
            return it->second;
        };
        std::vector<uint32_t> next;
        next.reserve(s.indices.size() * 4);
        for (size_t i = 0; i < s.indices.size(); i += 3) {
            const uint32_t a = s.indices[i], b = s.indices[i + 1], c = s.indices[i + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            for (uint32_t v : {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca}) next.push_back(v);
        }
        s.indices = std::move(next);
    }
    return s;
}

}  // namespace

void write_blob_obj(const std::string& path, int levels, uint32_t seed) {
    if (levels < 0 || levels > 9) throw std::invalid_argument("blob levels must be 0..9");
    const Icosphere sphere = icosphere(levels);
    // Three plane waves in random directions: smooth, and different per seed.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), phase(0.0, 6.283185307179586),
        frequency(2.0, 4.0);
    struct Wave {
        glm::dvec3 direction;
        double frequency, phase;
    };
    std::vector<Wave> waves;
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 d(unit(rng), unit(rng), unit(rng));
        if (glm::length(d) < 1e-3) d = glm::dvec3(0, 1, 0);
        waves.push_back({glm::normalize(d), frequency(rng), phase(rng)});
    }
    std::string text;
    text.reserve(sphere.directions.size() * 64 + sphere.indices.size() * 12);
    char line[160];
    text += "# facet benchmark blob: icosphere level " + std::to_string(levels) + ", seed " +
            std::to_string(seed) + "\n";
    for (const glm::dvec3& d : sphere.directions) {
        double r = 1.0;
        for (const Wave& w : waves)
            r += 0.06 * std::sin(w.frequency * glm::dot(d, w.direction) + w.phase);
        std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", d.x * r, d.y * r, d.z * r);
        text += line;
    }
    for (const glm::dvec3& d : sphere.directions) {
        // Spherical map: u round the Y axis, v from the north pole down.
        const double u = 0.5 + std::atan2(d.z, d.x) / 6.283185307179586;
        const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / 3.141592653589793;
        std::snprintf(line, sizeof line, "vt %.6f %.6f\n", u, 1.0 - v);
        text += line;
    }
    for (size_t i = 0; i < sphere.indices.size(); i += 3) {
        const uint32_t a = sphere.indices[i] + 1, b = sphere.indices[i + 1] + 1,
                       c = sphere.indices[i + 2] + 1;
        std::snprintf(line, sizeof line, "f %u/%u %u/%u %u/%u\n", a, a, b, b, c, c);
        text += line;
    }
    facet::write_file_atomically(path, text);
}

void write_blob_texture(const std::string& path, int size) {
    // Stripes and rings in two colours, with fine detail that mipmapping
    // has to filter.
    facet::ColorImage image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = (x + 0.5) / size, v = (y + 0.5) / size;
            const double stripes = 0.5 + 0.5 * std::sin(u * 6.283185307179586 * 24);
            const double rings = 0.5 + 0.5 * std::sin(v * 6.283185307179586 * 12);
            const double fine = ((x / 2 + y / 2) % 2) ? 0.9 : 1.0;
            const float a = static_cast<float>(stripes * rings * fine);
            image.at(x, y) = glm::vec4(0.9f * a + 0.1f, 0.5f * a + 0.2f, 0.2f + 0.1f * a, 1.0f);
        }
    facet::write_file_atomically(path, facet::encode_png_color(image, 6));
}

}  // namespace facet_bench
