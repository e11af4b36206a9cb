#include "casteljau/render/bands.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace casteljau {

namespace {

// The units of work the threads take in turn: whole bands, then the last
// `halved` bands in two halves each. The threads end apart by up to the
// last unit one of them took, more when a core runs slower for a while
// (15-25% on a shared machine); halving the last units halves that wait.
// A half repeats the flattening of the shapes crossing its middle, so only
// the last units are halved. In order, the units cover each row once.
class BandUnits {
  public:
    struct Unit {
        int band, y0, y1; ///< the band whose node list it draws, and its rows
    };
    BandUnits(int bands, int halved, int height)
        : whole_(bands - std::min(bands, halved)), bands_(bands), height_(height) {}
    int count() const { return whole_ + 2 * (bands_ - whole_); }
    Unit at(int u) const {
        if (u < whole_) return {u, u * kBandRows, std::min(height_, (u + 1) * kBandRows)};
        const int band = whole_ + (u - whole_) / 2;
        const int y0 = band * kBandRows, y1 = std::min(height_, y0 + kBandRows);
        const int mid = (y0 + y1) / 2;
        return (u - whole_) % 2 == 0 ? Unit{band, y0, mid} : Unit{band, mid, y1};
    }

  private:
    int whole_, bands_, height_;
};

} // namespace

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

template <class Pixel>
RenderStats BandRenderer::render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                                 const RenderOptions& options, Premul background, int threads) {
    const int w = canvas.width(), h = canvas.height();
    const int bands = std::max(1, (h + kBandRows - 1) / kBandRows);
    const int n = std::clamp(threads, 1, bands);
    while (int(renderers_.size()) < n) renderers_.push_back(std::make_unique<Renderer>());
    for (int t = 0; t < n; ++t) renderers_[std::size_t(t)]->set_layer_budget(kMaxLayerBytes / n);
    auto& views = std::get<std::vector<BasicCanvas<Pixel>>>(bands_);
    views.resize(std::size_t(n));
    const PixelRect frame{0, 0, w, h};
    stats_.assign(std::size_t(n), RenderStats{});
    // Each thread takes the next band not yet taken, so a thread that drew
    // a light band goes on while another draws a dense one. A band's pixels
    // do not depend on which thread draws it. Bands are drawn in place: the
    // band canvas is a view of the band's rows of the frame (the rows of
    // different bands are disjoint, and a band's rows are contiguous).
    sort_into_bands(scene, view, h, bands);
    const BandUnits units{bands, n > 1 ? n : 0, h};
    std::atomic<int> next{0};
    const auto work = [&](int t) {
        BasicCanvas<Pixel>& band = views[std::size_t(t)];
        RenderStats& total = stats_[std::size_t(t)];
        for (int u = next++; u < units.count(); u = next++) {
            const BandUnits::Unit unit = units.at(u);
            if (unit.y0 == unit.y1) continue; // the empty half of a one-row band
            band.view_rows(canvas, unit.y0, unit.y1 - unit.y0, background);
            total += renderers_[std::size_t(t)]->render_nodes(band_nodes_[std::size_t(unit.band)],
                                                              view, band, options, frame);
            band.settle();
        }
    };
    if (n == 1) {
        work(0);
    } else {
        if (!pool_) pool_ = std::make_unique<WorkerPool>();
        pool_->run(n, work); // the calling thread is worker 0
    }
    for (int t = 0; t < n; ++t) renderers_[std::size_t(t)]->release_reserved();
    RenderStats total;
    for (const RenderStats& s : stats_) total += s;
    return total;
}

template RenderStats BandRenderer::render(const Scene&, const Affine&, Canvas&,
                                          const RenderOptions&, Premul, int);
template RenderStats BandRenderer::render(const Scene&, const Affine&, Canvas8&,
                                          const RenderOptions&, Premul, int);

} // namespace casteljau
