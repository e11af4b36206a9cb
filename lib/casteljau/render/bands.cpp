#include "casteljau/render/bands.h"

#include <algorithm>
#include <atomic>
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
    stats_.assign(std::size_t(n), RenderStats{});
    // Each thread takes the next band not yet taken, so a thread that drew
    // a light band goes on while another draws a dense one. A band's pixels
    // do not depend on which thread draws it. Bands are drawn in place: the
    // band canvas is a view of the band's rows of the frame (the rows of
    // different bands are disjoint, and a band's rows are contiguous).
    std::atomic<int> next{0};
    const auto work = [&](int t) {
        Canvas& band = bands_[std::size_t(t)];
        RenderStats& total = stats_[std::size_t(t)];
        for (int b = next++; b < bands; b = next++) {
            const int y0 = b * kBandRows, y1 = std::min(h, y0 + kBandRows);
            band.view_rows(canvas, y0, y1 - y0, background);
            total += renderers_[std::size_t(t)]->render(scene, view, band, options, frame);
            band.settle();
        }
    };
    // The calling thread is worker 0: n - 1 threads are started per frame.
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& th : pool) th.join();
    RenderStats total;
    for (const RenderStats& s : stats_) total += s;
    return total;
}

} // namespace casteljau
