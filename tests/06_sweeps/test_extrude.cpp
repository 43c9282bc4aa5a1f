// Lab 06, Task 3: extrusion. Expected values: closed forms (prism V = A·h, frustum V = A·h·(1 + s + s²)/3, areas),
// the vertex layout formula, and lib's check_surface for closedness, orientation and genus.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
glm::dvec3 layer_point(glm::dvec2 q, const ExtrudeOptions& o, int k) {
    const double s = double(k) / o.steps, sc = 1 + s * (o.scale - 1), c = std::cos(s * o.twist), sn = std::sin(s * o.twist);
    return glm::dvec3(sc * (c * q.x - sn * q.y), sc * (sn * q.x + c * q.y), 0) + s * o.direction;
}
}  // namespace

TEST_SUITE("Task 3: extrusion") {
    TEST_CASE("extrude: the 4×4 square with a 2×2 hole; height 1: V = 12; A = 48; closed; genus 1" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Side walls: two triangles per loop edge a→b and step, (a₀, b₀, b₁) and (a₀, b₁, a₁); caps from "
                           "triangulate, the bottom one reversed (handout §4).")) {
        const Profile p = square_with_hole();
        const PolygonSoup m = extrude(p, {});
        INFO("input: " << str(p) << ", direction (0, 0, 1), 1 step");
        CHECK_MESSAGE(close(double(volume_ld(m)), 12.0, 1e-12), "volume: expected 12, got " << double(volume_ld(m)));
        LD area = 0;
        for (std::size_t f = 0; f < m.n_faces(); ++f) area += glm::length(tri_normal(m, f)) / 2;
        CHECK_MESSAGE(close(double(area), 48.0, 1e-12), "area: expected 48, got " << double(area));
        const std::string bad = surface_problem(m, 0, 1);
        CHECK_MESSAGE(bad.empty(), "expected a closed oriented torus-like solid (χ = 0, genus 1):" << bad);
        CHECK_MESSAGE(m.n_vertices() == 16, "expected 16 vertices (8 profile points × 2 layers), got " << m.n_vertices());
    }

    TEST_CASE("extrude: vertices layer by layer; scaled; turned and moved as the contract says" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Layer k at s = k/steps: scale by 1 + s(scale − 1), turn by s·twist about z, then add "
                           "s·direction; profile_points order inside a layer.")) {
        Rng rng(81);
        for (int n = 0; n < 8; ++n) {
            const Profile p = star_with_holes(rng, rng.integer(5, 20), n % 3);
            ExtrudeOptions o{{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 3)}, rng.integer(1, 9),
                             rng.uniform(-2, 2), rng.uniform(0.3, 2)};
            if (std::abs(o.twist) / o.steps >= 1.5) o.twist = 0.5 * o.steps;
            const PolygonSoup m = extrude(p, o);
            const auto pts = profile_points(p);
            INFO("input: " << str(p) << "; steps " << o.steps << ", twist " << o.twist << ", scale " << o.scale
                           << ", direction " << str(o.direction));
            REQUIRE_MESSAGE(m.n_vertices() == pts.size() * (o.steps + 1),
                            "expected " << pts.size() * (o.steps + 1) << " vertices, got " << m.n_vertices());
            int bad = 0;
            for (int k = 0; k <= o.steps && bad < 3; ++k)
                for (std::size_t i = 0; i < pts.size() && bad < 3; ++i) {
                    const glm::dvec3 want = layer_point(pts[i], o, k), got = m.positions[k * pts.size() + i];
                    if (glm::length(want - got) > 1e-12 * 10) {
                        ++bad;
                        FAIL_CHECK("layer " << k << ", point " << i << ": expected " << str(want) << ", got " << str(got));
                    }
                }
        }
    }

    TEST_CASE("extrude: twist and scale give closed; oriented solids without self-intersections" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("With the walls' triangles as in the contract and twist per step below 90° no triangle flips; "
                           "check your caps' winding and your wall diagonals.")) {
        Rng rng(82);
        for (int n = 0; n < 6; ++n) {
            const Profile p = star_with_holes(rng, rng.integer(5, 16), n % 3);
            const ExtrudeOptions o{{0.2, -0.1, 2}, 12, rng.uniform(-2.5, 2.5), rng.uniform(0.4, 1.5)};
            const PolygonSoup m = extrude(p, o);
            INFO("input: " << str(p) << "; twist " << o.twist << " over 12 steps, scale " << o.scale);
            const std::string bad = surface_problem(m, 2 - 2 * long(p.holes.size()), 1);
            CHECK_MESSAGE(bad.empty(), "expected a closed oriented solid of genus " << p.holes.size() << ":" << bad);
            // No flipped wall triangle: each wall normal points away from the layer's axis side it bounds.
            const auto pts = profile_points(p);
            const std::size_t n_pts = pts.size();
            std::vector<std::size_t> next(n_pts);  // the successor of each profile point in its loop
            std::size_t start = 0;
            for (std::size_t l = 0; l <= p.holes.size(); ++l) {
                const std::size_t len = l == 0 ? p.outer.size() : p.holes[l - 1].size();
                for (std::size_t i = 0; i < len; ++i) next[start + i] = start + (i + 1) % len;
                start += len;
            }
            std::size_t flipped = 0;
            for (std::size_t f = 0; f < m.n_faces(); ++f) {
                const auto fc = m.face(f);
                const std::size_t k = std::min({fc[0] / n_pts, fc[1] / n_pts, fc[2] / n_pts});
                if (k == std::max({fc[0] / n_pts, fc[1] / n_pts, fc[2] / n_pts})) continue;  // a cap
                // the loop edge a→b the wall triangle comes from, and its outward normal (b − a) × z in layer k
                std::size_t a = fc[0] % n_pts, b = fc[0] % n_pts;
                for (auto i : fc)
                    for (auto j : fc)
                        if (next[i % n_pts] == j % n_pts && i % n_pts != j % n_pts) a = i % n_pts, b = j % n_pts;
                const glm::dvec3 pa = m.positions[k * n_pts + a], pb = m.positions[k * n_pts + b];
                const glm::dvec3 out = glm::cross(pb - pa, glm::dvec3(0, 0, 1));
                if (glm::dot(tri_normal(m, f), out) <= 0) ++flipped;
            }
            CHECK_MESSAGE(flipped == 0, flipped << " wall triangles face inward (flipped)");
        }
    }

    TEST_CASE("extrude: a scaled prism is a frustum; V = A·h·(1 + s + s²)/3; twist keeps the cross-section area" *
              geolab::points(2) *
                        geolab::builds_on("Task 1, Task 2") * geolab::hint("Scale about the origin before moving; the caps are the scaled profile.")) {
        Rng rng(83);
        for (int n = 0; n < 6; ++n) {
            const Profile p = star_with_holes(rng, rng.integer(5, 16), n % 2);
            const double s = rng.uniform(0.3, 2.0), h = rng.uniform(0.5, 3.0);
            const PolygonSoup m = extrude(p, {{0.3, 0.1, h}, rng.integer(1, 5), 0.0, s});
            const double A = double(region_area(p)), want = A * h * (1 + s + s * s) / 3, got = double(volume_ld(m));
            INFO("input: " << str(p) << "; scale " << s << ", height " << h);
            CHECK_MESSAGE(close(got, want, 1e-10), "volume: expected " << want << ", got " << got);
        }
    }

    TEST_CASE("extrude: the caps face outward; the bottom −z and the top +z" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("The triangulation is counter-clockwise seen from +z: keep it for the top, reverse it for the "
                           "bottom.")) {
        const Profile p = square_with_hole();
        const PolygonSoup m = extrude(p, {{0, 0, 2}, 3, 0.6, 0.7});
        std::size_t bottom = 0, top = 0, wrong = 0;
        for (std::size_t f = 0; f < m.n_faces(); ++f) {
            const auto fc = m.face(f);
            const double z0 = m.positions[fc[0]].z, z1 = m.positions[fc[1]].z, z2 = m.positions[fc[2]].z;
            if (z0 != z1 || z1 != z2) continue;
            const glm::dvec3 nrm = tri_normal(m, f);
            if (z0 == 0) ++bottom, wrong += nrm.z >= 0;
            else ++top, wrong += nrm.z <= 0;
        }
        CHECK_MESSAGE(bottom == 8, "expected 8 bottom cap triangles, got " << bottom);
        CHECK_MESSAGE(top == 8, "expected 8 top cap triangles, got " << top);
        CHECK_MESSAGE(wrong == 0, wrong << " cap triangles face into the solid");
    }

    TEST_CASE("extrude: bad options and invalid profiles are rejected" * geolab::points(1) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("std::invalid_argument for steps < 1, direction.z ≤ 0, scale ≤ 0, non-finite values, a twist "
                           "of a quarter turn or more per step, and invalid profiles.")) {
        const Profile p = square_with_hole();
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 0, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, -1}, 1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{1, 0, 0}, 1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 1, 0, 0}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 2, 3.2, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 2, pi, 1}), std::invalid_argument);  // exactly a quarter turn a step
        CHECK_THROWS_AS(extrude(p, {{0, 0, NAN}, 1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{NAN, 0, 1}, 1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, INFINITY, 1}, 1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 1, NAN, 1}), std::invalid_argument);
        CHECK_THROWS_AS(extrude(p, {{0, 0, 1}, 1, 0, INFINITY}), std::invalid_argument);
        Profile q = p;
        q.holes[0] = reversed(q.holes[0]);
        CHECK_THROWS_AS(extrude(q, {}), std::invalid_argument);
        CHECK_NOTHROW(extrude(p, {{0, 0, 1}, 2, 3.1, 1}));
    }
}  // TEST_SUITE
