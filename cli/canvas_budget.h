// CanvasBudget: a bound on the canvas memory of the files a batch renders at
// once. Workers rendering whole files in parallel each hold a frame (16
// bytes a pixel in float, up to kMaxPixels: 1 GiB); on a many-core machine
// a batch of large files would hold one per core, where rendering them one
// after the other holds one. A file waits until its canvas fits in the
// budget beside those in flight, and always starts when none is, so the
// largest file allowed still renders (alone), and no file waits forever:
// the ones in flight finish without waiting for anything.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>

namespace casteljau::cli {

class CanvasBudget {
  public:
    explicit CanvasBudget(std::size_t bytes) : limit_(bytes) {}

    /// Waits until `bytes` fit beside the bytes in flight (or none are).
    void acquire(std::size_t bytes) {
        std::unique_lock lock(mutex_);
        freed_.wait(lock, [&] { return used_ == 0 || used_ + bytes <= limit_; });
        used_ += bytes;
    }
    void release(std::size_t bytes) {
        {
            const std::lock_guard lock(mutex_);
            used_ -= bytes;
        }
        freed_.notify_all();
    }

    /// Holds `bytes` of a budget for its life.
    class Hold {
      public:
        Hold(CanvasBudget& b, std::size_t bytes) : budget_(b), bytes_(bytes) { b.acquire(bytes); }
        ~Hold() { budget_.release(bytes_); }
        Hold(const Hold&) = delete;
        Hold& operator=(const Hold&) = delete;

      private:
        CanvasBudget& budget_;
        std::size_t bytes_;
    };

  private:
    std::mutex mutex_;
    std::condition_variable freed_;
    std::size_t limit_;
    std::size_t used_ = 0;
};

} // namespace casteljau::cli
