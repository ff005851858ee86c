#include "timeline/bake_job.hpp"

namespace animator {

BakeJob::BakeJob(std::unique_ptr<Timeline> timeline, double until) : until_(until) {
    result_.timeline = std::move(timeline);
}

BakeJob::~BakeJob() {
    cancel_ = true;
    if (thread_.joinable()) thread_.join();
}

void BakeJob::start() {
    thread_ = std::thread([this] {
        try {
            result_.timeline->bake(until_, [this](double fraction) {
                progress_ = fraction;
                return !cancel_.load();
            });
            progress_ = 1.0;
        } catch (const BakeCancelled &) {
            result_.cancelled = true;
        } catch (const std::exception &e) {
            result_.error = e.what();
        }
        done_ = true;
    });
}

BakeJob::Result BakeJob::wait() {
    if (thread_.joinable()) thread_.join();
    return std::move(result_);
}

} // namespace animator
