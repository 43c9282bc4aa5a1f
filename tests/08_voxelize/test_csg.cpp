// Lab 08, Task 5: voxel CSG. Expected values by the formulas, voxel by voxel.
#include "helpers.hpp"

using namespace lab08;

namespace {
ValueGrid random_values(Dims d, Rng& rng) {
    ValueGrid g;
    g.dims = d;
    for (std::int64_t n = 0; n < d.count(); ++n) g.values.push_back(rng.integer(0, 3) == 0 ? 0.0 : rng.uniform(-1, 2));
    return g;
}
BitGrid random_bits(Dims d, Rng& rng) {
    return grid_of(d, [&](std::int64_t, std::int64_t, std::int64_t) { return rng.integer(0, 2) == 0; });
}
}  // namespace

TEST_SUITE("Task 5: voxel CSG") {
    TEST_CASE("CSG: union = max; intersection = min; add = C1·F1 + C2·F2; subtract = max(F1 − F2; 0)" * geolab::points(2) *
              geolab::hint("voxel by voxel, same dims; subtract clamps at 0")) {
        Rng rng(5);
        for (Dims d : {Dims{3, 4, 5}, Dims{1, 1, 1}, Dims{7, 1, 2}}) {
            const ValueGrid a = random_values(d, rng), b = random_values(d, rng);
            const ValueGrid u = csg_union(a, b), i = csg_intersection(a, b), s = csg_subtract(a, b),
                            t = csg_add(a, b, 0.5, -2.0);
            for (const ValueGrid* g : {&u, &i, &s, &t}) {
                CHECK(g->dims == d);
                REQUIRE(g->values.size() == a.values.size());
            }
            for (std::size_t n = 0; n < a.values.size(); ++n) {
                INFO("voxel " << n << ": F1 = " << a.values[n] << ", F2 = " << b.values[n] << "; union " << u.values[n]
                              << ", intersection " << i.values[n] << ", subtract " << s.values[n] << ", 0.5 F1 - 2 F2 = " << t.values[n]);
                CHECK(u.values[n] == std::max(a.values[n], b.values[n]));
                CHECK(i.values[n] == std::min(a.values[n], b.values[n]));
                CHECK(s.values[n] == std::max(a.values[n] - b.values[n], 0.0));
                CHECK(t.values[n] == 0.5 * a.values[n] + -2.0 * b.values[n]);
            }
        }
    }
    TEST_CASE("CSG: packed grids; bitwise; with clean tails" * geolab::points(2) *
              geolab::hint("| & &~ word by word; the complement must clear the bits past the last voxel")) {
        Rng rng(6);
        for (Dims d : {Dims{5, 5, 5}, Dims{8, 8, 1}, Dims{3, 7, 11}, Dims{1, 1, 1}}) {
            const BitGrid a = random_bits(d, rng), b = random_bits(d, rng);
            const BitGrid u = bits_union(a, b), i = bits_intersection(a, b), f = bits_difference(a, b), c = bits_complement(a);
            for (const BitGrid* g : {&u, &i, &f, &c}) CHECK_MESSAGE(tail_clean(*g), "grid " << str(d) << ": the bits past the last voxel must be 0");
            const std::string du = first_difference(u, grid_of(d, [&](auto x, auto y, auto z) { return a.get(x, y, z) || b.get(x, y, z); }));
            const std::string di = first_difference(i, grid_of(d, [&](auto x, auto y, auto z) { return a.get(x, y, z) && b.get(x, y, z); }));
            const std::string df = first_difference(f, grid_of(d, [&](auto x, auto y, auto z) { return a.get(x, y, z) && !b.get(x, y, z); }));
            const std::string dc = first_difference(c, grid_of(d, [&](auto x, auto y, auto z) { return !a.get(x, y, z); }));
            CHECK_MESSAGE(du.empty(), "union " << str(d) << ": " << du);
            CHECK_MESSAGE(di.empty(), "intersection " << str(d) << ": " << di);
            CHECK_MESSAGE(df.empty(), "difference " << str(d) << ": " << df);
            CHECK_MESSAGE(dc.empty(), "complement " << str(d) << ": " << dc);
        }
    }
    TEST_CASE("CSG: mismatched grids are errors" * geolab::points(1) *
              geolab::hint("different dims, or values / words of the wrong size: std::invalid_argument")) {
        Rng rng(7);
        const ValueGrid a = random_values({2, 3, 4}, rng), b = random_values({4, 3, 2}, rng);
        ValueGrid short_a = a;
        short_a.values.pop_back();
        CHECK_THROWS_AS(csg_union(a, b), std::invalid_argument);
        CHECK_THROWS_AS(csg_intersection(a, b), std::invalid_argument);
        CHECK_THROWS_AS(csg_add(a, b, 1, 1), std::invalid_argument);
        CHECK_THROWS_AS(csg_subtract(a, b), std::invalid_argument);
        CHECK_THROWS_AS(csg_union(short_a, short_a), std::invalid_argument);
        ValueGrid negative;  // (−1)·(−1)·1 = 1 value: the product matches, the dims do not make sense
        negative.dims = {-1, -1, 1};
        negative.values = {0.5};
        CHECK_THROWS_AS(csg_union(negative, negative), std::invalid_argument);
        // matching grids are no error ("reject everything" is not the contract)
        CHECK(csg_union(a, a).values.size() == a.values.size());
        CHECK(csg_subtract(a, a).dims == a.dims);
        negative.dims = {1, -1, -1};
        CHECK_THROWS_AS(csg_subtract(negative, negative), std::invalid_argument);
        const BitGrid p({3, 3, 3}), q({3, 3, 4});
        BitGrid broken = p;
        broken.words.push_back(0);
        CHECK_THROWS_AS(bits_union(p, q), std::invalid_argument);
        CHECK_THROWS_AS(bits_intersection(p, q), std::invalid_argument);
        CHECK_THROWS_AS(bits_difference(p, q), std::invalid_argument);
        CHECK_THROWS_AS(bits_union(broken, broken), std::invalid_argument);
        CHECK_THROWS_AS(bits_complement(broken), std::invalid_argument);
    }
}
