// Large arrays in 2 MB pages, for the host and plugins alike (C++ only, header-only; Linux, and
// elsewhere the standard allocator). A bake's arrays of a value per model are written once,
// fresh: at 100,000 models each is several megabytes, and every 4 KB page of them costs the
// kernel a page fault on first touch (11 us a page on the virtual machines we measure on, where
// a bake of 100,000 balls spent more time in page faults than in its event loop:
// docs/performance.md, the gas). Arrays of `kHugePagesFrom` bytes or more are mapped apart, on
// 2 MB boundaries, and the kernel asked for transparent huge pages there (madvise: granted where
// /sys/kernel/mm/transparent_hugepage/enabled says "madvise" or "always"), one fault a 2 MB page;
// smaller ones come from the standard allocator. Under AddressSanitizer every array comes from
// the standard allocator, so that its overflows are still caught.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
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
#endif

namespace ani {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kHugePagesFrom = std::size_t{4} << 20;

// The standard allocator, but for arrays of kHugePagesFrom bytes or more (above): those mapped
// apart, rounded up to whole 2 MB pages on a 2 MB boundary, and unmapped when freed.
template <class T> struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U> HugePageAllocator(const HugePageAllocator<U> &) {}
    template <class U> bool operator==(const HugePageAllocator<U> &) const { return true; }
    template <class U> bool operator!=(const HugePageAllocator<U> &) const { return false; }

    T *allocate(std::size_t n) {
#ifdef ANI_HUGE_PAGES
        if (n * sizeof(T) >= kHugePagesFrom) {
            // Mapped a page larger, then trimmed to the boundary on each side.
            const std::size_t length = rounded(n);
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
            return static_cast<T *>(p);
        }
#endif
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T *p, std::size_t n) {
#ifdef ANI_HUGE_PAGES
        if (n * sizeof(T) >= kHugePagesFrom) {
            munmap(p, rounded(n));
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

} // namespace ani
