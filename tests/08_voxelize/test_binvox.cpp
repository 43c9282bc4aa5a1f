// Lab 08, Task 6: .binvox. Expected bytes written out by hand from the format's specification (x slowest, then z,
// y fastest; value/count pairs), and decoding checked voxel by voxel.
#include "helpers.hpp"

using namespace lab08;

namespace {
std::string pairs(std::initializer_list<int> v) {
    std::string s;
    for (int x : v) s.push_back(char(x));
    return s;
}
std::string hex(const std::string& s) {
    std::ostringstream o;
    for (unsigned char c : s) o << (c >= 32 && c < 127 && c != '\\' ? std::string(1, char(c)) : "\\x" + std::to_string(int(c)));
    return o.str();
}
Binvox one_voxel(std::int64_t i, std::int64_t j, std::int64_t k) {
    Binvox b;
    b.grid = BitGrid({2, 2, 2});
    b.grid.set(i, j, k);
    b.translate = {0.5, -1, 2};
    b.scale = 0.25;
    return b;
}
const std::string header2 = "#binvox 1\ndim 2 2 2\ntranslate 0.5 -1 2\nscale 0.25\ndata\n";
}  // namespace

TEST_SUITE("Task 6: binvox") {
    TEST_CASE("binvox: hand-checked bytes of 2³ files (x; z; y order with y fastest)" * geolab::points(2) *
              geolab::hint("file position x·n² + z·n + y holds voxel (x, y, z); runs are (value, count) byte pairs")) {
        struct C {
            std::int64_t i, j, k;
            std::string data;
        };
        for (const C& c : {C{1, 0, 0, pairs({0, 4, 1, 1, 0, 3})}, C{0, 1, 0, pairs({0, 1, 1, 1, 0, 6})},
                           C{0, 0, 1, pairs({0, 2, 1, 1, 0, 5})}, C{1, 1, 1, pairs({0, 7, 1, 1})}, C{0, 0, 0, pairs({1, 1, 0, 7})}}) {
            const std::string want = header2 + c.data;
            const std::string got = encode_binvox(one_voxel(c.i, c.j, c.k));
            INFO("voxel (" << c.i << ", " << c.j << ", " << c.k << ") set in 2³: expected \"" << hex(want) << "\", got \"" << hex(got) << "\"");
            CHECK(got == want);
            const Binvox back = decode_binvox(want);
            CHECK(count_bits(back.grid) == 1);
            CHECK(back.grid.get(c.i, c.j, c.k));
            CHECK(back.translate == glm::dvec3(0.5, -1, 2));
            CHECK(back.scale == 0.25);
        }
    }
    TEST_CASE("binvox: runs stop at 255" * geolab::points(1) * geolab::hint("a run of 512 ones is 255, 255, 2")) {
        Binvox b;
        b.grid = BitGrid({8, 8, 8});
        for (auto& w : b.grid.words) w = ~std::uint64_t(0);
        const std::string got = encode_binvox(b);
        const std::string want = "#binvox 1\ndim 8 8 8\ntranslate 0 0 0\nscale 1\ndata\n" + pairs({1, 255, 1, 255, 1, 2});
        INFO("expected \"" << hex(want) << "\", got \"" << hex(got) << "\"");
        CHECK(got == want);
    }
    TEST_CASE("binvox: round trips of random grids" * geolab::points(1) *
              geolab::hint("decode_binvox(encode_binvox(b)) == b, voxel for voxel, translate and scale exactly")) {
        Rng rng(9);
        for (std::int64_t n : {1, 3, 5, 16, 33}) {
            Binvox b;
            b.grid = grid_of({n, n, n}, [&](auto, auto, auto) { return rng.integer(0, 9) < 3; });
            b.translate = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            b.scale = rng.uniform(0.1, 10);
            const Binvox back = decode_binvox(encode_binvox(b));
            const std::string diff = first_difference(back.grid, b.grid);
            CHECK_MESSAGE(diff.empty(), n << "³: " << diff);
            CHECK(back.translate == b.translate);
            CHECK(back.scale == b.scale);
        }
    }
    TEST_CASE("binvox: hostile files are clear errors; never crashes or huge allocations" * geolab::points(2) *
              geolab::hint("check every header line and every pair; compare n³ with what the pairs can hold before "
                           "allocating; throw geolab::IoError")) {
        const std::string ok = header2 + pairs({0, 4, 1, 1, 0, 3});
        CHECK_NOTHROW(decode_binvox(ok));
        CHECK(decode_binvox("#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 8})).scale == 1.0);  // translate/scale optional
        const std::vector<std::pair<std::string, std::string>> bad = {
            {"", "empty"},
            {"#binvox 3\ndim 2 2 2\ndata\n" + pairs({0, 8}), "version 3"},
            {"binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 8}), "no #"},
            {"#binvox 1\ndata\n" + pairs({0, 8}), "no dim"},
            {"#binvox 1\ndim 2 2 2\ndim 2 2 2\ndata\n" + pairs({0, 8}), "two dims"},
            {"#binvox 1\ndim 2 2\ndata\n" + pairs({0, 8}), "two sizes"},
            {"#binvox 1\ndim 2 2 3\ndata\n" + pairs({0, 12}), "not cubic"},
            {"#binvox 1\ndim 0 0 0\ndata\n", "dim 0"},
            {"#binvox 1\ndim -2 -2 -2\ndata\n" + pairs({0, 8}), "negative"},
            {"#binvox 1\ndim 2x 2 2\ndata\n" + pairs({0, 8}), "bad size"},
            {"#binvox 1\ndim 2 2 2\nscale nan\ndata\n" + pairs({0, 8}), "scale nan"},
            {"#binvox 1\ndim 2 2 2\ntranslate 1 2\ndata\n" + pairs({0, 8}), "translate of 2"},
            {"#binvox 1\ndim 2 2 2\nfoo 1\ndata\n" + pairs({0, 8}), "unknown line"},
            {"#binvox 1\ndim 2 2 2\n", "no data line"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 4}), "short of n³"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 4, 1}), "a truncated pair"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 4, 1, 5}), "runs past n³"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 0, 0, 8}), "count 0"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({2, 8}), "value 2 in version 1"},
            {"#binvox 1\ndim 2 2 2\ndata\n" + pairs({0, 8, 0}), "a trailing byte"},
            {"#binvox 1\ndim 100000 100000 100000\ndata\n" + pairs({0, 255, 0, 255}), "a lying header (10^15 voxels)"},
            {"#binvox 1\ndim 3000000000 3000000000 3000000000\ndata\n" + pairs({0, 8}), "a size whose cube overflows"},
            {"#binvox 1\ndim 9223372036854775807 9223372036854775807 9223372036854775807\ndata\n", "int64 max"},
            {"#binvox 1\ndim 99999999999999999999999 1 1\ndata\n", "a size past int64"},
            {"#binvox 1\n" + std::string(100000, 'x'), "a huge line"},
            {"#binvox 1\ndim 2 3 2\ndata\n" + pairs({0, 8}), "dims 2 3 2"},
            {"#binvox 1\ndim 2 2 2\ndata 1\n" + pairs({0, 8}), "a data line with a word after data"},
            {"#binvox 1\ndim 2 2 2\nscale 1x\ndata\n" + pairs({0, 8}), "scale 1x"},
            {"#binvox 1\ndim 2 2 2\ntranslate 1 2 3x\ndata\n" + pairs({0, 8}), "translate 1 2 3x"},
            {"#binvox 1\ndim 2 2 2\nscale 0.5" + std::string(257 - 9, ' ') + "\ndata\n" + pairs({0, 8}), "a 257-byte scale line"},
            {"#binvox 1\ndim 2 2 2\nscale 0.5" + std::string(300, ' ') + "\ndata\n" + pairs({0, 8}), "a 309-byte scale line"},
        };
        for (const auto& [bytes, what] : bad) {
            INFO(what << ": expected geolab::IoError");
            CHECK_THROWS_AS(decode_binvox(bytes, what), geolab::IoError);
        }
        // non-cubic dims whose data would fit the first size; the error names the header line
        CHECK_THROWS_AS(decode_binvox("#binvox 1\ndim 2 2 3\ndata\n" + pairs({0, 8})), geolab::IoError);
        CHECK_THROWS_AS(decode_binvox("#binvox 1\ndim 3 2 2\ndata\n" + pairs({0, 27})), geolab::IoError);
        try {
            decode_binvox("#binvox 1\ndim 2 2 2\nfoo 1\ndata\n" + pairs({0, 8}), "f.binvox");
            FAIL("an unknown header line must throw");
        } catch (const geolab::IoError& e) {
            INFO("the unknown line is line 3 of the file; the error says line " << e.line() << ": " << e.what());
            CHECK(e.line() == 3);
            CHECK(e.file() == "f.binvox");
        }
        // what the header allows: "\r\n" line ends, spaces and tabs around words, lines of 256 bytes
        for (const auto& [bytes, what] : std::vector<std::pair<std::string, std::string>>{
                 {"#binvox 1\r\ndim 2 2 2\r\ntranslate 0.5 -1 2\r\nscale 0.25\r\ndata\r\n", "\\r\\n line ends"},
                 {"#binvox 1\n \tdim\t2  2 2 \ntranslate 0.5\t-1 2\t\n scale 0.25 \n\tdata  \n", "spaces and tabs around words"},
                 {"#binvox 1\ndim 2 2 2\ntranslate 0.5 -1 2\nscale 0.25" + std::string(256 - 10, ' ') + "\ndata\n", "a 256-byte scale line"}}) {
            INFO(what << ": " << hex(bytes));
            try {
                const Binvox b = decode_binvox(bytes + pairs({0, 4, 1, 1, 0, 3}), what);
                CHECK_MESSAGE(b.grid.dims.nx == 2, "expected dim 2, got " << b.grid.dims.nx);
                CHECK_MESSAGE((b.translate == glm::dvec3(0.5, -1, 2) && b.scale == 0.25),
                              "expected translate (0.5, -1, 2) scale 0.25, got " << str(b.translate) << " " << b.scale);
                CHECK_MESSAGE((count_bits(b.grid) == 1 && b.grid.get(1, 0, 0)), "expected only voxel (1, 0, 0), got " << count_bits(b.grid) << " voxels");
            } catch (const std::exception& e) {
                FAIL_CHECK("expected a valid file, got an exception: " << e.what());
            }
        }
        // n³ = 255 · pairs exactly: the pairs hold every voxel (255³ set voxels in 255² pairs)
        {
            std::string full = "#binvox 1\ndim 255 255 255\ndata\n";
            for (int r = 0; r < 255 * 255; ++r) full += pairs({1, 255});
            try {
                const Binvox b = decode_binvox(full, "255³ full");
                CHECK_MESSAGE(count_bits(b.grid) == 255ull * 255 * 255, "255³ full grid in 65,025 pairs of (1, 255): expected 16,581,375 voxels, got " << count_bits(b.grid));
            } catch (const std::exception& e) {
                FAIL_CHECK("255³ full grid in 65,025 pairs of (1, 255): expected a valid file, got an exception: " << e.what());
            }
        }
        // version 2: any non-zero value is a set voxel
        const Binvox v2 = decode_binvox("#binvox 2\ndim 2 2 2\ndata\n" + pairs({0, 4, 7, 1, 0, 3}));
        CHECK(v2.grid.get(1, 0, 0));
        CHECK(count_bits(v2.grid) == 1);
    }
    TEST_CASE("binvox: what cannot be written is an error" * geolab::points(1) *
              geolab::hint("non-cubic or empty grids, wrong words sizes and non-finite numbers: std::invalid_argument")) {
        Binvox b;
        b.grid = BitGrid({2, 2, 3});
        CHECK_THROWS_AS(encode_binvox(b), std::invalid_argument);
        b.grid = BitGrid({0, 0, 0});
        CHECK_THROWS_AS(encode_binvox(b), std::invalid_argument);
        b.grid = BitGrid({2, 2, 2});
        b.scale = std::numeric_limits<double>::infinity();
        CHECK_THROWS_AS(encode_binvox(b), std::invalid_argument);
        b.scale = 1;
        b.translate.y = std::nan("");
        CHECK_THROWS_AS(encode_binvox(b), std::invalid_argument);
        b.translate.y = 0;
        b.grid.words.push_back(0);
        CHECK_THROWS_AS(encode_binvox(b), std::invalid_argument);
        // the same grid with the right words is written ("reject everything" is not the contract)
        b.grid.words.pop_back();
        const std::string bytes = encode_binvox(b);
        CHECK_MESSAGE(bytes.rfind("#binvox 1\n", 0) == 0, "a valid 2 x 2 x 2 grid: the file should start with the header");
    }
}
