// Lab 08, Task 2: the triangle–box test. Expected values by clipping the triangle to the box in long double
// (helpers.hpp), and by construction for the exact contacts.
#include "helpers.hpp"

using namespace lab08;

namespace {
using Tri = std::array<glm::dvec3, 3>;
void check(const Tri& t, std::int64_t i, std::int64_t j, std::int64_t k, bool want, const std::string& what) {
    const bool got = triangle_overlaps_voxel(t[0], t[1], t[2], i, j, k);
    INFO(what << ": triangle " << str(t[0]) << " " << str(t[1]) << " " << str(t[2]) << ", voxel (" << i << ", " << j
              << ", " << k << "): expected " << (want ? "overlap" : "no overlap") << ", got " << (got ? "overlap" : "no overlap"));
    CHECK(got == want);
}
// Does one of the 3 face normals or the triangle's normal separate t from the box [0,1]³ (with touching)?
bool separated_by_face_axes(const Tri& t) {
    for (int d = 0; d < 3; ++d) {
        const double lo = std::min({t[0][d], t[1][d], t[2][d]}), hi = std::max({t[0][d], t[1][d], t[2][d]});
        if (lo >= 1 || hi <= 0) return true;
    }
    const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    double lo = 1e300, hi = -1e300;
    for (int c = 0; c < 8; ++c) {
        const double p = glm::dot(n, glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
    const double p = glm::dot(n, t[0]);
    return p <= lo || p >= hi;
}
}  // namespace

TEST_SUITE("Task 2: the triangle-box test") {
    TEST_CASE("triangle-box: random triangles near a voxel agree with clipping" * geolab::points(2) *
              geolab::hint("13 axes: 3 box normals, the triangle's normal, 9 edge cross products; separated when the "
                           "projections are disjoint or only touch")) {
        Rng rng(2001);
        int overlaps = 0, misses = 0;
        for (int n = 0; n < 4000; ++n) {
            const glm::dvec3 base(rng.integer(-3, 3), rng.integer(-3, 3), rng.integer(-3, 3));
            Tri t;
            for (auto& p : t) p = base + glm::dvec3(rng.uniform(-1.5, 2.5), rng.uniform(-1.5, 2.5), rng.uniform(-1.5, 2.5));
            const auto i = std::int64_t(base.x), j = std::int64_t(base.y), k = std::int64_t(base.z);
            const bool want = expected_overlap(t, i, j, k);
            (want ? overlaps : misses)++;
            check(t, i, j, k, want, "random triangle " + std::to_string(n));
        }
        CHECK(overlaps > 500);
        CHECK(misses > 500);
    }
    TEST_CASE("triangle-box: triangles only an edge cross-product axis separates" * geolab::points(2) *
              geolab::hint("when neither the box's normals nor the triangle's normal separate, one of the nine "
                           "axes e_d × (triangle edge) may: test all nine")) {
        // found by search: the face axes do not separate them, clipping says they miss the box
        Rng rng(13);
        int found = 0, centred = 0;
        for (int n = 0; n < 200000 && found < 300; ++n) {
            Tri t;
            const glm::dvec3 c(rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3));
            for (auto& p : t) p = c + glm::dvec3(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
            if (separated_by_face_axes(t)) continue;
            if (expected_overlap(t, 0, 0, 0)) continue;
            ++found;
            check(t, 0, 0, 0, false, "edge-axis case " + std::to_string(found));
            // the same triangle moved into voxel (5, -2, 7)
            Tri u = t;
            for (auto& p : u) p += glm::dvec3(5, -2, 7);
            check(u, 5, -2, 7, false, "edge-axis case moved");
            // and moved so that its centroid is the voxel's centre: now it meets the open voxel ("false" always fails)
            Tri w = t;
            const glm::dvec3 shift = glm::dvec3(0.5) - (t[0] + t[1] + t[2]) / 3.0;
            for (auto& p : w) p += shift;
            if (expected_overlap(w, 0, 0, 0)) {
                check(w, 0, 0, 0, true, "edge-axis case centred on the voxel");
                ++centred;
            }
        }
        CHECK_MESSAGE(found >= 100, "test self-check: only " << found << " edge-axis cases found");
        CHECK_MESSAGE(centred >= 100, "test self-check: only " << centred << " centred cases");
    }
    TEST_CASE("triangle-box: touching a face; an edge or a corner only is no overlap" * geolab::points(2) *
              geolab::hint("the voxel is open: a projection that only touches the box's projection separates")) {
        // a triangle in the plane x = 1.5 touching voxel (0,0,0)'s face? no: these touch the box [0,1]^3 from outside
        check({glm::dvec3(1, 0.2, 0.2), glm::dvec3(2, 0.5, 0.2), glm::dvec3(1.5, 0.5, 0.9)}, 0, 0, 0, false, "touches face x = 1 at a vertex");
        check({glm::dvec3(1, 0.2, 0.2), glm::dvec3(1, 0.8, 0.3), glm::dvec3(2, 0.5, 0.9)}, 0, 0, 0, false, "touches face x = 1 along an edge");
        check({glm::dvec3(1, 1, 0.5), glm::dvec3(2, 1.5, 0.2), glm::dvec3(1.5, 2, 0.8)}, 0, 0, 0, false, "touches edge x = y = 1 at a vertex");
        check({glm::dvec3(1, 1, 1), glm::dvec3(2, 1.5, 1.2), glm::dvec3(1.5, 2, 1.8)}, 0, 0, 0, false, "touches the corner (1,1,1)");
        check({glm::dvec3(2, 0, 0), glm::dvec3(0, 2, 0), glm::dvec3(0, 0, 2)}, 0, 0, 0, true, "the plane x+y+z = 2 cuts the box");
        check({glm::dvec3(3, 0, 0), glm::dvec3(0, 3, 0), glm::dvec3(0, 0, 3)}, 0, 0, 0, false, "x+y+z = 3 touches the corner (1,1,1)");
        check({glm::dvec3(3, 0, 0), glm::dvec3(0, 3, 0), glm::dvec3(0, 0, 3)}, 1, 1, 0, true, "x+y+z = 3 cuts voxel (1,1,0)");
        check({glm::dvec3(-1, 0.5, 0.5), glm::dvec3(2, 0.5, 0.5), glm::dvec3(0.5, 0.5, 2)}, 0, 0, 0, true, "a triangle through the centre");
        check({glm::dvec3(-1, 1, 0.5), glm::dvec3(2, 1, 0.5), glm::dvec3(0.5, 2, 0.5)}, 0, 0, 0, false, "edge along the face y = 1, outside");
        check({glm::dvec3(-1, 1, 0.5), glm::dvec3(2, 1, 0.5), glm::dvec3(0.5, 0, 0.5)}, 0, 0, 0, true, "edge along the face y = 1, inside");
        // the same contacts from the other side (the projections end exactly where the box's begin)
        check({glm::dvec3(1, 0.2, 0.2), glm::dvec3(0, 0.5, 0.2), glm::dvec3(0.5, 0.5, 0.9)}, 1, 0, 0, false, "touches face x = 1 of voxel (1,0,0) from below");
        check({glm::dvec3(0.2, 2, 0.2), glm::dvec3(0.5, 1, 0.2), glm::dvec3(0.8, 1.5, 0.9)}, 0, 2, 0, false, "touches face y = 2 of voxel (0,2,0) from below");
        check({glm::dvec3(0.2, 0.3, 0), glm::dvec3(0.5, 0.8, -1), glm::dvec3(0.8, 0.4, 0)}, 0, 0, 0, false, "touches face z = 0 from below along an edge");
        check({glm::dvec3(3, 0, 0), glm::dvec3(0, 0, 3), glm::dvec3(0, 3, 0)}, 0, 0, 0, false, "x+y+z = 3 (normal -(1,1,1)) touches the corner (1,1,1)");
        check({glm::dvec3(0, 2, 1.5), glm::dvec3(2, 0, 1.5), glm::dvec3(0, 0, 1.5)}, 1, 1, 1, false,
              "in the plane z = 1.5, its edge x+y = 2 touches the box edge x = y = 1 (only the axis z x (1,-1,0) separates)");
        check({glm::dvec3(0, 2, 1.5), glm::dvec3(2.01, 0, 1.5), glm::dvec3(0, 0, 1.5)}, 1, 1, 1, true, "the same edge moved 0.005 into the box");
    }
    TEST_CASE("triangle-box: a triangle in a voxel plane belongs to the layer behind its normal" * geolab::points(2) *
              geolab::hint("all three x equal to an integer m: normal +x → layer m − 1, normal −x → layer m; in the plane, "
                           "the open square test")) {
        const Tri px = {glm::dvec3(3, 0.2, 0.2), glm::dvec3(3, 0.8, 0.2), glm::dvec3(3, 0.5, 0.9)};  // normal +x
        check(px, 2, 0, 0, true, "x = 3, normal +x");
        check(px, 3, 0, 0, false, "x = 3, normal +x");
        const Tri mx = {px[0], px[2], px[1]};
        check(mx, 3, 0, 0, true, "x = 3, normal -x");
        check(mx, 2, 0, 0, false, "x = 3, normal -x");
        const Tri pz = {glm::dvec3(0, 0, -2), glm::dvec3(2, 0, -2), glm::dvec3(0, 2, -2)};  // normal +z, covers 2x2 half
        check(pz, 0, 0, -3, true, "z = -2, normal +z");
        check(pz, 1, 0, -3, true, "z = -2, normal +z");
        check(pz, 1, 1, -3, false, "z = -2, normal +z: the hypotenuse only touches the corner of voxel (1,1)");
        check(pz, 0, 0, -2, false, "z = -2, normal +z");
        check(pz, 2, 0, -3, false, "z = -2, normal +z: touches the square's edge x = 2 only");
        const Tri py = {glm::dvec3(0, 5, 0), glm::dvec3(0, 5, 1), glm::dvec3(1, 5, 0)};  // normal (0,0,1)x(1,0,0) = +y
        check(py, 0, 4, 0, true, "y = 5, normal +y");
        check(py, 0, 5, 0, false, "y = 5, normal +y");
        // the normal's sign from (b − a) × (c − a) with vertices far from the origin
        const Tri f1 = {glm::dvec3(0, 5, 1), glm::dvec3(1, 5, 1), glm::dvec3(1, 6, 1)};  // normal +z
        check(f1, 0, 5, 0, true, "z = 1, normal +z, y from 5 to 6");
        check(f1, 0, 5, 1, false, "z = 1, normal +z, y from 5 to 6");
        const Tri f2 = {glm::dvec3(5, 0, 1), glm::dvec3(5, 1, 1), glm::dvec3(4, 1, 1)};  // normal +z
        check(f2, 4, 0, 0, true, "z = 1, normal +z, x from 4 to 5");
        check(f2, 4, 0, 1, false, "z = 1, normal +z, x from 4 to 5");
        // not on a voxel plane: an ordinary open test
        const Tri half = {glm::dvec3(3.5, 0.2, 0.2), glm::dvec3(3.5, 0.8, 0.2), glm::dvec3(3.5, 0.5, 0.9)};
        check(half, 3, 0, 0, true, "x = 3.5");
        check(half, 2, 0, 0, false, "x = 3.5");
    }
    TEST_CASE("triangle-box: a zero-area triangle belongs to no voxel" * geolab::points(1) *
              geolab::hint("(b − a) × (c − a) = 0: no voxel")) {
        check({glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0.5, 0.5, 0.5)}, 0, 0, 0, false, "a point");
        check({glm::dvec3(-1, 0.5, 0.5), glm::dvec3(2, 0.5, 0.5), glm::dvec3(0.5, 0.5, 0.5)}, 0, 0, 0, false, "a segment");
        check({glm::dvec3(0.2, 0.2, 0.2), glm::dvec3(0.4, 0.4, 0.4), glm::dvec3(0.9, 0.9, 0.9)}, 0, 0, 0, false, "collinear");
        // the same places with a little area do belong ("no voxel, ever" is not the rule)
        check({glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0.5 + 1e-6, 0.5, 0.5), glm::dvec3(0.5, 0.5 + 1e-6, 0.5)}, 0, 0, 0, true,
              "a tiny triangle at the centre");
        check({glm::dvec3(0.2, 0.2, 0.2), glm::dvec3(0.4, 0.4, 0.4), glm::dvec3(0.9, 0.9, 0.8)}, 0, 0, 0, true,
              "almost collinear");
        check({glm::dvec3(3, 2, 2), glm::dvec3(2, 3, 2), glm::dvec3(2, 2, 3)}, 2, 2, 2, true, "normal (1, 1, 1), through the voxel");
    }
}
