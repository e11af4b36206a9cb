// FlatVertex: one vertex of a flattened curve and the curve parameter it sits at.
// Every flattener emits the vertices after the curve's start, in order, ending
// with the curve's end point at t = 1 (bit for bit, so joined curves stay joined).
#pragma once

#include "casteljau/geom/point.h"

#include <cstddef>
#include <iterator>

namespace casteljau {

/// A vertex of a flattened curve and the curve parameter it lies at.
struct FlatVertex {
    Point p;
    double t = 0;
    /// Exact equality of every member.
    constexpr bool operator==(const FlatVertex&) const = default;
};

/// The range form of a flattener F with `bool next(FlatVertex&)`:
/// `for (FlatVertex v : F(curve, tol))` visits what the sink form emits.
template <class F>
class FlatVertexIterator {
  public:
    /// Input iterator tag: each vertex is produced once.
    using iterator_category = std::input_iterator_tag;
    /// Iterated values are vertices.
    using value_type = FlatVertex;
    /// Distance type (unused by an input iterator).
    using difference_type = std::ptrdiff_t;
    /// Pointer to a vertex.
    using pointer = const FlatVertex*;
    /// Reference to a vertex.
    using reference = const FlatVertex&;
    FlatVertexIterator() = default;
    /// An iterator at the first vertex after the start.
    explicit FlatVertexIterator(F* f) : f_(f) { ++*this; }
    /// The current vertex.
    const FlatVertex& operator*() const { return v_; }
    /// Advances to the next vertex.
    FlatVertexIterator& operator++() {
        if (!f_->next(v_)) f_ = nullptr;
        return *this;
    }
    /// Advances to the next vertex (post-increment, returns nothing).
    void operator++(int) { ++*this; }
    /// Exact equality of every member.
    bool operator==(const FlatVertexIterator& o) const { return f_ == o.f_; }

  private:
    F* f_ = nullptr;
    FlatVertex v_{};
};

/// The sink form of a flattener: sink(FlatVertex) for every vertex it yields.
template <class F, class Sink>
void drain_flattener(F&& flattener, Sink&& sink) noexcept {
    FlatVertex v;
    while (flattener.next(v)) sink(v);
}

/// Gives a flattener F (with `bool next(FlatVertex&)`) its range form:
/// `class F : public FlatVertexRange<F>`.
template <class F>
struct FlatVertexRange {
    /// The input iterator over F's vertices.
    using iterator = FlatVertexIterator<F>;
    /// The first vertex after the curve's start (the start itself is not emitted).
    iterator begin() { return iterator(static_cast<F*>(this)); }
    /// The end sentinel.
    iterator end() { return iterator(); }
};

/// The range and sink forms of a flattener F whose work is one loop,
/// `template <class Emit> bool F::run(Emit&& emit)`, calling emit(v) for each
/// vertex while emit returns true and returning whether it stopped at one:
/// `class F : public FlatVertexLoop<F>` (F befriends it). next() stops the
/// loop at each vertex; drain() runs it to the end in one call, so that the
/// loop's state stays in registers (1.1x guided's segments per second on the
/// bench/flatten corpus, pinned).
template <class F>
struct FlatVertexLoop : FlatVertexRange<F> {
    /// Writes the next vertex; false once the end point has been emitted.
    bool next(FlatVertex& out) noexcept {
        return static_cast<F*>(this)->run([&](const FlatVertex& v) {
            out = v;
            return false;
        });
    }
    /// The sink form: sink(v) for every remaining vertex.
    template <class Sink>
    void drain(Sink& sink) noexcept {
        static_cast<F*>(this)->run([&](const FlatVertex& v) {
            sink(v);
            return true;
        });
    }
};

} // namespace casteljau
