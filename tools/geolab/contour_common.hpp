#pragma once
// What geolab contour and geolab table1 share: the input (a mesh file, a fetched model or a named implicit), one
// dual contouring run with its mesh checks, the two-sided Hausdorff distance, number formatting. Lab 09 builds only.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#ifdef GEOLAB_HAS_LAB_09
#include "geolab/dual_contouring.hpp"
#include "geolab/surface_checks.hpp"
#include "geolab/implicits.hpp"
#include "geolab/io.hpp"
#include "geolab/mesh_field.hpp"
#include "geolab/models.hpp"
#endif


#ifdef GEOLAB_HAS_LAB_09
namespace geolab::cli::contour_common {


using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

inline const std::vector<std::string> table_models{"bunny00", "cow", "lion", "head", "armadillo", "ChineseDragon-10kv"};

inline std::string join(const std::vector<std::string>& v, const std::string& sep = ", ") {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

inline std::string fmt(const char* f, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, x);
    return buf;
}

// 1234567 → "1,234,567"
inline std::string grouped(std::size_t n) {
    const std::string digits = std::to_string(n);
    std::string s;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
        s += digits[i];
    }
    return s;
}

inline std::string vec_str(const glm::dvec3& p) {
    return "(" + fmt("%.4g", p.x) + ", " + fmt("%.4g", p.y) + ", " + fmt("%.4g", p.z) + ")";
}

// ---- the input: a mesh file, a fetched model or a named implicit ---------------------------------------------------

struct Input {
    std::string arg;
    std::string kind;  // "mesh file", "model", "implicit"
    std::filesystem::path path;
    std::optional<PolygonSoup> mesh;
    std::shared_ptr<const ScalarField> field;
    std::shared_ptr<const MeshField> mesh_field;  // == field for meshes
    double read_seconds = 0.0, field_seconds = 0.0;
    double volume = 0.0;  // a mesh input's signed volume (dc::signed_volume)
    std::string warning;  // set when a mesh input cannot bound a solid (flat, open or zero volume)
};

inline std::string unknown_input_message(const std::string& arg) {
    return "'" + arg + "' is not a mesh file, a fetched model (e.g. " + join(table_models) +
           "; tools/fetch_models.sh) or a named implicit (" + join(implicit_names()) + ")";
}

