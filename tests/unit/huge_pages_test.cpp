// The SDK's HugeVector (animator/huge_pages.hpp): a vector like any other as it grows through the
// size where its storage moves to huge pages and back, and, where it does, storage on a 2 MB
// boundary that the kernel backs with 2 MB pages (its own account: /proc/self/smaps).
#include <animator/huge_pages.hpp>

#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

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
