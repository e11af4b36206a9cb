#include "casteljau/render/bands.h"

#include <algorithm>
#include <cstring>
#include <thread>

namespace casteljau {

RenderStats BandRenderer::render(const Scene& scene, const Affine& view, Canvas& canvas,
                                 const RenderOptions& options, Premul background, int threads) {
    const int w = canvas.width(), h = canvas.height();
    const int n = std::clamp(threads, 1, std::max(1, h));
    while (int(renderers_.size()) < n) renderers_.push_back(std::make_unique<Renderer>());
    const PixelRect frame{0, 0, w, h};
    if (n == 1) {
        canvas.fill(background);
        return renderers_[0]->render(scene, view, canvas, options, frame);
    }
    bands_.resize(std::size_t(n));
    std::vector<RenderStats> stats(static_cast<std::size_t>(n));
    std::vector<std::thread> pool;
    for (int i = 0; i < n; ++i) {
        const int y0 = int(std::int64_t(h) * i / n), y1 = int(std::int64_t(h) * (i + 1) / n);
        pool.emplace_back([&, i, y0, y1] {
            Canvas& band = bands_[std::size_t(i)];
            band.reset(w, y1 - y0, 0, y0);
            band.fill(background);
            stats[std::size_t(i)] =
                renderers_[std::size_t(i)]->render(scene, view, band, options, frame);
            for (int y = y0; y < y1; ++y)
                std::memcpy(static_cast<void*>(canvas.row(y)), band.row(y - y0),
                            std::size_t(w) * sizeof(Premul));
        });
    }
    for (std::thread& t : pool) t.join();
    RenderStats total;
    for (const RenderStats& s : stats) {
        total.flatten.curves_in += s.flatten.curves_in;
        total.flatten.segments_out += s.flatten.segments_out;
        total.flatten.max_depth = std::max(total.flatten.max_depth, s.flatten.max_depth);
        total.flatten.max_error = std::max(total.flatten.max_error, s.flatten.max_error);
        total.flatten_ms += s.flatten_ms;
        total.raster_ms += s.raster_ms;
    }
    return total;
}

} // namespace casteljau