// Reads/builds the input; progress lines go to `log` (stderr) when not null. Throws with a message naming arg.
inline Input load_input(const std::string& arg, std::ostream* log) {
    Input in;
    in.arg = arg;
    std::error_code ec;
    const auto names = implicit_names();
    // a named implicit wins over a fetched model of the same name (sphere, cube, cylinder, blob), as in the demo;
    // that model's file path still reaches it
    if (std::find(names.begin(), names.end(), arg) != names.end()) {
        in.kind = "implicit";
        auto t0 = Clock::now();
        in.field = named_implicit(arg);
        in.field_seconds = seconds_since(t0);
        return in;
    }
    if (std::filesystem::is_regular_file(arg, ec)) {
        in.kind = "mesh file";
        in.path = arg;
    } else if (auto p = model_path(arg)) {
        in.kind = "model";
        in.path = *p;
    } else {
        throw std::runtime_error(unknown_input_message(arg));
    }
    if (log) *log << "  reading " << in.path.string() << " ..." << std::endl;
    auto t0 = Clock::now();
    try {
        in.mesh = read_mesh(in.path);
    } catch (const IoError& e) {
        throw std::runtime_error("cannot read " + arg + ": " + e.what());
    }
    in.read_seconds = seconds_since(t0);
    {
        // a flat or zero-volume input has no inside: its winding-number field never crosses ½ cleanly, and dual
        // contouring returns at best a zero-volume double sheet around it; say so instead of reporting a surface
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (const auto& p : in.mesh->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double diagonal = in.mesh->positions.empty() ? 0.0 : glm::length(hi - lo);
        in.volume = dc::signed_volume(*in.mesh);
        if (!(std::abs(in.volume) > 1e-6 * diagonal * diagonal * diagonal))
            in.warning = arg + " encloses no volume (|V| = " + fmt("%.3g", std::abs(in.volume)) +
                         ", bounding-box diagonal " + fmt("%.3g", diagonal) +
                         "): a flat or open input has no inside, and the output is not a solid's surface";
        if (log && !in.warning.empty()) *log << "  warning: " << in.warning << std::endl;
    }
    if (log)
        *log << "  building the mesh field (BVH + fast winding numbers) of " << grouped(in.mesh->n_faces())
             << " faces ..." << std::endl;
    t0 = Clock::now();
    try {
        in.mesh_field = std::make_shared<MeshField>(*in.mesh);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error("cannot build a distance field of " + arg + ": " + e.what());
    }
    in.field = in.mesh_field;
    in.field_seconds = seconds_since(t0);
    return in;
}

// ---- one dual contouring run ---------------------------------------------------------------------------------------

struct Run {
    dc::Coordinates octree = dc::Coordinates::cartesian;
    int level = 0;
    PolygonSoup soup;
    dc::DcStats stats;
    dc::MeshCheck check;
    SurfaceCheck surface;  // lib's full count (exact self-intersections, non-manifold vertices, zero-area faces ...)
    glm::dvec3 origin_start{0.0};
    std::string origin_start_what;
    double cell = 0.0;       // Cartesian: the finest cell's side; spherical: the finest radial step
    double max_abs_f = 0.0;  // max |f(v)| over the output vertices
    double volume = 0.0;
    double contour_seconds = 0.0, check_seconds = 0.0;
};

inline const char* octree_name(dc::Coordinates c) { return c == dc::Coordinates::cartesian ? "cartesian" : "spherical"; }

inline const char* pole_fill_name(dc::PoleFill::Method m) {
    switch (m) {
        case dc::PoleFill::normal_projection: return "normal";
        case dc::PoleFill::vertical_projection: return "vertical";
        default: return "none";
    }
}

// The Cartesian runs use the lab's default CartesianParams (simplification on, tolerance 1e-5 of the finest cell).
inline const dc::CartesianParams default_cartesian{};

inline Run run_dc(const Input& in, dc::Coordinates octree, int level, dc::PoleFill::Method pole_fill) {
    Run r;
    r.octree = octree;
    r.level = level;
    const ScalarField& f = *in.field;
    const double n = double(1 << level);
    auto t0 = Clock::now();
    if (octree == dc::Coordinates::cartesian) {
        dc::CartesianParams p = default_cartesian;
        p.max_level = level;
        r.soup = dc::dual_contour_cartesian(f, p, &r.stats);
        r.contour_seconds = seconds_since(t0);
        r.cell = dc::cartesian_domain(f, p.padding).second / n;
    } else {
        dc::SphericalParams p;
        p.max_level = level;
        p.pole_fill = pole_fill;
        if (in.mesh) {
            // the origin's rule (lab 09 handout §5): a mesh starts at the centre of the smallest enclosing sphere
            // of its vertices (the paper); a field without vertices at the centre of bounds()
            r.origin_start = dc::minimal_enclosing_sphere(in.mesh->positions).center;
            r.origin_start_what = "centre of the smallest enclosing sphere of the vertices";
            p.origin = r.origin_start;
        } else {
            r.origin_start = f.bounds().center();
            r.origin_start_what = "centre of the field's bounds";
        }
        r.soup = dc::dual_contour_spherical(f, p, &r.stats);
        r.contour_seconds = seconds_since(t0);
        r.cell = (r.stats.r_max - r.stats.r_min) / n;
    }
    t0 = Clock::now();
    r.check = dc::check_mesh(r.soup);
    r.surface = check_surface(r.soup);
    r.max_abs_f = dc::max_abs_value(f, r.soup);
    r.volume = dc::signed_volume(r.soup);
    r.check_seconds = seconds_since(t0);
    return r;
}

// ---- sampled two-sided Hausdorff distance ---------------------------------------------------------------------------

// n points uniformly distributed by area on the soup's triangles (polygons as fans), deterministic (seed).
inline std::vector<glm::dvec3> sample_surface(const PolygonSoup& soup, std::size_t n, std::uint64_t seed) {
    struct Tri {
        std::uint32_t a, b, c;
    };
    std::vector<Tri> tris;
    std::vector<double> cumulative;
    double total = 0.0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
            const auto &a = soup.positions[vs[0]], &b = soup.positions[vs[i]], &c = soup.positions[vs[i + 1]];
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
            if (!(area > 0.0)) continue;
            tris.push_back({vs[0], vs[i], vs[i + 1]});
            total += area;
            cumulative.push_back(total);
        }
    }
    std::vector<glm::dvec3> pts;
    if (tris.empty()) return pts;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    pts.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = u(rng) * total;
        std::size_t i = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), t) - cumulative.begin());
        i = std::min(i, tris.size() - 1);
        const double s = std::sqrt(u(rng)), v = u(rng);
        const auto &a = soup.positions[tris[i].a], &b = soup.positions[tris[i].b], &c = soup.positions[tris[i].c];
        pts.push_back((1.0 - s) * a + s * (1.0 - v) * b + s * v * c);
    }
    return pts;
}

