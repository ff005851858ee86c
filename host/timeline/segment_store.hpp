// Every model's motion segments of a bake. A bake reports its segments models interleaved, each
// model's in time order: they are written once, as they come, into a log in chunks that never
// move, and each model's run lists where its segments are in the log (4 bytes a segment), in time
// order. Filing a bake call's segments (once per call) writes those indices, not the segments:
// copying 96-byte segments into runs per model had been 6% of a bake of 100,000 balls
// (docs/performance.md, the gas). A run that must grow moves to the index array's end with twice
// its capacity; the space it leaves, and the log's segments a re-bake dropped, are reclaimed when
// the store is compacted, once more is left than used. At 100,000 balls a vector per model had
// cost a hundred thousand allocations and about 4,000 page faults each bake.
#pragma once

#include <animator/huge_pages.hpp>
#include <animator/physics.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <vector>

namespace animator {

// A model's segments, read-only, in time order (valid until the store changes).
class SegmentSpan {
  public:
    class iterator {
      public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = ani_motion_segment;
        using difference_type = std::ptrdiff_t;
        using pointer = const ani_motion_segment *;
        using reference = const ani_motion_segment &;

        iterator() = default;
        iterator(const ani_motion_segment *const *chunks, const std::uint32_t *at)
            : chunks_(chunks), at_(at) {}
        reference operator*() const { return segment(chunks_, *at_); }
        pointer operator->() const { return &**this; }
        reference operator[](difference_type k) const { return segment(chunks_, at_[k]); }
        iterator &operator++() { return ++at_, *this; }
        iterator &operator--() { return --at_, *this; }
        iterator operator++(int) { return iterator(chunks_, at_++); }
        iterator operator--(int) { return iterator(chunks_, at_--); }
        iterator &operator+=(difference_type k) { return at_ += k, *this; }
        iterator &operator-=(difference_type k) { return at_ -= k, *this; }
        friend iterator operator+(iterator i, difference_type k) { return i += k; }
        friend iterator operator+(difference_type k, iterator i) { return i += k; }
        friend iterator operator-(iterator i, difference_type k) { return i -= k; }
        friend difference_type operator-(const iterator &a, const iterator &b) {
            return a.at_ - b.at_;
        }
        friend bool operator==(const iterator &a, const iterator &b) { return a.at_ == b.at_; }
        friend bool operator!=(const iterator &a, const iterator &b) { return a.at_ != b.at_; }
        friend bool operator<(const iterator &a, const iterator &b) { return a.at_ < b.at_; }
        friend bool operator>(const iterator &a, const iterator &b) { return a.at_ > b.at_; }
        friend bool operator<=(const iterator &a, const iterator &b) { return a.at_ <= b.at_; }
        friend bool operator>=(const iterator &a, const iterator &b) { return a.at_ >= b.at_; }

      private:
        const ani_motion_segment *const *chunks_ = nullptr;
        const std::uint32_t *at_ = nullptr;
    };
    using const_iterator = iterator;

    // The log's chunks: 65,536 segments each (6 MB, in huge pages).
    static constexpr unsigned kChunkBits = 16;
    static constexpr std::uint32_t kChunk = std::uint32_t{1} << kChunkBits;
    static const ani_motion_segment &segment(const ani_motion_segment *const *chunks,
                                             std::uint32_t k) {
        return chunks[k >> kChunkBits][k & (kChunk - 1)];
    }

    SegmentSpan() = default;
    SegmentSpan(const ani_motion_segment *const *chunks, const std::uint32_t *at, std::size_t size)
        : chunks_(chunks), at_(at), size_(size) {}
    iterator begin() const { return iterator(chunks_, at_); }
    iterator end() const { return iterator(chunks_, at_ + size_); }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const ani_motion_segment &operator[](std::size_t k) const { return segment(chunks_, at_[k]); }
    const ani_motion_segment &front() const { return (*this)[0]; }
    const ani_motion_segment &back() const { return (*this)[size_ - 1]; }

  private:
    const ani_motion_segment *const *chunks_ = nullptr;
    const std::uint32_t *at_ = nullptr;
    std::size_t size_ = 0;
};

class SegmentStore {
  public:
    explicit SegmentStore(std::size_t models = 0) : runs_(models) {}
    // Moved, not copied: chunk_at_ points into chunks_, whose buffers a move keeps and a copy
    // would not.
    SegmentStore(SegmentStore &&) = default;
    SegmentStore &operator=(SegmentStore &&) = default;
    SegmentStore(const SegmentStore &) = delete;
    SegmentStore &operator=(const SegmentStore &) = delete;

    std::size_t models() const { return runs_.size(); }
    SegmentSpan operator[](std::size_t model) const {
        const Run &r = runs_[model];
        return SegmentSpan(chunk_at_.data(), index_.data() + r.begin, r.size);
    }
    // Every segment filed, for tests and reports.
    std::size_t segment_count() const { return live_; }
    // The index array's length (used, reserved for growth, or left by runs that moved).
    std::size_t capacity() const { return index_.size(); }
    // The log's length in segments (filed, logged and not yet filed, or dropped by a re-bake).
    std::size_t logged() const { return logged_; }

    // Empties the store for `models` models.
    void reset(std::size_t models);
    // Logs a segment of model s.model < models(), reported after that model's earlier ones: it
    // joins its model's run at the next file().
    void log(const ani_motion_segment &s) {
        if (logged_ == chunks_.size() * std::size_t{SegmentSpan::kChunk}) add_chunk();
        ani_motion_segment *slot =
            &chunk_at_[logged_ >> SegmentSpan::kChunkBits][logged_ & (SegmentSpan::kChunk - 1)];
        // (The slot 24 ahead asked for, to be written: its line is fetched while the bake goes on,
        // not when the segment there comes. At 100,000 balls 2% of the bake; past a chunk's end
        // the hint is ignored.)
        __builtin_prefetch(reinterpret_cast<const void *>(reinterpret_cast<std::uintptr_t>(slot) +
                                                          24 * sizeof(ani_motion_segment)),
                           1);
        *slot = s;
        models_.push_back(s.model);
        ++logged_;
    }
    // Files every segment logged since the last call into its model's run.
    void file();
    // Drops every segment starting at `from` or later, and ends the one going on there at `from`
    // (segments logged and not yet filed are filed first).
    void truncate(double from);

    // As lists per model (a bake's file: timeline/bake_file.hpp), and back.
    std::vector<std::vector<ani_motion_segment>> lists() const;
    void assign(const std::vector<std::vector<ani_motion_segment>> &lists);

  private:
    struct Run {
        std::size_t begin = 0;
        std::uint32_t size = 0, capacity = 0;
    };
    static std::size_t room_for(const Run &r, std::uint32_t more);
    void add_chunk();
    // Runs with room for `count` more indices each.
    void make_room(const std::vector<std::uint32_t> &count);
    // The log and the index array rebuilt tight, model after model (each run with room for
    // `count` more).
    void compact_with(const std::vector<std::uint32_t> &count);

    std::vector<Run> runs_;
    // The log: its chunks, where each starts, and each logged segment's model.
    std::vector<ani::UnwrittenVector<ani_motion_segment>> chunks_;
    std::vector<ani_motion_segment *> chunk_at_;
    ani::HugeVector<std::uint32_t> models_;
    std::size_t logged_ = 0, filed_ = 0; // segments logged, and of them filed
    // Each run's log positions, in time order.
    ani::UnwrittenVector<std::uint32_t> index_;
    std::size_t live_ = 0; // segments in runs
};

} // namespace animator
