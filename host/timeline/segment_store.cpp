#include "timeline/segment_store.hpp"

#include <algorithm>

namespace animator {

namespace {

// Below this many, space left in the index array or the log is never worth a compaction.
constexpr std::size_t kSlack = std::size_t{1} << 16;

} // namespace

void SegmentStore::reset(std::size_t models) {
    runs_.assign(models, Run{});
    chunks_.clear();
    chunk_at_.clear();
    models_.clear();
    models_.shrink_to_fit();
    logged_ = filed_ = 0;
    index_.clear();
    index_.shrink_to_fit();
    live_ = 0;
}

void SegmentStore::add_chunk() {
    chunks_.emplace_back().resize(SegmentSpan::kChunk); // (unwritten: huge_pages.hpp)
    chunk_at_.push_back(chunks_.back().data());
}

// The room a run takes after `more` segments: as now if they fit, else (it moves) exactly them
// for a run that had none, or the larger of what it needs and twice its room.
std::size_t SegmentStore::room_for(const Run &r, std::uint32_t more) {
    if (more == 0 || r.size + more <= r.capacity) return r.capacity;
    return r.capacity == 0 ? more : std::max<std::size_t>(r.size + more, 2 * std::size_t{r.capacity});
}

void SegmentStore::file() {
    if (filed_ == logged_) return;
    std::vector<std::uint32_t> count(runs_.size(), 0);
    for (std::size_t k = filed_; k < logged_; ++k) ++count[models_[k]];
    make_room(count);
    for (std::size_t k = filed_; k < logged_; ++k) {
        Run &r = runs_[models_[k]];
        index_[r.begin + r.size++] = static_cast<std::uint32_t>(k);
    }
    live_ += logged_ - filed_;
    filed_ = logged_;
}

void SegmentStore::make_room(const std::vector<std::uint32_t> &count) {
    // The runs that must move (to the end, with room to grow) and the room they take.
    std::size_t moved = 0;
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        const std::size_t room = room_for(runs_[m], count[m]);
        if (room != runs_[m].capacity) moved += room;
    }
    const std::size_t live = live_ + (logged_ - filed_);
    // Once the space left behind by moved runs would pass what is used, or the log holds more
    // segments dropped by re-bakes than kept, the store is rebuilt tight (each run as large as it
    // will be now, moved ones with room to double).
    if (index_.size() + moved > 2 * live + kSlack || logged_ - live > live + kSlack) {
        compact_with(count);
        return;
    }
    if (moved == 0) return;
    std::size_t end = index_.size();
    index_.resize(end + moved);
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        Run &r = runs_[m];
        const std::size_t room = room_for(r, count[m]);
        if (room == r.capacity) continue;
        std::copy(index_.data() + r.begin, index_.data() + r.begin + r.size, index_.data() + end);
        r.begin = end;
        r.capacity = static_cast<std::uint32_t>(room);
        end += room;
    }
}

void SegmentStore::compact_with(const std::vector<std::uint32_t> &count) {
    SegmentStore tight; // its log: the runs' segments model after model, then those not filed
    tight.models_.reserve(live_ + (logged_ - filed_));
    tight.index_.resize(live_ + (logged_ - filed_));
    std::size_t end = 0;
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        Run &r = runs_[m];
        for (std::uint32_t k = 0; k < r.size; ++k) {
            tight.index_[end + k] = static_cast<std::uint32_t>(tight.logged_);
            tight.log(SegmentSpan::segment(chunk_at_.data(), index_[r.begin + k]));
        }
        r.begin = end;
        r.capacity = r.size + count[m];
        end += r.capacity;
    }
    const std::size_t filed = tight.logged_;
    for (std::size_t k = filed_; k < logged_; ++k)
        tight.log(SegmentSpan::segment(chunk_at_.data(), static_cast<std::uint32_t>(k)));
    chunks_ = std::move(tight.chunks_);
    chunk_at_ = std::move(tight.chunk_at_);
    models_ = std::move(tight.models_);
    index_ = std::move(tight.index_);
    filed_ = filed;
    logged_ = tight.logged_;
}

void SegmentStore::truncate(double from) {
    file();
    for (Run &r : runs_) {
        std::uint32_t *begin = index_.data() + r.begin, *end = begin + r.size;
        std::uint32_t *kept = std::remove_if(begin, end, [&](std::uint32_t k) {
            return SegmentSpan::segment(chunk_at_.data(), k).t0 >= from;
        });
        live_ -= static_cast<std::size_t>(end - kept);
        r.size = static_cast<std::uint32_t>(kept - begin);
        if (r.size == 0) continue;
        const std::uint32_t last = begin[r.size - 1];
        ani_motion_segment &s =
            chunk_at_[last >> SegmentSpan::kChunkBits][last & (SegmentSpan::kChunk - 1)];
        if (s.t1 > from) s.t1 = from;
    }
    if (live_ == 0) { // (a bake from the start: the log starts again, its chunks kept)
        models_.clear();
        logged_ = filed_ = 0;
    }
}

std::vector<std::vector<ani_motion_segment>> SegmentStore::lists() const {
    std::vector<std::vector<ani_motion_segment>> lists(runs_.size());
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        const SegmentSpan s = (*this)[m];
        lists[m].assign(s.begin(), s.end());
    }
    return lists;
}

void SegmentStore::assign(const std::vector<std::vector<ani_motion_segment>> &lists) {
    reset(lists.size());
    for (std::size_t m = 0; m < lists.size(); ++m)
        for (ani_motion_segment s : lists[m]) {
            s.model = static_cast<std::uint32_t>(m);
            log(s);
        }
    file();
}

} // namespace animator
