#include "timeline/segment_store.hpp"

#include <algorithm>

namespace animator {

void SegmentStore::reset(std::size_t models) {
    runs_.assign(models, Run{});
    pool_.clear();
    pool_.shrink_to_fit();
    live_ = 0;
}

// The room a run takes after `more` segments: as now if they fit, else (it moves) exactly them
// for a run that had none, or the larger of what it needs and twice its room.
std::size_t SegmentStore::room_for(const Run &r, std::uint32_t more) {
    if (more == 0 || r.size + more <= r.capacity) return r.capacity;
    return r.capacity == 0 ? more : std::max<std::size_t>(r.size + more, 2 * std::size_t{r.capacity});
}

void SegmentStore::make_room(const std::vector<std::uint32_t> &count) {
    // The runs that must move (to the end, with room to grow) and the room they take.
    std::size_t moved = 0, added = 0;
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        added += count[m];
        const std::size_t room = room_for(runs_[m], count[m]);
        if (room != runs_[m].capacity) moved += room;
    }
    live_ += added;
    if (moved == 0) return;
    // Once the space left behind by moved runs would pass what is used, the store is rebuilt tight
    // (each run as large as it will be now, moved ones with room to double).
    if (pool_.size() + moved > 2 * live_ + (std::size_t{1} << 16)) {
        compact_with(count);
        return;
    }
    std::size_t end = pool_.size();
    pool_.resize(end + moved);
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        Run &r = runs_[m];
        const std::size_t room = room_for(r, count[m]);
        if (room == r.capacity) continue;
        std::copy(pool_.data() + r.begin, pool_.data() + r.begin + r.size, pool_.data() + end);
        r.begin = end;
        r.capacity = static_cast<std::uint32_t>(room);
        end += room;
    }
}

void SegmentStore::compact_with(const std::vector<std::uint32_t> &count) {
    Pool pool;
    pool.resize(live_);
    std::size_t end = 0;
    for (std::size_t m = 0; m < runs_.size(); ++m) {
        Run &r = runs_[m];
        std::copy(pool_.data() + r.begin, pool_.data() + r.begin + r.size, pool.data() + end);
        r.begin = end;
        r.capacity = r.size + count[m];
        end += r.capacity;
    }
    pool_ = std::move(pool);
}

void SegmentStore::truncate(double from) {
    for (Run &r : runs_) {
        ani_motion_segment *begin = pool_.data() + r.begin, *end = begin + r.size;
        ani_motion_segment *kept = std::remove_if(begin, end, [&](const ani_motion_segment &s) { return s.t0 >= from; });
        live_ -= static_cast<std::size_t>(end - kept);
        r.size = static_cast<std::uint32_t>(kept - begin);
        if (r.size > 0 && begin[r.size - 1].t1 > from) begin[r.size - 1].t1 = from;
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
    std::vector<std::uint32_t> count(lists.size());
    for (std::size_t m = 0; m < lists.size(); ++m) count[m] = static_cast<std::uint32_t>(lists[m].size());
    append(count, [&](auto &&put) {
        for (std::size_t m = 0; m < lists.size(); ++m)
            for (ani_motion_segment s : lists[m]) {
                s.model = static_cast<std::uint32_t>(m);
                put(s);
            }
    });
}

} // namespace animator
