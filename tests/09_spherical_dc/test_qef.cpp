// Lab 09, Task 1: the quadratic error function (handout §2). Every test builds Qefs with Qef::add and calls
// Qef::solve / Qef::error, so an unimplemented stub fails them all.
#include <Eigen/Eigenvalues>

#include "helpers.hpp"

using namespace lab09;

namespace {
// Brute-force Q(x) = Σ (nᵢ · (x − pᵢ))².
struct Planes {
    std::vector<glm::dvec3> p, n;
    void add(const glm::dvec3& point, const glm::dvec3& normal) { p.push_back(point), n.push_back(glm::normalize(normal)); }
    Qef qef() const {
        Qef q;
        for (std::size_t i = 0; i < p.size(); ++i) q.add(p[i], n[i]);
        return q;
    }
    double error(const glm::dvec3& x) const {
        double s = 0;
        for (std::size_t i = 0; i < p.size(); ++i) s += std::pow(glm::dot(n[i], x - p[i]), 2);
        return s;
    }
    glm::dvec3 mass() const {
        glm::dvec3 m(0.0);
        for (auto& q : p) m += q;
        return m / double(p.size());
    }
};

// The truncated pseudo-inverse solution computed independently: Eigen's symmetric eigen-solver on AtA (summed here
// from the planes), the right-hand side about the mass point as sum n (n . (p - m)).
struct Reference {
    glm::dvec3 x{0.0};
    int rank = 0;
    double ratio_near_threshold = 0.0;  // the eigenvalue ratio (lambda / lambda_max) nearest tau
};
Reference eigen_reference(const Planes& pl, double tau) {
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    const glm::dvec3 m = pl.mass();
    for (std::size_t i = 0; i < pl.p.size(); ++i) {
        const Eigen::Vector3d n(pl.n[i].x, pl.n[i].y, pl.n[i].z);
        ata += n * n.transpose();
        r += n * glm::dot(pl.n[i], pl.p[i] - m);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(ata);
    const Eigen::Vector3d lambda = es.eigenvalues();
    const double lmax = lambda.cwiseAbs().maxCoeff();
    Reference out;
    out.x = m;
    double nearest = 1e300;
    for (int i = 0; i < 3; ++i) {
        const double ratio = lambda(i) / lmax;
        if (std::abs(ratio - tau) < std::abs(nearest - tau)) nearest = ratio;
        if (lambda(i) < tau * lmax) continue;
        const Eigen::Vector3d e = es.eigenvectors().col(i);
        const double c = e.dot(r) / lambda(i);
        out.x += c * glm::dvec3(e(0), e(1), e(2));
        ++out.rank;
    }
    out.ratio_near_threshold = nearest;
    return out;
}
}  // namespace

TEST_SUITE("Task 1: QEF") {

TEST_CASE("qef: rank 1 near-planar data gives the mass point projected onto the plane" * geolab::points(1) *
          geolab::hint("tau = 0.01 truncates every eigenvalue of AtA below 0.01 * lambda_max: a (nearly) flat patch "
                       "has rank 1, and the solution must not drift along the plane. Solve about the mass point m: "
                       "x = m + (AtA)+ (Atb - AtA m). Handout §2.2.")) {
    // points on the plane z = 2.3 spread over a unit cell far from the origin, normals tilted by up to 2e-3 rad
    Lcg rng(7);
    Planes pl;
    const glm::dvec3 cell(5.0, -3.0, 2.0);
    for (int i = 0; i < 12; ++i) {
        glm::dvec3 p = cell + glm::dvec3(rng.uniform(), rng.uniform(), 0.0);
        p.z = 2.3;
        pl.add(p, glm::dvec3(rng.uniform(-2e-3, 2e-3), rng.uniform(-2e-3, 2e-3), 1.0));
    }
    const Qef q = pl.qef();
    int rank = -1;
    glm::dvec3 m(0.0);
    const glm::dvec3 x = q.solve(0.01, &m, &rank);
    glm::dvec3 expected = pl.mass();
    expected.z = 2.3;
    INFO("12 points on z = 2.3 in the cell [5,6]x[-3,-2], normals within 2e-3 rad of +Z");
    INFO("solve returned " << str(x) << ", expected about " << str(expected) << ", rank " << rank);
    CHECK(rank == 1);
    CHECK(glm::length(m - pl.mass()) < 1e-12);
    CHECK_MESSAGE(glm::length(glm::dvec2(x.x - expected.x, x.y - expected.y)) < 1e-2,
                  "the solution drifted along the plane (no truncation, or not solved about the mass point)");
    CHECK(std::abs(x.z - 2.3) < 1e-2);
    // exactly planar: exact projection of the mass point
    Planes flat;
    for (int i = 0; i < 5; ++i) flat.add(cell + glm::dvec3(0.2 * i, 0.9 - 0.15 * i, 0.25), glm::dvec3(0, 0, 1));
    const glm::dvec3 y = flat.qef().solve(0.01, nullptr, &rank);
    glm::dvec3 ey = flat.mass();
    CAPTURE(str(y));
    CHECK(rank == 1);
    CHECK(glm::length(y - ey) < 1e-9);
}

TEST_CASE("qef: rank 2 edge gives the point of the edge line nearest the mass point" * geolab::points(1) *
          geolab::hint("Two plane families (a sharp edge) determine 2 directions; along the edge line the solution "
                       "keeps the mass point's coordinate. Handout §2.2.")) {
    // planes n1·x = d1 and n2·x = d2 (60 degrees apart), points along their common line and off it on each plane
    const glm::dvec3 n1 = glm::normalize(glm::dvec3(1, 0, 0.2)), n2 = glm::normalize(glm::dvec3(-0.5, 0.866, 0.1));
    const glm::dvec3 dir = glm::normalize(glm::cross(n1, n2));
    const glm::dvec3 on_line(0.7, -0.4, 1.3);  // a point of the edge line
    Planes pl;
    Lcg rng(11);
    for (int i = 0; i < 6; ++i) {
        glm::dvec3 t1 = glm::normalize(glm::cross(n1, dir));  // in plane 1, away from the edge
        glm::dvec3 t2 = glm::normalize(glm::cross(n2, dir));
        pl.add(on_line + rng.uniform(-0.3, 0.3) * dir + rng.uniform(0.0, 0.2) * t1, n1);
        pl.add(on_line + rng.uniform(-0.3, 0.3) * dir + rng.uniform(0.0, 0.2) * t2, n2);
    }
    int rank = -1;
    const glm::dvec3 x = pl.qef().solve(0.01, nullptr, &rank);
    // expected: on the line, at the mass point's coordinate along it
    const glm::dvec3 expected = on_line + glm::dot(pl.mass() - on_line, dir) * dir;
    INFO("solve returned " << str(x) << ", expected " << str(expected) << ", rank " << rank);
    CHECK(rank == 2);
    CHECK(glm::length(x - expected) < 1e-9);
}

TEST_CASE("qef: rank 3 box corner is solved exactly" * geolab::points(1) *
          geolab::hint("Three independent normals: no truncation, x is the exact intersection of the planes.")) {
    for (int rotated = 0; rotated < 2; ++rotated) {
        const glm::dvec3 corner(1.25, -0.5, 3.0);
        glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        if (rotated) {
            axes[0] = glm::normalize(glm::dvec3(1, 1, 0));
            axes[1] = glm::normalize(glm::dvec3(-1, 1, 1));
            axes[2] = glm::normalize(glm::cross(axes[0], axes[1]));
        }
        Planes pl;
        // 3 faces of the box at the corner, 3 points each
        for (int a = 0; a < 3; ++a)
            for (int k = 1; k <= 3; ++k)
                pl.add(corner - 0.1 * k * axes[(a + 1) % 3] - 0.07 * (4 - k) * axes[(a + 2) % 3], axes[a]);
        int rank = -1;
        const Qef q = pl.qef();
        const glm::dvec3 x = q.solve(0.01, nullptr, &rank);
        INFO((rotated ? "rotated" : "axis-aligned") << " corner " << str(corner) << ": solve returned " << str(x)
                                                    << ", rank " << rank);
        CHECK(rank == 3);
        CHECK(glm::length(x - corner) < 1e-9);
        CHECK(std::abs(q.error(x)) < 1e-12);
    }
}

TEST_CASE("qef: cone tips: a sharp tip is kept (rank 3); a needle or a nearly flat tip is truncated" *
          geolab::points(1) *
          geolab::hint("The tangent planes around a cone's apex have eigenvalues k sin^2(g) along the axis and "
                       "k cos^2(g)/2 across it (g the half-angle): tau = 0.01 keeps all three for g = 40 degrees (x "
                       "is the apex), drops the axis for a needle (g = 3: x on the axis at the mass point's height) "
                       "and drops both cross directions for a nearly flat tip (g = 87: x moves from the mass point "
                       "along the axis only). Handout §1.")) {
    const glm::dvec3 apex(0.3, -0.2, 0.5), u = glm::normalize(glm::dvec3(1, 2, 2));
    const glm::dvec3 e1 = glm::normalize(glm::cross(u, glm::dvec3(1, 0, 0))), e2 = glm::cross(u, e1);
    struct Case {
        double degrees;
        int rank;
        double arc;  // the generators cover this fraction of the circle around the axis
    } cases[] = {{40.0, 3, 1.0}, {3.0, 2, 1.0}, {87.0, 1, 0.5}};
    for (const Case& cs : cases) {
        const double g = cs.degrees * kPi / 180.0;
        // 12 generators × 3 distances from the apex; n ⟂ the generator, pointing away from the axis. Every tangent
        // plane contains the apex, so an untruncated solve always returns the apex.
        Planes pl;
        for (int i = 0; i < 12; ++i) {
            const double phi = 2.0 * kPi * cs.arc * i / 12.0;
            const glm::dvec3 radial = std::cos(phi) * e1 + std::sin(phi) * e2;
            for (double t : {0.05, 0.1, 0.2})
                pl.add(apex + t * (std::cos(g) * u + std::sin(g) * radial), -std::sin(g) * u + std::cos(g) * radial);
        }
        const Qef q = pl.qef();
        int rank = -1;
        glm::dvec3 m;
        const glm::dvec3 x = q.solve(0.01, &m, &rank);
        INFO("cone with half-angle " << cs.degrees << " degrees, apex " << str(apex) << ", axis " << str(u)
                                     << ": solve returned " << str(x) << ", rank " << rank << ", mass point "
                                     << str(m));
        CHECK(rank == cs.rank);
        if (cs.rank == 3) CHECK(glm::length(x - apex) < 1e-9);
        if (cs.rank == 2) {
            CHECK(std::abs(glm::dot(x - m, u)) < 1e-9);                                // keeps m's axis coordinate
            CHECK(glm::length(x - (apex + glm::dot(m - apex, u) * u)) < 1e-9);        // on the axis
        }
        if (cs.rank == 1) {  // half a circle of generators: the mass point is off the axis, and so stays x
            const glm::dvec3 off_axis = (m - apex) - glm::dot(m - apex, u) * u;
            CHECK(glm::length(off_axis) > 0.05);
            CHECK(glm::length(x - apex) > 0.5 * glm::length(off_axis));  // not pulled to the ill-determined apex
        }
    }
}

TEST_CASE("qef: near-planar and near-threshold data match an independent eigen-solver (Eigen) to 1e-9 of the cell" *
          geolab::points(2) *
          geolab::hint("Truncated pseudo-inverse about the mass point: x = m + sum over kept eigenpairs of "
                       "e (e . (Atb - AtA m)) / lambda, kept when lambda >= tau * lambda_max. Near-planar data (normals "
                       "tilted slightly around a slanted plane) have two tiny eigenvalues: any shortcut for that case "
                       "(rank 1) must give the same point as the full decomposition. Eigenvalue ratios 2% on either side "
                       "of tau decide the rank. Handout §1.")) {
    // normals n0 + tilt (ea cos(phi) a + eb sin(phi) b), normalised: eigenvalue ratios about ea^2 / 2 and eb^2 / 2
    Lcg rng(2024);
    int checked = 0, ranks[4] = {0, 0, 0, 0};
    for (const glm::dvec3 base : {glm::dvec3(0.3, -0.5, 0.8), glm::dvec3(0.3, 0.5, 0.8)}) {
    const glm::dvec3 n0 = glm::normalize(base);
    const glm::dvec3 a = glm::normalize(glm::cross(n0, glm::dvec3(1, 0, 0))), b = glm::cross(n0, a);
    struct Case {
        double ratio_a, ratio_b;  // target eigenvalue ratios of the two tilt directions
        double cell;              // the cell size the points are spread over
    } cases[] = {{1e-12, 1e-12, 1.0}, {1e-8, 3e-9, 0.01},  {1e-5, 1e-6, 0.25},  {1e-3, 1e-3, 1.0},
                 {2.4e-3, 2.4e-3, 0.1}, {4.4e-3, 3e-4, 1.0}, {5.6e-3, 1e-3, 0.5}, {9.0e-3, 8.0e-3, 2.0},
                 {0.0096, 1e-4, 1.0},   {0.0106, 1e-4, 1.0}, {0.0106, 0.0096, 0.3}, {0.03, 0.0096, 1.0},
                 {0.03, 0.0108, 0.7}};
    for (const Case& cs : cases) {
        Planes pl;
        const glm::dvec3 corner(5.0, -3.0, 2.0);
        const int count = 16;
        const double ea = std::sqrt(2.0 * cs.ratio_a), eb = std::sqrt(2.0 * cs.ratio_b);
        for (int i = 0; i < count; ++i) {
            const double phi = 2.0 * kPi * (i + 0.25 * rng.uniform()) / count;
            // points near a slanted plane through the cell, slightly curved (not all on one plane)
            const double u = rng.uniform(), v = rng.uniform();
            const glm::dvec3 p = corner + cs.cell * (glm::dvec3(0.5) + (u - 0.5) * a + (v - 0.5) * b +
                                                     0.02 * (u * u + v * v - 0.5) * n0);
            pl.add(p, n0 + ea * std::cos(phi) * a + eb * std::sin(phi) * b);
        }
        const double tau = 0.01;
        const Reference ref = eigen_reference(pl, tau);
        INFO("16 planes in a cell of size " << cs.cell << " at " << str(corner) << ", normals tilted around "
                                            << str(n0) << " (target eigenvalue ratios " << cs.ratio_a << ", "
                                            << cs.ratio_b << "; Eigen's ratio nearest tau " << ref.ratio_near_threshold
                                            << ")");
        // the test's own data must keep clear of the threshold (2% of tau)
        REQUIRE(std::abs(ref.ratio_near_threshold - tau) > 1e-4);
        const Qef q = pl.qef();
        int rank = -1;
        const glm::dvec3 x = q.solve(tau, nullptr, &rank);
        INFO("solve returned " << str(x) << " with rank " << rank << "; Eigen's truncated pseudo-inverse gives "
                               << str(ref.x) << " with rank " << ref.rank << " (difference "
                               << glm::length(x - ref.x) / cs.cell << " cell)");
        CHECK(rank == ref.rank);
        CHECK(glm::length(x - ref.x) <= 1e-9 * cs.cell);
        ++checked;
        ranks[ref.rank] += 1;
    }
    }
    CHECK(ranks[1] >= 18);  // the data cover ranks 1 to 3
    CHECK(ranks[2] >= 4);
    CHECK(ranks[3] >= 2);
    CHECK(checked == 26);
}

TEST_CASE("qef: weighted planes (AtA and Atb and btb scaled by one w) give the same point and rank" * geolab::points(1) *
          geolab::hint("Qef's fields may hold weighted planes (sum of w n n^T): scaling AtA, Atb and btb by one w > 0 "
                       "does not move the minimiser, and the truncation (lambda < tau * lambda_max) is relative. Any "
                       "threshold or shortcut in solve must compare eigenvalues with each other (or with the trace), "
                       "never with an absolute number such as 1. Handout §1.")) {
    int checked = 0;
    // edges: two planes whose normals make an angle theta (eigenvalue ratio (1 - cos) / (1 + cos): 0.0130 at 13
    // degrees, above tau = 0.01, so rank 2), a near-flat fan of 5 planes, and a corner
    for (int shape = 0; shape < 6; ++shape) {
        Planes pl;
        const glm::dvec3 p0(1.5, -0.5, 2.0), axis = glm::normalize(glm::dvec3(0.2, 1.0, -0.4));
        const glm::dvec3 n0 = glm::normalize(glm::cross(axis, glm::dvec3(1, 0, 0))), n1 = glm::cross(axis, n0);
        const double theta_deg[] = {13.0, 14.0, 15.0, 40.0};
        if (shape < 4) {
            const double t = theta_deg[shape] * kPi / 180.0;
            pl.add(p0 + 0.1 * axis, n0);
            pl.add(p0 + 0.05 * n1 - 0.2 * axis, std::cos(t) * n0 + std::sin(t) * n1);
        } else if (shape == 4) {
            for (int i = 0; i < 5; ++i) pl.add(p0 + 0.03 * i * n1 + 0.02 * i * axis, n0 + 0.15 * (i - 2) * n1);
        } else {
            pl.add(p0 + glm::dvec3(0.1, 0, 0), {1, 0, 0});
            pl.add(p0 + glm::dvec3(0, 0.1, 0), {0, 1, 0});
            pl.add(p0 + glm::dvec3(0, 0, 0.1), {0.2, 0.1, 1});
        }
        const double tau = 0.01;
        const Reference ref = eigen_reference(pl, tau);
        REQUIRE(std::abs(ref.ratio_near_threshold - tau) > 1e-4);
        for (double w : {1e-3, 0.2, 0.25, 0.4, 0.7, 3.0, 1e3}) {
            Qef q = pl.qef();
            for (double& e : q.ata) e *= w;
            q.atb *= w;
            q.btb *= w;
            int rank = -1;
            const glm::dvec3 x = q.solve(tau, nullptr, &rank);
            INFO("shape " << shape << " (" << (shape < 4 ? "an edge of two planes" : shape == 4 ? "a fan of 5 planes" : "a corner")
                          << "), weight " << w << ": solve gave " << str(x) << " rank " << rank
                          << "; the unweighted truncated pseudo-inverse (Eigen) gives " << str(ref.x) << " rank " << ref.rank);
            CHECK(rank == ref.rank);
            CHECK(glm::length(x - ref.x) <= 1e-9);
            ++checked;
        }
    }
    CHECK(checked == 42);
}

TEST_CASE("qef: any axis order; normals in a coordinate plane; equal diagonals; weights 1e-100 to 1e12; one plane; "
          "tau 0.01 to 1.5: all match Eigen" *
          geolab::points(1) *
          geolab::hint("solve must not depend on which axis the data favour: permuting x, y, z permutes the answer. "
                       "Cases that trip hand-written solvers: AtA entries that are exactly 0 (normals in a coordinate "
                       "plane) or equal diagonal entries (a Jacobi rotation with a[q][q] - a[p][p] = 0 must still zero "
                       "a[p][q]), all entries 1e-9 or 1e-100 (convergence tests must be relative; products of four entries "
                       "underflow to 0), the largest eigenvalue "
                       "in any slot (lambda_max is the largest of all three), one plane alone (rank 1), and tau >= 1 "
                       "(tau = 1 keeps lambda_max only: it is not below 1 * lambda_max; tau = 1.5 truncates every "
                       "eigenvalue: x is the mass point, rank 0). Handout §1.")) {
    // planes with weights: AtA = sum w n nT, Atb = sum w n (n.p), btb = sum w (n.p)^2 (the Qef's fields)
    struct Weighted {
        std::string name;
        std::vector<glm::dvec3> p, n;
        std::vector<double> w;
        void add(const glm::dvec3& point, const glm::dvec3& normal, double weight = 1.0) {
            p.push_back(point), n.push_back(glm::normalize(normal)), w.push_back(weight);
        }
    };
    std::vector<Weighted> shapes;
    {  // near-planar, curved points; the normal favours one axis (which one depends on the permutation)
        Weighted s{"a near-planar patch", {}, {}, {}};
        const glm::dvec3 n0 = glm::normalize(glm::dvec3(0.25, -0.3, 0.92));
        const glm::dvec3 a = glm::normalize(glm::cross(n0, glm::dvec3(1, 0, 0))), b = glm::cross(n0, a);
        for (int i = 0; i < 10; ++i) {
            const double phi = 2.0 * kPi * i / 10.0, u = 0.1 * (i % 4), v = 0.07 * (i % 3);
            s.add(glm::dvec3(0.4, 0.6, -0.2) + (u - 0.15) * a + (v - 0.07) * b + 0.05 * (u * u + v * v) * n0,
                  n0 + 0.012 * std::cos(phi) * a + 0.004 * std::sin(phi) * b);
        }
        shapes.push_back(s);
    }
    {  // near-planar, close to where a rank-1 shortcut must give up (eigenvalue ratios about 3e-3 and 5e-4), with
       // points on a cap of radius 6 so that the solution lies off the mass point
        Weighted s{"a curved patch near the rank-1 limit", {}, {}, {}};
        const glm::dvec3 n0 = glm::normalize(glm::dvec3(-0.4, 0.2, 0.9));
        const glm::dvec3 a = glm::normalize(glm::cross(n0, glm::dvec3(0, 1, 0))), b = glm::cross(n0, a);
        const glm::dvec3 centre = glm::dvec3(0.2, 0.1, -0.3) - 6.0 * n0;  // the cap's sphere
        for (int i = 0; i < 12; ++i) {
            const double phi = 2.0 * kPi * (i + 0.3) / 12.0, t = 0.25 + 0.05 * (i % 3);
            const glm::dvec3 d = glm::normalize(6.0 * n0 + t * 1.4 * (std::cos(phi) * a + 0.35 * std::sin(phi) * b));
            s.add(centre + 6.0 * d, d);
        }
        shapes.push_back(s);
    }
    {  // near-planar with every normal in the plane y = 0 (AtA's xy and yz entries exactly 0)
        Weighted s{"a near-planar patch with normals in a coordinate plane", {}, {}, {}};
        const glm::dvec3 n0 = glm::normalize(glm::dvec3(0.8, 0.0, 0.6)), a(-0.6, 0.0, 0.8);
        for (int i = 0; i < 8; ++i) {
            const double t = -0.35 + 0.1 * i;
            s.add(glm::dvec3(1.0, 0.2 * (i % 3), 0.5) + t * a + 0.06 * t * t * n0, n0 + 0.02 * t * a);
        }
        shapes.push_back(s);
    }
    {  // a sharp edge with every normal in the plane y = 0 (rank 2)
        Weighted s{"an edge with normals in a coordinate plane", {}, {}, {}};
        const glm::dvec3 n1 = glm::normalize(glm::dvec3(1, 0, 0.2)), n2 = glm::normalize(glm::dvec3(-0.5, 0, 0.866));
        for (int i = 0; i < 4; ++i) {
            s.add(glm::dvec3(0.3, 0.1 * i, 0.0) + 0.05 * i * glm::cross(n1, glm::dvec3(0, 1, 0)), n1);
            s.add(glm::dvec3(0.3, 0.1 * i + 0.05, 0.0) - 0.04 * i * glm::cross(n2, glm::dvec3(0, 1, 0)), n2);
        }
        shapes.push_back(s);
    }
    {  // an edge of two planes 80 degrees apart: eigenvalue ratio (1 - cos) / (1 + cos) = 0.70, kept at tau = 0.6
        Weighted s{"an edge of two planes 80 degrees apart", {}, {}, {}};
        const double t = 80.0 * kPi / 180.0;
        const glm::dvec3 n1 = glm::normalize(glm::dvec3(0.3, -0.2, 1.0)), u = glm::normalize(glm::cross(n1, glm::dvec3(1, 0, 0)));
        const glm::dvec3 n2 = std::cos(t) * n1 + std::sin(t) * u;
        for (int i = 0; i < 3; ++i) {
            s.add(glm::dvec3(0.1 * i, 0.2, -0.1) + 0.05 * i * u, n1);
            s.add(glm::dvec3(0.1 * i, 0.25, -0.1) - 0.04 * i * n1, n2);
        }
        shapes.push_back(s);
    }
    {  // a corner whose AtA has two equal diagonal entries and a nonzero entry between them
        Weighted s{"a corner with equal diagonal entries", {}, {}, {}};
        const glm::dvec3 c(0.2, -0.1, 0.3), n3(0.6, 0.6, std::sqrt(0.28));
        s.add(c + glm::dvec3(0, 0.1, 0.2), {1, 0, 0});
        s.add(c + glm::dvec3(0.1, 0, 0.2), {0, 1, 0});
        s.add(c + 0.1 * glm::normalize(glm::cross(n3, glm::dvec3(1, -1, 0))), n3);
        shapes.push_back(s);
    }
    {  // a corner whose AtA has two equal diagonal entries and an exact 0 between them
        Weighted s{"a corner with equal diagonal entries and a zero between them", {}, {}, {}};
        const glm::dvec3 c(-0.3, 0.2, 0.1);
        s.add(c + glm::dvec3(0, 0.1, 0.1), {1, 0, 0});
        s.add(c + glm::dvec3(0.1, 0, 0.1), {0, 1, 0});
        s.add(c + glm::dvec3(0.1, 0.8 * 0.1, -0.6 * 0.1), {0, 0.6, 0.8});
        s.add(c + glm::dvec3(0.8 * 0.1, 0.1, -0.6 * 0.1), {0.6, 0, 0.8});
        shapes.push_back(s);
    }
    {  // weighted axis planes, eigenvalues 1, 0.5 and 0.007 (kept only if lambda_max were 0.5), slightly rotated
        Weighted s{"weighted planes with eigenvalues 1, 0.5, 0.007", {}, {}, {}};
        const glm::dvec3 e0 = glm::normalize(glm::dvec3(1, 0.08, -0.05)), e1 = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), e0)),
                         e2 = glm::cross(e0, e1);
        s.add(glm::dvec3(0.1, 0.2, 0.3), e0, 1.0);
        s.add(glm::dvec3(-0.2, 0.1, 0.0), e1, 0.5);
        s.add(glm::dvec3(0.3, -0.1, 0.2), e2, 0.007);
        shapes.push_back(s);
    }
    {  // one plane
        Weighted s{"one plane", {}, {}, {}};
        s.add(glm::dvec3(0.7, -0.4, 0.25), glm::dvec3(0.3, -0.4, 0.5));
        shapes.push_back(s);
    }
    const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
    const auto permute = [](const glm::dvec3& v, const int* pm) { return glm::dvec3(v[pm[0]], v[pm[1]], v[pm[2]]); };
    int checked = 0, ranks[4] = {0, 0, 0, 0};
    for (const Weighted& s : shapes)
        for (const auto& pm : perms)
            for (double tau : {0.01, 0.3, 0.6, 1.0, 1.5}) {
                // the reference: Eigen on the same sums, the right-hand side about the mass point
                Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
                Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
                glm::dvec3 m(0.0);
                for (const glm::dvec3& p : s.p) m += permute(p, pm);
                m /= double(s.p.size());
                for (std::size_t i = 0; i < s.p.size(); ++i) {
                    const glm::dvec3 n = permute(s.n[i], pm), p = permute(s.p[i], pm);
                    const Eigen::Vector3d en(n.x, n.y, n.z);
                    ata += s.w[i] * en * en.transpose();
                    rhs += s.w[i] * en * glm::dot(n, p - m);
                }
                const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(ata);
                const double lmax = es.eigenvalues().cwiseAbs().maxCoeff();
                glm::dvec3 expected = m;
                int expected_rank = 0;
                for (int i = 0; i < 3; ++i) {
                    const double l = es.eigenvalues()(i);
                    // the test's data keep clear of the threshold, but for lambda_max itself at tau = 1 (kept: not below)
                    REQUIRE((std::abs(l / lmax - tau) > 1e-3 || l == lmax));
                    if (l < tau * lmax) continue;
                    const Eigen::Vector3d e = es.eigenvectors().col(i);
                    expected += (e.dot(rhs) / l) * glm::dvec3(e(0), e(1), e(2));
                    ++expected_rank;
                }
                for (double scale : {1e-100, 1e-9, 1.0, 1e12}) {
                    Qef q;
                    for (std::size_t i = 0; i < s.p.size(); ++i) {
                        const glm::dvec3 n = permute(s.n[i], pm), p = permute(s.p[i], pm);
                        const double w = scale * s.w[i], d = glm::dot(n, p);
                        const double nn[6] = {n.x * n.x, n.x * n.y, n.x * n.z, n.y * n.y, n.y * n.z, n.z * n.z};
                        for (int k = 0; k < 6; ++k) q.ata[k] += w * nn[k];
                        q.atb += w * d * n;
                        q.btb += w * d * d;
                        q.mass_sum += p;
                        q.count += 1;
                    }
                    int rank = -1;
                    const glm::dvec3 x = q.solve(tau, nullptr, &rank);
                    INFO(s.name << ", axes permuted to (" << "xyz"[pm[0]] << "xyz"[pm[1]] << "xyz"[pm[2]]
                                << "), all weights times " << scale << ", tau " << tau << ": solve gave " << str(x)
                                << " rank " << rank << "; Eigen's truncated pseudo-inverse gives " << str(expected)
                                << " rank " << expected_rank);
                    CHECK(rank == expected_rank);
                    CHECK(glm::length(x - expected) <= 1e-9);
                    ++checked;
                    ranks[expected_rank] += 1;
                }
            }
    CHECK(checked == 9 * 6 * 5 * 4);
    CHECK(ranks[0] >= 6 * 4 * 9);  // tau = 1.5 keeps nothing
    CHECK(ranks[1] >= 6 * 4 * 3 + 6 * 4 * 9);  // tau = 1 keeps lambda_max only
    CHECK(ranks[2] >= 6 * 4);
    CHECK(ranks[3] >= 6 * 4);
}

