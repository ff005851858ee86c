// The SDK's HugeVector (animator/huge_pages.hpp): a vector like any other as it grows through the
// size where its storage moves to huge pages and back, and, where it does, storage on a 2 MB
// boundary that the kernel backs with 2 MB pages (its own account: /proc/self/smaps).
#include <animator/huge_pages.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>

namespace {

// The kernel's transparent huge pages setting: "always", "madvise" or "never" (the bracketed one).
std::string thp_mode() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(in, line);
    const auto open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

// The kB of huge pages backing the mapping that holds `p` (smaps' AnonHugePages), or -1.
long huge_kb_at(const void *p) {
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    std::ifstream in("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
            inside = lo <= at && at < hi;
            continue;
        }
        if (inside && line.rfind("AnonHugePages:", 0) == 0) return std::stol(line.substr(14));
    }
    return -1;
}

bool huge_pages_built() {
#ifdef ANI_HUGE_PAGES
    return true;
#else
    return false;
#endif
}

} // namespace

TEST_CASE("a HugeVector keeps its values as it grows into huge pages and back") {
    ani::HugeVector<std::uint64_t> v;
    const std::size_t n = 3 * ani::kHugePagesFrom / sizeof(std::uint64_t); // 12 MB
    for (std::size_t k = 0; k < n; ++k) v.push_back(k * 2654435761u);
    REQUIRE(v.size() == n);
    bool same = true;
    for (std::size_t k = 0; k < n; ++k) same = same && v[k] == k * 2654435761u;
    CHECK(same);
    if (huge_pages_built()) CHECK(reinterpret_cast<std::uintptr_t>(v.data()) % ani::kHugePage == 0);
    v.resize(10);
    v.shrink_to_fit(); // back to the standard allocator
    CHECK(v.capacity() * sizeof(std::uint64_t) < ani::kHugePagesFrom);
    CHECK(v[9] == std::uint64_t{9} * 2654435761u);
}

TEST_CASE("a large HugeVector is backed by 2 MB pages where the kernel grants them") {
    if (!huge_pages_built()) {
        WARN("built without huge pages (AddressSanitizer, or not Linux): nothing to check");
        return;
    }
    const std::string mode = thp_mode();
    if (mode != "always" && mode != "madvise") {
        WARN("transparent huge pages are '" << mode << "' here: the kernel grants none");
        return;
    }
    ani::HugeVector<double> v(2 * ani::kHugePagesFrom / sizeof(double), 1.0); // 8 MB, written
    const long kb = huge_kb_at(v.data());
    CAPTURE(mode, kb);
    // The kernel may be short of free 2 MB blocks; it grants most of them on a machine at rest.
    CHECK(kb >= 2048);
}

#ifdef ANI_HUGE_PAGES
namespace {

long minor_faults() {
    rusage r{};
    getrusage(RUSAGE_SELF, &r);
    return r.ru_minflt;
}

} // namespace
#endif

TEST_CASE("freed huge-page arrays are kept and handed to the next ones, split and joined") {
#ifndef ANI_HUGE_PAGES
    WARN("built without huge pages (AddressSanitizer, or not Linux): nothing to check");
#else
    ani::huge_pages_trim(); // what earlier tests left kept would be handed out first
    constexpr std::size_t mb = std::size_t{1} << 20;
    const std::size_t n16 = 16 * mb / sizeof(std::uint32_t), n8 = n16 / 2;
    const std::uint32_t *first = nullptr;
    long fresh = 0;
    {
        const long before = minor_faults();
        ani::HugeVector<std::uint32_t> a(n16, 7u); // 16 MB, written
        fresh = minor_faults() - before;
        first = a.data();
    }
    // Handed out again: the same memory, written again without the kernel's first-touch faults
    // (one a 2 MB page where huge pages are granted, one a 4 KB page where not).
    const long before = minor_faults();
    ani::HugeVector<std::uint32_t> b(n16, 9u);
    const long again = minor_faults() - before;
    CHECK(b.data() == first);
    CAPTURE(fresh, again);
    CHECK(again * 2 <= fresh);
    CHECK(std::all_of(b.begin(), b.end(), [](std::uint32_t v) { return v == 9u; }));
    b = ani::HugeVector<std::uint32_t>();
    // Two halves from the kept 16 MB: the head, then the tail next to it; given back, they are
    // joined, and the whole 16 MB is handed out at its start.
    ani::HugeVector<std::uint32_t> head(n8, 1u), tail(n8, 2u);
    CHECK(head.data() == first);
    CHECK(tail.data() == first + n8);
    CHECK(std::all_of(head.begin(), head.end(), [](std::uint32_t v) { return v == 1u; }));
    CHECK(std::all_of(tail.begin(), tail.end(), [](std::uint32_t v) { return v == 2u; }));
    head = ani::HugeVector<std::uint32_t>();
    tail = ani::HugeVector<std::uint32_t>();
    ani::HugeVector<std::uint32_t> whole(n16, 3u);
    CHECK(whole.data() == first);
    CHECK(std::all_of(whole.begin(), whole.end(), [](std::uint32_t v) { return v == 3u; }));
#endif
}

TEST_CASE("no more than the limit of freed huge-page memory is kept") {
#ifndef ANI_HUGE_PAGES
    WARN("built without huge pages (AddressSanitizer, or not Linux): nothing to check");
#else
    const std::size_t limit = ani::detail::huge_page_cache().limit;
    CHECK(limit <= ani::kHugePagesKept);
    CHECK(limit >= 64 * (std::size_t{1} << 20));
    {
        // Arrays of 1.5 times the limit together (reserved, not written), all freed: the kept
        // memory stays within it.
        std::vector<ani::HugeVector<char>> arrays(6);
        for (auto &a : arrays) a.reserve(limit / 4);
    }
    ani::detail::HugePageCache &c = ani::detail::huge_page_cache();
    std::lock_guard<std::mutex> hold(c.lock);
    std::size_t kept = 0;
    for (const auto &k : c.kept) kept += k.second;
    CHECK(kept == c.kept_bytes);
    CHECK(kept <= limit);
    CHECK(kept >= limit / 2); // and some were kept
#endif
}

TEST_CASE("trimming hands every kept huge-page mapping back") {
#ifndef ANI_HUGE_PAGES
    WARN("built without huge pages (AddressSanitizer, or not Linux): nothing to check");
#else
    const void *at = nullptr;
    {
        ani::HugeVector<double> a(ani::kHugePagesFrom / sizeof(double), 1.0);
        at = a.data();
    }
    CHECK(huge_kb_at(at) >= 0); // kept: still mapped
    ani::huge_pages_trim();
    CHECK(ani::detail::huge_page_cache().kept_bytes == 0);
    CHECK(huge_kb_at(at) == -1); // unmapped
#endif
}
