// A batch on N threads: min(N, files) workers, each rendering whole files
// (parse, render, encode), one after the other, with a FileRenderer of its
// own (band renderer and canvases reused from file to file). Files are many
// and small in the usual batch, where a file's parse and encode run on one
// thread only and its bands are too few to share: whole files keep every
// core busy where bands cannot.
//
// Band threads: the N threads are tokens. A worker starting a file takes
// its share of the free ones: the free tokens divided among the files that
// could start now (the idle workers, at most the files not yet started),
// rounded down, at least one. So one file alone takes all N (as before
// batches: a single large file is not slower), two files on eight threads
// take four each, and a thousand files take one each. The tokens a file
// takes are back when it ends; no more than N are ever out, so the workers
// and their band threads never oversubscribe the cores. (A share is at
// least one: the free tokens never fall below the files that could start
// now. That holds at the start, N >= workers; a claim of F/k of F tokens
// leaves F(k-1)/k >= k-1, and one file fewer could start; an end gives
// back at least one token and lets at most one more file start.)
// The output does not depend on the share: bands are bit-identical on any
// number of threads (render/bands.h).
//
// Reports: a file's messages are printed together when it ends (workers
// end files in any order, and each message names its file); the records go
// to the sink in input order, each as soon as the files before it are done.
#include "render_batch.h"

#include "commands.h"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

namespace casteljau::cli {

namespace {

// The canvas bytes of the files in flight at once: those of the largest
// frame allowed in float (kMaxPixels, 16 bytes a pixel, 1 GiB). A batch of
// files that large renders one at a time, as it would have before batches.
constexpr std::size_t kBatchCanvasBytes = std::size_t(kMaxPixels) * sizeof(Premul);

class Batch {
  public:
    Batch(const RenderArgs& a, Premul background, const std::vector<RenderJob>& jobs, bool progress,
          const RecordSink& sink, int threads, int workers)
        : a_(a), background_(background), jobs_(jobs), progress_(progress), sink_(sink),
          free_threads_(threads), idle_workers_(workers), records_(jobs.size()),
          done_(jobs.size(), false) {}

    /// A worker's loop: files until none is left.
    void work() {
        FileRenderer files(a_, background_);
        while (const std::optional<Claim> c = claim())
            finish(*c, files.render(jobs_[c->job], c->threads, budget_));
    }

    int status() const { return status_; }

  private:
    struct Claim {
        std::size_t job;
        int threads;
    };

    std::optional<Claim> claim() {
        const std::lock_guard lock(mutex_);
        if (next_ == jobs_.size()) return std::nullopt;
        const int could_start = int(std::min(std::size_t(idle_workers_), jobs_.size() - next_));
        const int share = std::max(1, free_threads_ / could_start);
        free_threads_ -= share;
        --idle_workers_;
        return Claim{next_++, share};
    }

    void finish(const Claim& c, FileOutcome o) {
        const std::lock_guard lock(mutex_);
        free_threads_ += c.threads;
        ++idle_workers_;
        status_ = std::max(status_, o.status);
        ++finished_;
        if (progress_ && !o.log.text.empty()) std::fputs("\r\033[K", stderr);
        o.log.print();
        if (progress_)
            std::fprintf(stderr, "\r[%zu/%zu] %s\033[K", finished_, jobs_.size(),
                         jobs_[c.job].input.c_str());
        records_[c.job] = std::move(o.record);
        done_[c.job] = true;
        for (; emitted_ < jobs_.size() && done_[emitted_]; ++emitted_) {
            if (!records_[emitted_].empty()) sink_(records_[emitted_]);
            records_[emitted_] = std::string{};
        }
    }

    const RenderArgs& a_;
    const Premul background_;
    const std::vector<RenderJob>& jobs_;
    const bool progress_;
    const RecordSink& sink_;
    CanvasBudget budget_{kBatchCanvasBytes};
    std::mutex mutex_; ///< guards everything below
    int free_threads_;
    int idle_workers_;
    std::size_t next_ = 0;     ///< the first job not yet started
    std::size_t finished_ = 0; ///< jobs done
    std::size_t emitted_ = 0;  ///< the first job whose record is not yet out
    std::vector<std::string> records_;
    std::vector<bool> done_;
    int status_ = kExitOk;
};

} // namespace

int render_batch(const RenderArgs& a, Premul background, const std::vector<RenderJob>& jobs,
                 bool progress, const RecordSink& sink) {
    if (jobs.empty()) return kExitOk;
    const int threads = all_threads(a);
    const int workers = int(std::min(std::size_t(threads), jobs.size()));
    Batch batch(a, background, jobs, progress, sink, threads, workers);
    std::vector<std::thread> helpers;
    try {
        for (int w = 1; w < workers; ++w) helpers.emplace_back([&batch] { batch.work(); });
    } catch (const std::exception&) {
        // No thread (system_error) or no memory for its handle (bad_alloc):
        // fewer workers than planned, and the ones there are take every file;
        // letting it escape would destroy the started threads unjoined.
    }
    batch.work();
    for (std::thread& t : helpers) t.join();
    if (progress) std::fputs("\n", stderr);
    return batch.status();
}

} // namespace casteljau::cli
