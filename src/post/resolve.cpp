#include "post/resolve.hpp"

#include <algorithm>

#include <glm/vec3.hpp>

namespace facet {

void resolve_supersampled(const SampleImages& in, const ResolvedImages& out, ThreadPool& pool) {
    const int k = in.k;
    const float weight = 1.0f / static_cast<float>(k * k);
    const glm::vec4 bg = in.background;
    // Rows are independent, and each sum runs in the same order whatever
    // thread does it: identical results for any thread count.
    pool.parallel_for(static_cast<size_t>(out.color.height), [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < out.color.width; ++x) {
            glm::vec4 sum(0.0f), over_nothing(0.0f), lines(0.0f);
            float alpha = 0.0f;
            float nearest = in.depth.at(x * k, y * k);
            for (int sy = 0; sy < k; ++sy)
                for (int sx = 0; sx < k; ++sx) {
                    const int at_x = x * k + sx, at_y = y * k + sy;
                    const glm::vec4& c = in.color.at(at_x, at_y);
                    sum += glm::vec4(glm::vec3(c), 0.0f);
                    alpha += c.a + bg.a * (1.0f - c.a);
                    if (out.alpha)
                        over_nothing += glm::vec4(glm::vec3(c) - glm::vec3(bg) * (1.0f - c.a), c.a);
                    if (out.lines) lines += in.lines->at(at_x, at_y);
                    nearest = std::min(nearest, in.depth.at(at_x, at_y));
                }
            sum.a = alpha;
            out.color.at(x, y) = to_half(sum * weight);
            out.depth.at(x, y) = nearest;
            if (out.alpha) out.alpha->at(x, y) = to_half(over_nothing * weight);
            if (out.lines) out.lines->at(x, y) = to_half(lines * weight);
        }
    });
}

}  // namespace facet
