#include "post/resolve.hpp"

#include <algorithm>

namespace facet {

void resolve_supersampled(const ColorImage& color, const DepthImage& depth, int k,
                          HalfColorImage& out_color, DepthImage& out_depth, ThreadPool& pool) {
    const float weight = 1.0f / static_cast<float>(k * k);
    // Rows are independent, and each sum runs in the same order whatever
    // thread does it: identical results for any thread count.
    pool.parallel_for(static_cast<size_t>(out_color.height), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < out_color.width; ++x) {
            glm::vec4 sum(0.0f);
            float nearest = depth.at(x * k, y * k);
            for (int sy = 0; sy < k; ++sy)
                for (int sx = 0; sx < k; ++sx) {
                    sum += color.at(x * k + sx, y * k + sy);
                    nearest = std::min(nearest, depth.at(x * k + sx, y * k + sy));
                }
            out_color.at(x, y) = to_half(sum * weight);
            out_depth.at(x, y) = nearest;
        }
    });
}

}  // namespace facet
