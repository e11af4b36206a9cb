#include "casteljau/render/bands.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace casteljau {

void BandRenderer::sort_into_bands(const Scene& scene, const Affine& view, int height, int bands) {
    if (int(band_nodes_.size()) < bands) band_nodes_.resize(std::size_t(bands));
    for (int b = 0; b < bands; ++b) band_nodes_[std::size_t(b)].clear();
    for (const Node& n : scene.root.children) {
        const Rect box = Renderer::node_reach_box(n, view);
        // Left out only where provably outside every band, as draw_shape
        // tests a band: box.y1 <= its top or box.y0 >= its bottom. The rows
        // are clamped to the frame first (a NaN end takes the frame's end).
        if (box.y1 <= 0 || box.y0 >= double(height)) continue;
        const double y0 = box.y0 >= 0 ? box.y0 : 0.0;
        const double y1 = box.y1 <= double(height) ? box.y1 : double(height);
        const int first = int(y0) / kBandRows;
        const int last = std::min(bands - 1, std::max(0, int(std::ceil(y1)) - 1) / kBandRows);
        for (int b = first; b <= last; ++b) band_nodes_[std::size_t(b)].push_back(&n);
    }
}

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
    sort_into_bands(scene, view, h, bands);
    std::atomic<int> next{0};
    const auto work = [&](int t) {
        Canvas& band = bands_[std::size_t(t)];
        RenderStats& total = stats_[std::size_t(t)];
        for (int b = next++; b < bands; b = next++) {
            const int y0 = b * kBandRows, y1 = std::min(h, y0 + kBandRows);
            band.view_rows(canvas, y0, y1 - y0, background);
            total += renderers_[std::size_t(t)]->render_nodes(band_nodes_[std::size_t(b)], view,
                                                              band, options, frame);
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