TEST_CASE("qef: error(x) equals the brute-force sum of squares; accumulated in double" * geolab::points(1) *
          geolab::hint("Q(x) = xT AtA x - 2 xT Atb + btb with every sum in double (float loses everything here: "
                       "the points are near 1e4 while Q is of order 1). Handout §2.1.")) {
    Lcg rng(3);
    Planes pl;
    const glm::dvec3 far(1.0e4, -2.0e4, 3.0e4);
    for (int i = 0; i < 20; ++i) pl.add(far + glm::dvec3(rng.uniform(), rng.uniform(), rng.uniform()), rng.unit_vector());
    const Qef q = pl.qef();
    CHECK(q.count == 20);
    CHECK(glm::length(q.mass_sum / 20.0 - pl.mass()) < 1e-9);
    double ata[6] = {0, 0, 0, 0, 0, 0}, btb = 0;
    glm::dvec3 atb(0.0);
    for (std::size_t i = 0; i < pl.p.size(); ++i) {
        const glm::dvec3& n = pl.n[i];
        double d = glm::dot(n, pl.p[i]);
        ata[0] += n.x * n.x, ata[1] += n.x * n.y, ata[2] += n.x * n.z, ata[3] += n.y * n.y, ata[4] += n.y * n.z,
            ata[5] += n.z * n.z;
        atb += d * n, btb += d * d;
    }
    for (int k = 0; k < 6; ++k) CHECK(std::abs(q.ata[k] - ata[k]) < 1e-12);
    CHECK(glm::length(q.atb - atb) < 1e-10 * glm::length(atb));
    CHECK(std::abs(q.btb - btb) < 1e-12 * btb);
    for (int i = 0; i < 10; ++i) {
        const glm::dvec3 x = far + glm::dvec3(rng.uniform(-1, 2), rng.uniform(-1, 2), rng.uniform(-1, 2));
        const double got = q.error(x), want = pl.error(x);
        INFO("x = " << str(x) << ": error(x) = " << got << ", brute force " << want);
        CHECK(std::abs(got - want) < 1e-5 * std::max(1.0, want));
    }
    // an empty Qef
    Qef empty;
    int rank = -1;
    const glm::dvec3 z = empty.solve(0.01, nullptr, &rank);
    CHECK(rank == 0);
    CHECK(glm::length(z) == 0.0);
    CHECK(empty.error(glm::dvec3(1, 2, 3)) == 0.0);
}

}  // TEST_SUITE
