// Working memory of strokes and filters: a budget the threads share, and
// beyond it one thread at a time.
//
// Why: hostile input can make a stroke's outline amplify a small file into
// gigabytes (round joins on a stroke 1e6 px wide, a circle 1e61 px tall,
// a million dashes), and a filter chain hold a gigabyte of images; the
// stroker's point limit and the filters' byte limit bound one call, but
// every thread of a frame, and every file of a batch, made its own calls at
// once: eight threads took 1.5 GB on such a stroke, four 2.6 GB on such a
// filter, and the CLI's default is a thread per core.
//
// How: a renderer reserves what its stroker's and filters' buffers grow to
// (an estimate in bytes) from kSharedBytes, and keeps the buffers and the
// reservation to the end of the frame (Renderer::release_reserved), so an
// idle renderer holds no share. When the budget has not enough left, the
// thread enters the gate instead, holds whatever the call takes (up to the
// call's own limits), and, once the stroke strip or filter chain is drawn,
// frees those buffers and leaves (LeaveGate in renderer.cpp). So the
// threads together hold at most kSharedBytes plus one call's worth,
// whatever their number, and ordinary
// files (strokes below 1.3 MB and chains below 4 MiB reserve nothing) never
// wait. The pictures do not change, only the order in which the heavy
// strokes and filters are drawn; a chain larger than the budget alone
// reallocates its images for every band.
//
// Invariants. The gate is one process-wide mutex with a per-thread depth, so
// a thread already through it passes again without waiting (a pattern
// tile's stroke drawn while the stroke it paints holds it). No thread waits
// on another while through it: it is left before the renderer returns from
// the stroke or filter, so neither a band's pool nor a batch's workers can
// deadlock on it. Fork: fork() waits until no other thread is through the
// gate (a pthread_atfork handler takes it), so a child never inherits a
// gate held by a thread it does not have. Reservations other threads held
// at the fork stay counted in the child, which then goes through the gate
// sooner: slower there, never unbounded.
#pragma once

#include <cstddef>

namespace casteljau::memory_gate {

/// The working memory all threads may hold outside the gate, together, by
/// default: 256 MiB.
inline constexpr std::size_t kSharedBytes = std::size_t(256) << 20;

/// Sets that budget for the process (a program that allows its renders
/// more or less memory; the tests, a small one). Reservations already held
/// stay; past the new budget, they only block new ones.
void set_budget(std::size_t bytes);

/// The budget now.
std::size_t budget();

/// Takes `bytes` from the shared budget and returns true; or, when it has
/// not that much left (or this thread is through the gate already), enters
/// the gate and returns false.
bool reserve(std::size_t bytes);

/// Gives back bytes that reserve() took.
void unreserve(std::size_t bytes);

/// Waits until no other thread is through the gate, then passes it (again,
/// one level deeper, when this thread already is).
void enter();

/// Leaves one level; the last one lets the next thread through.
void leave();

/// How many times this thread is through the gate (0: it is not).
int depth();

/// Bytes reserved from the budget, given back when reset or destroyed.
class Reservation {
  public:
    Reservation() = default;
    /// Takes over o's bytes.
    Reservation(Reservation&& o) noexcept : bytes_(o.bytes_) { o.bytes_ = 0; }
    /// Gives back its own bytes and takes over o's.
    Reservation& operator=(Reservation&& o) noexcept {
        if (this != &o) {
            reset();
            bytes_ = o.bytes_;
            o.bytes_ = 0;
        }
        return *this;
    }
    ~Reservation() { reset(); }

    /// Grows to at least `bytes` (reserve); false when the budget had not
    /// enough left, and this thread entered the gate instead.
    bool grow_to(std::size_t bytes) {
        if (bytes <= bytes_) return true;
        if (!reserve(bytes - bytes_)) return false;
        bytes_ = bytes;
        return true;
    }
    /// The bytes held.
    std::size_t bytes() const { return bytes_; }
    /// Gives everything back.
    void reset() {
        if (bytes_) unreserve(bytes_);
        bytes_ = 0;
    }

  private:
    std::size_t bytes_ = 0;
};

} // namespace casteljau::memory_gate
