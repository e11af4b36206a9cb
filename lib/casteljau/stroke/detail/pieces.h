// Internal to the stroker (not installed): the subpaths a stroke outlines,
// in flat buffers kept from stroke to stroke, and the memory reservation
// they grow under.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/flatten/vertex.h"
#include "casteljau/geom/rect.h"
#include "casteljau/stroke/stroker.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace casteljau::stroke_detail {

// The working memory the buffers are counted at (stroker.h,
// set_memory_budget): 80 bytes per element of the largest (a point on its way
// to coverage: itself, its edge and its sorted edge, with vectors' slack; a
// dash piece is a segment of up to 72 bytes; a sample 40).
constexpr std::size_t kElementBytes = 80;
// Elements below which nothing is reserved (1.3 MB): the tiger's largest
// stroke holds about 2,000 points, so ordinary strokes cost no atomic.
constexpr std::size_t kUnreserved = std::size_t(1) << 14;

// The buffers' reservation from the memory budget, grown as they grow and
// kept while they are; when the budget refuses, the call is `through` the
// gate instead (the budget's reserve entered it), and grows on unreserved.
struct Growth {
    bool (*reserve)(std::size_t) = nullptr;
    void (*unreserve)(std::size_t) = nullptr;
    std::size_t reserved = 0; // bytes
    bool through = false;     // this call's
    // A buffer holds n elements.
    void reached(std::size_t n) {
        if (n < kUnreserved || through || !reserve || n * kElementBytes <= reserved) return;
        // Twice as much as held, so that a growing buffer reserves a few times.
        const std::size_t more = std::max(n * kElementBytes, 2 * reserved) - reserved;
        if (reserve(more))
            reserved += more;
        else
            through = true;
    }
    void give_back() {
        if (unreserve && reserved) unreserve(reserved);
        reserved = 0;
    }
    // Whether a buffer of n elements may take one more within `limit`.
    bool may_grow(std::size_t n, std::size_t limit) {
        if (n >= limit) return false;
        reached(n);
        return true;
    }
};

// The subpaths to outline (the visible part of a path, or its dashes), with
// the Path building calls they are made by, in flat buffers that keep their
// capacity from stroke to stroke.
struct Pieces {
    struct Run {
        Point start;
        std::size_t begin, end; // segments[begin, end)
        bool closed;
        // Where the run has no length: the way its square cap faces (SVG 2,
        // 13.5: the path's direction at a zero-length dash; +x for a
        // subpath of no length).
        Vec2 along{1, 0};
    };
    std::vector<Segment> segments;
    std::vector<Run> runs;
    bool open = false;

    void clear() { segments.clear(), runs.clear(), open = false; }
    void move_to(Point p) {
        runs.push_back({p, segments.size(), segments.size(), false});
        open = true;
    }
    void append(const Segment& s) {
        if (!open) move_to(segment_start(s));
        segments.push_back(s);
        runs.back().end = segments.size();
    }
    // As Path::close: the closing line where the subpath ends elsewhere.
    void close() {
        if (!open) return;
        open = false;
        Run& r = runs.back();
        if (r.begin == r.end) return;
        if (const Point end = segment_end(segments.back()); end != r.start)
            append(Line{{end, r.start}});
        r.closed = true;
    }
    void add(const Subpath& sp) {
        move_to(sp.start);
        for (const Segment& s : sp.segments) append(s);
        if (sp.closed) close();
        open = false;
    }
    // The runs [first, end) are the parts of one closed subpath (cut by the
    // visible box, or its dashes), the first starting at its start and the
    // last ending there: through that point they are one stroke, with the
    // closing join and no caps. So the last run is moved in front of the
    // first (or, when they are one run, the whole subpath, closed).
    void rejoin(std::size_t first) {
        Run& f = runs[first];
        if (first + 1 == runs.size()) return void(f.closed = true);
        const Run last = runs.back();
        runs.pop_back();
        const auto at = [&](std::size_t i) { return segments.begin() + std::ptrdiff_t(i); };
        std::rotate(at(f.begin), at(last.begin), at(last.end));
        const std::size_t moved = last.end - last.begin;
        for (std::size_t r = first + 1; r < runs.size(); ++r)
            runs[r].begin += moved, runs[r].end += moved;
        f.start = last.start;
        f.end += moved;
    }
    std::span<const Segment> segments_of(const Run& r) const {
        return std::span<const Segment>(segments).subspan(r.begin, r.end - r.begin);
    }
};

/// The dash splitter's buffers, kept between strokes.
struct DashBuffers {
    std::vector<double> pattern; // the dash array, doubled when of odd length
    std::vector<FlatVertex> vertices;
};

// Splits the path into dashes (open subpaths) along its arc length, into
// `out`; dashes that lie outside `keep` are not emitted. Past kMaxDashes
// (stroker.h) dash boundaries, the path is stroked solid instead.
void dashed(const Path& path, const StrokeGeometry& st, double tol, const Rect& keep,
            DashBuffers& buffers, Pieces& out, Growth& growth);

// The parts of `path` within `keep`, as open or closed subpaths (the rules
// are pieces.cpp's).
void visible_part(const Path& path, const Rect& keep, Pieces& out, Growth& growth);

} // namespace casteljau::stroke_detail
