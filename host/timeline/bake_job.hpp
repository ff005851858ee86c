// A bake on a worker thread, so the editor stays responsive: it reads the progress, may cancel,
// and takes the timeline back when the job is done. While the job runs the timeline is the
// job's alone; the editor keeps showing the timeline it had, then swaps. No state is shared
// but the progress and the cancel flag.
#pragma once

#include "timeline/timeline.hpp"

#include <atomic>
#include <memory>
#include <string>
#include <thread>

namespace animator {

class BakeJob {
  public:
    struct Result {
        std::unique_ptr<Timeline> timeline; // baked to `until`, or as far as before on failure
        bool cancelled = false;
        std::string error; // empty unless the backend failed
    };

    BakeJob(std::unique_ptr<Timeline> timeline, double until);
    ~BakeJob(); // cancels a running bake and waits for it
    BakeJob(const BakeJob &) = delete;
    BakeJob &operator=(const BakeJob &) = delete;

    void start();
    void cancel() { cancel_ = true; }
    double progress() const { return progress_; } // [0, 1]
    bool done() const { return done_; }
    // Waits for the job (start() must have been called) and hands the timeline back.
    Result wait();

  private:
    Result result_;
    double until_;
    std::thread thread_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancel_{false}, done_{false};
};

} // namespace animator