struct OneSided {
    double max = 0.0, mean = 0.0;
};

// Distances from the points to the mesh of `target` (BVH queries, split over the hardware threads).
inline OneSided one_sided(const std::vector<glm::dvec3>& pts, const MeshField& target) {
    OneSided r;
    if (pts.empty()) return r;
    const unsigned nt = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
    std::vector<double> mx(nt, 0.0), sum(nt, 0.0);
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < nt; ++t)
        threads.emplace_back([&, t] {
            for (std::size_t i = t; i < pts.size(); i += nt) {
                const double d = target.unsigned_distance(pts[i]);
                mx[t] = std::max(mx[t], d);
                sum[t] += d;
            }
        });
    for (auto& th : threads) th.join();
    for (unsigned t = 0; t < nt; ++t) {
        r.max = std::max(r.max, mx[t]);
        r.mean += sum[t];
    }
    r.mean /= double(pts.size());
    return r;
}

struct Hausdorff {
    double max = 0.0;   // two-sided: max of the two one-sided maxima (a lower bound of the true distance)
    double mean = 0.0;  // mean of the two one-sided means (over the area-uniform samples)
    OneSided to_input, to_output;
    std::size_t output_samples = 0;  // area-uniform samples on the output (besides its vertices)
    double seconds = 0.0;
    bool valid = false;
};

// The two-sided Hausdorff distance between the input mesh and the output, as the maximum over finite point sets:
// area-uniform samples on each mesh (input_samples: on the input, reused for both octrees; on the output at least
// n and at least two per output face, so finer levels get more) and every vertex of both meshes. The maximum over
// a finite set never exceeds the true supremum, so the result is a lower bound; the vertices make it include the
// points where dual contouring's error usually peaks. The means are over the samples only (area-weighted).
inline Hausdorff hausdorff(const std::vector<glm::dvec3>& input_samples, const PolygonSoup& input_mesh,
                           const MeshField& input, const PolygonSoup& output, std::size_t n, std::uint64_t seed) {
    Hausdorff h;
    auto t0 = Clock::now();
    h.output_samples = std::max(n, 2 * output.n_faces());
    const auto out_samples = sample_surface(output, h.output_samples, seed + 1);
    if (out_samples.empty()) return h;
    const MeshField out_field(output);
    h.to_input = one_sided(out_samples, input);
    h.to_output = one_sided(input_samples, out_field);
    h.to_input.max = std::max(h.to_input.max, one_sided(output.positions, input).max);
    h.to_output.max = std::max(h.to_output.max, one_sided(input_mesh.positions, out_field).max);
    h.max = std::max(h.to_input.max, h.to_output.max);
    h.mean = 0.5 * (h.to_input.mean + h.to_output.mean);
    h.seconds = seconds_since(t0);
    h.valid = true;
    return h;
}

// The axis-aligned bounding box diagonal of the positions.
inline double bbox_diagonal(const std::vector<glm::dvec3>& ps) {
    if (ps.empty()) return 0.0;
    glm::dvec3 lo = ps[0], hi = ps[0];
    for (const auto& p : ps) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::length(hi - lo);
}

}  // namespace geolab::cli::contour_common
#endif
