// FixedStack: the explicit stack of a subdivision loop, in inline storage
// that is never cleared.
//
// Subdivision runs per curve, per band and per flattened vertex, and its
// stack is sized for the depth cap (41 pieces for the culling subdivision),
// while a typical run holds two or three. A std::array of curves would be
// zero-initialised on every run (Point and the curve types initialise their
// members), which cost more than the subdivision itself: a fifth of the
// stroke sampler's time per vertex on thin strokes (bench/render). Only
// pushed slots are ever read.
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <type_traits>

namespace casteljau {

/// At most N values of a trivially copyable T, pushed and popped; the caller's
/// depth cap keeps the count within N (checked in debug builds).
template <class T, std::size_t N>
class FixedStack {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

  public:
    FixedStack() noexcept {}
    /// Whether nothing is pushed.
    bool empty() const noexcept { return size_ == 0; }
    /// Pushes v. Precondition: fewer than N values are held.
    void push(const T& v) noexcept {
        assert(size_ < N);
        slots_[size_++].value = v;
    }
    /// Removes and returns the last value pushed. Precondition: not empty.
    T pop() noexcept {
        assert(size_ > 0);
        return slots_[--size_].value;
    }

  private:
    union Slot {
        Slot() noexcept {}
        T value;
    };
    std::array<Slot, N> slots_;
    std::size_t size_ = 0;
};

} // namespace casteljau
