// Lab 03, Task 7: images. Expected pixels from the ray–sphere distance computed here (the camera's rays are given code).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab03;

namespace {
// Compares the image with a sphere (centre c, radius r) seen by cam, Lambert-shaded; pixels within 1e-3 of the
// silhouette are skipped. Returns the number of hit pixels.
int check_sphere_image(const geolab::render::Image& img, const PinholeCamera& cam, glm::dvec3 c, double r,
                       glm::dvec3 light, int w, int h, const std::string& what) {
    REQUIRE_MESSAGE((img.width == w && img.height == h && img.rgba.size() == std::size_t(4 * w * h)),
                    what << ": expected a " << w << "x" << h << " image, got " << img.width << "x" << img.height
                         << " with " << img.rgba.size() << " bytes");
    const glm::dvec3 l = glm::normalize(light);
    int hits = 0, bad = 0, exact = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Ray ray = cam.ray(x, y, w, h);
            const glm::dvec3 d = glm::normalize(ray.direction), oc = c - ray.origin;
            const double along = glm::dot(oc, d);
            const double miss2 = glm::dot(oc, oc) - along * along;  // squared distance from c to the line
            if (std::abs(std::sqrt(std::max(0.0, miss2)) - r) < 1e-3) continue;
            int want = 0;
            if (miss2 < r * r && along > 0) {
                const double t = along - std::sqrt(r * r - miss2);
                const glm::dvec3 n = (ray.origin + t * d - c) / r;
                want = int(std::lround(255 * (0.1 + 0.9 * std::abs(glm::dot(n, l)))));
                ++hits;
            }
            const auto px = img.pixel(x, y);
            if (want > 0 && int(px[0]) == want) ++exact;
            if ((std::abs(int(px[0]) - want) > 1 || px[1] != px[0] || px[2] != px[0] || px[3] != 255) && bad++ < 5)
                FAIL_CHECK(what << ": pixel (" << x << ", " << y << ") should be gray " << want << " with alpha 255, got ("
                                << int(px[0]) << ", " << int(px[1]) << ", " << int(px[2]) << ", " << int(px[3]) << ")");
        }
    CHECK_MESSAGE(bad == 0, what << ": " << bad << " pixels differ");
    // ±1 is allowed for rounding at .5; most pixels must be exactly round(255 v)
    CHECK_MESSAGE(exact >= 0.8 * hits, what << ": only " << exact << " of " << hits
                                            << " lit pixels are exactly round(255 v): scale by 255, round to nearest");
    return hits;
}
}  // namespace

TEST_SUITE("Task 7: images") {
    TEST_CASE("images: a quadric sphere in a box; Lambert-shaded; pixel by pixel" * geolab::points(2) *
              geolab::builds_on("Task 4") *
              geolab::hint("One ray per pixel from camera.ray(x, y, w, h); the first hit of intersect_in_box; v = 0.1 + "
                           "0.9·|n·l| with l normalized; round(255 v) in R, G, B; alpha 255; a miss is 0.")) {
        const PinholeCamera cam{{0.5, 1, 6}, {0, 0, 0}, {0, 1, 0}, 35};
        Scene scene;
        scene.Q = matrix_of({1, 1, 1, 0, 0, 0, -0.2, 0.1, 0, 0.04 + 0.01 - 1.21});  // centre (0.2, −0.1, 0), r = 1.1
        scene.box = {{-3, -3, -3}, {3, 3, 3}};
        scene.light = {1, 2, 3};
        const auto img = render_lambert(scene, cam, 40, 30);
        const int hits = check_sphere_image(img, cam, {0.2, -0.1, 0}, 1.1, scene.light, 40, 30, "quadric sphere");
        CHECK(hits > 50);
        CHECK_THROWS_AS(render_lambert(scene, cam, 0, 10), std::invalid_argument);
        CHECK_THROWS_AS(render_lambert(scene, cam, 10, 0), std::invalid_argument);
        CHECK_THROWS_AS(render_lambert(scene, cam, -3, 5), std::invalid_argument);
        const auto one = render_lambert(scene, cam, 1, 1);  // one pixel: the ray through the centre hits the sphere
        REQUIRE_MESSAGE((one.width == 1 && one.height == 1 && one.rgba.size() == 4u), "a 1x1 image must work");
        CHECK(one.rgba[0] > 0);
        const auto row = render_lambert(scene, cam, 7, 1);
        CHECK((row.width == 7 && row.height == 1));
        const auto column = render_lambert(scene, cam, 1, 5);
        CHECK((column.width == 1 && column.height == 5));
    }

    TEST_CASE("images: a superquadric (ε = 1: an ellipsoid of equal radii) renders the same sphere" * geolab::points(2) *
              geolab::builds_on("Task 5") *
              geolab::hint("For a superquadric scene use intersect_superquadric from t = 0; the shading is the same.")) {
        const PinholeCamera cam{{-2, 3, 5}, {0, 0, 0}, {0, 1, 0}, 30};
        Scene scene;
        scene.is_superquadric = true;
        scene.sq = {{1.3, 1.3, 1.3}, 1, 1};
        scene.light = {-1, 0.5, 2};
        const auto img = render_lambert(scene, cam, 36, 28);
        const int hits = check_sphere_image(img, cam, {0, 0, 0}, 1.3, scene.light, 36, 28, "superquadric sphere");
        CHECK(hits > 50);
        // the camera 0.4 from the surface: hits at t < 1 count too (t >= 0)
        const PinholeCamera near{{0.3, 0.2, 1.7}, {0, 0, 0}, {0, 1, 0}, 60};
        const auto img2 = render_lambert(scene, near, 24, 18);
        CHECK(check_sphere_image(img2, near, {0, 0, 0}, 1.3, scene.light, 24, 18, "superquadric sphere, camera close") > 50);
    }
}  // TEST_SUITE
