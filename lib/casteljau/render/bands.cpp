#include "casteljau/render/bands.h"

#include <algorithm>
#include <cstring>
#include <thread>

namespace casteljau {

RenderStats BandRenderer::render(const Scene& scene, const Affine& view, Canvas& canvas,
                                 const RenderOptions& options, Premul background, int threads) {
    const int w = canvas.width(), h = canvas.height();
    const int bands = std::max(1, (h + kBandRows - 1) / kBandRows);
    const int n = std::clamp(threads, 1, bands);
    while (int(renderers_.size()) < n) renderers_.push_back(std::make_unique<Renderer>());
    bands_.resize(std::size_t(n));
    const PixelRect frame{0, 0, w, h};
    std::vector<RenderStats> stats(static_cast<std::size_t>(n));
    // Thread t renders bands t, t + n, t + 2n, ... into its own band canvas
    // and copies each into the frame (the rows of different bands are disjoint).
    const auto work = [&](int t) {
        Canvas& band = bands_[std::size_t(t)];
        RenderStats& total = stats[std::size_t(t)];
        for (int b = t; b < bands; b += n) {
            const int y0 = b * kBandRows, y1 = std::min(h, y0 + kBandRows);
            band.reset(w, y1 - y0, 0, y0, background);
            total += renderers_[std::size_t(t)]->render(scene, view, band, options, frame);
            for (int y = y0; y < y1; ++y)
                std::memcpy(static_cast<void*>(canvas.row(y)), band.row(y - y0),
                            std::size_t(w) * sizeof(Premul));
        }
    };
    if (n == 1) {
        work(0);
    } else {
        std::vector<std::thread> pool;
        for (int t = 0; t < n; ++t) pool.emplace_back(work, t);
        for (std::thread& th : pool) th.join();
    }
    RenderStats total;
    for (const RenderStats& s : stats) total += s;
    return total;
}

} // namespace casteljau
