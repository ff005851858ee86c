// Large arrays in 2 MB pages, for the host and plugins alike (C++ only, header-only; Linux, and
// elsewhere the standard allocator). A bake's arrays of a value per model are written once,
// fresh: at 100,000 models each is several megabytes, and every 4 KB page of them costs the
// kernel a page fault on first touch (11 us a page on the virtual machines we measure on, where
// a bake of 100,000 balls spent more time in page faults than in its event loop:
// docs/performance.md, the gas). Arrays of `kHugePagesFrom` bytes or more are mapped apart, on
// 2 MB boundaries, and the kernel asked for transparent huge pages there (madvise: granted where
// /sys/kernel/mm/transparent_hugepage/enabled says "madvise" or "always"), one fault a 2 MB page;
// smaller ones come from the standard allocator. Freed, they are kept for the next large array
// (huge_pages_take/give below; huge_pages_trim hands them back). Under AddressSanitizer every
// array comes from the standard allocator, so that its overflows are still caught.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#if defined(__has_feature)
#if !__has_feature(address_sanitizer)
#define ANI_HUGE_PAGES 1
#endif
#else
#define ANI_HUGE_PAGES 1
#endif
#endif

#ifdef ANI_HUGE_PAGES
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <mutex>
#include <utility>
#endif

namespace ani {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kHugePagesFrom = std::size_t{4} << 20;
// At most this much freed huge-page memory is kept for reuse (below).
constexpr std::size_t kHugePagesKept = std::size_t{1} << 30;

#ifdef ANI_HUGE_PAGES
// Freed mappings are kept for the next large array, as glibc keeps freed heap for the next
// malloc: a fresh mapping costs the kernel a zeroed 2 MB page at each first touch (on the virtual
// machines we measure on, about 1.4 GB a second: a third of a 100,000-ball bake went there,
// docs/performance.md, the gas), while a kept one is written again in place. Kept mappings are
// marked MADV_FREE, so the kernel takes their pages back, without asking, when memory runs short;
// at most kHugePagesKept bytes (or an eighth of the machine's memory, if less) are kept, the
// rest unmapped. One list for the process, behind a lock (bakes run on worker threads).
namespace detail {

struct HugePageCache {
    std::mutex lock;
    std::vector<std::pair<std::uintptr_t, std::size_t>> kept; // (start, length), 2 MB multiples
    std::size_t kept_bytes = 0;
    std::size_t limit = 0;
};

inline HugePageCache &huge_page_cache() {
    // Never destroyed: arrays in static objects may be freed after it would be.
    static HugePageCache *cache = [] {
        auto *c = new HugePageCache;
        const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
        const std::size_t memory =
            pages > 0 && page > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page) : 0;
        c->limit = memory > 0 ? std::min(kHugePagesKept, memory / 8) : kHugePagesKept;
        return c;
    }();
    return *cache;
}

} // namespace detail

// `length` bytes (a multiple of kHugePage) on a 2 MB boundary: the smallest kept mapping that
// holds them (its tail kept), or a fresh one.
inline void *huge_pages_take(std::size_t length) {
    {
        detail::HugePageCache &c = detail::huge_page_cache();
        std::lock_guard<std::mutex> hold(c.lock);
        std::size_t best = c.kept.size();
        for (std::size_t k = 0; k < c.kept.size(); ++k)
            if (c.kept[k].second >= length &&
                (best == c.kept.size() || c.kept[k].second < c.kept[best].second))
                best = k;
        if (best < c.kept.size()) {
            const std::uintptr_t start = c.kept[best].first;
            c.kept_bytes -= length;
            if (c.kept[best].second > length) {
                c.kept[best].first += length;
                c.kept[best].second -= length;
            } else {
                c.kept.erase(c.kept.begin() + static_cast<std::ptrdiff_t>(best));
            }
            return reinterpret_cast<void *>(start);
        }
    }
    // Mapped a page larger, then trimmed to the boundary on each side.
    void *mapped = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
    const std::uintptr_t end = start + length + kHugePage;
    if (aligned > start) munmap(mapped, aligned - start);
    if (end > aligned + length) munmap(reinterpret_cast<void *>(aligned + length), end - aligned - length);
    void *p = reinterpret_cast<void *>(aligned);
    madvise(p, length, MADV_HUGEPAGE); // (refused: 4 KB pages, still correct)
    return p;
}

