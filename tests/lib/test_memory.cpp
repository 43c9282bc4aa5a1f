// Tests of the memory hint: geolab/memory.hpp.
#include <doctest/doctest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "geolab/memory.hpp"

namespace {

// The kernel's transparent-huge-page mode ("always", "madvise" or "never"; empty when the file does not exist).
std::string thp_mode() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(in, line);
    const auto open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos ? std::string() : line.substr(open + 1, close - open - 1);
}

}  // namespace

TEST_CASE("prefer_huge_pages: small or empty ranges get no advice") {
    CHECK_FALSE(geolab::prefer_huge_pages(nullptr, std::size_t(64) << 20));
    std::vector<double> small(1000, 1.0);
    CHECK_FALSE(geolab::prefer_huge_pages(small));
    std::vector<double> none;
    CHECK_FALSE(geolab::prefer_huge_pages(none));
    CHECK(small[999] == 1.0);
}

TEST_CASE("prefer_huge_pages: a large array keeps its contents and stays usable") {
    std::vector<std::uint64_t> v;
    v.reserve(std::size_t(3) << 20);  // 24 MiB
    const bool advised = geolab::prefer_huge_pages(v);
#if defined(__linux__)
    const std::string mode = thp_mode();
    INFO("transparent huge pages: '" << mode << "'");
    if (mode == "always" || mode == "madvise") CHECK(advised);
#else
    CHECK_FALSE(advised);
#endif
    v.resize(v.capacity());
    std::iota(v.begin(), v.end(), std::uint64_t(7));
    CHECK(v.front() == 7);
    CHECK(v.back() == 7 + v.size() - 1);
    // advising memory that is already written changes nothing either
    geolab::prefer_huge_pages(v);
    CHECK(v[v.size() / 2] == 7 + v.size() / 2);
}