// Gives back what huge_pages_take handed out: kept (joined to a kept neighbour) while the kept
// total stays within the limit, unmapped otherwise.
inline void huge_pages_give(void *p, std::size_t length) {
    detail::HugePageCache &c = detail::huge_page_cache();
    {
        std::lock_guard<std::mutex> hold(c.lock);
        if (c.kept_bytes + length <= c.limit) {
#ifdef MADV_FREE
            madvise(p, length, MADV_FREE);
#endif
            std::uintptr_t start = reinterpret_cast<std::uintptr_t>(p), size = length;
            for (std::size_t k = 0; k < c.kept.size();) {
                if (c.kept[k].first + c.kept[k].second == start ||
                    start + size == c.kept[k].first) {
                    start = std::min(start, c.kept[k].first);
                    size += c.kept[k].second;
                    c.kept.erase(c.kept.begin() + static_cast<std::ptrdiff_t>(k));
                } else {
                    ++k;
                }
            }
            c.kept.emplace_back(start, size);
            c.kept_bytes += length;
            return;
        }
    }
    munmap(p, length);
}

// Unmaps every kept mapping (memory handed back to the system at once; the next large arrays are
// fresh mappings again).
inline void huge_pages_trim() {
    detail::HugePageCache &c = detail::huge_page_cache();
    std::lock_guard<std::mutex> hold(c.lock);
    for (const auto &k : c.kept) munmap(reinterpret_cast<void *>(k.first), k.second);
    c.kept.clear();
    c.kept_bytes = 0;
}
#else
inline void huge_pages_trim() {} // (nothing is kept without huge pages)
#endif

// The standard allocator, but for arrays of kHugePagesFrom bytes or more (above): those mapped
// apart, rounded up to whole 2 MB pages on a 2 MB boundary, and kept for reuse when freed.
template <class T> struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U> HugePageAllocator(const HugePageAllocator<U> &) {}
    template <class U> bool operator==(const HugePageAllocator<U> &) const { return true; }
    template <class U> bool operator!=(const HugePageAllocator<U> &) const { return false; }

    T *allocate(std::size_t n) {
#ifdef ANI_HUGE_PAGES
        if (n * sizeof(T) >= kHugePagesFrom) return static_cast<T *>(huge_pages_take(rounded(n)));
#endif
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T *p, std::size_t n) {
#ifdef ANI_HUGE_PAGES
        if (n * sizeof(T) >= kHugePagesFrom) {
            huge_pages_give(p, rounded(n));
            return;
        }
#endif
        std::allocator<T>().deallocate(p, n);
    }

  private:
    static std::size_t rounded(std::size_t n) {
        return (n * sizeof(T) + kHugePage - 1) / kHugePage * kHugePage;
    }
};

// A vector whose storage is in huge pages once it is large.
template <class T> using HugeVector = std::vector<T, HugePageAllocator<T>>;

// As HugePageAllocator, but the room a resize (or a vector's constructor of n elements) adds is
// left unwritten where T is trivially copyable: std::vector would zero it, a pass over the whole
// array before the caller writes every element anyway (a bake's arrays of a value per model are
// filled in two halves at once; zeroing them first, on one thread, was 2% of a bake of 100,000
// balls: docs/performance.md, the gas). Every such element must be written
// before it is read.
template <class T> struct UnwrittenAllocator : HugePageAllocator<T> {
    template <class U> struct rebind { using other = UnwrittenAllocator<U>; };
    UnwrittenAllocator() = default;
    template <class U> UnwrittenAllocator(const UnwrittenAllocator<U> &) {}
    template <class U>
    void construct(U *p) noexcept(std::is_nothrow_default_constructible<U>::value) {
        if constexpr (!std::is_trivially_copyable<U>::value) ::new (static_cast<void *>(p)) U;
    }
    template <class U, class... A> void construct(U *p, A &&...a) {
        ::new (static_cast<void *>(p)) U(std::forward<A>(a)...);
    }
};

template <class T> using UnwrittenVector = std::vector<T, UnwrittenAllocator<T>>;

} // namespace ani
