// Lab 01 demo: see a half-edge mesh. Pick a vertex (its one-ring), a face (its half-edges and neighbours) or a
// half-edge (twin / next / to_vertex / face, and walk with N, T, P, O); boundary loops in colour; step the
// Laplacian smoothing. Headless: --png FILE renders the same view; --figures DIR renders the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
// A function that throws geolab::NotImplemented is reported in the status line; what does not need it still shows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "geolab/errors.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/halfedge.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/render.hpp"

namespace {

using namespace geolab::halfedge;
using geolab::PolygonSoup;
namespace fx = geolab::fixtures;
namespace gr = geolab::render;
using glm::dvec3;
using glm::vec3;
using gr::attempt;
using gr::fmt;
using gr::Issues;
using gr::Segments;

// ---- colours (the handout's legend uses these names) ------------------------------------------------------------
const vec3 kGrey{0.82f, 0.82f, 0.84f};        // faces
const vec3 kWire{0.35f, 0.35f, 0.38f};        // polygon edges
const vec3 kH{0.05f, 0.05f, 0.05f};           // the selected half-edge h: black
const vec3 kTwin{0.85f, 0.10f, 0.10f};        // twin(h): red
const vec3 kNext{0.10f, 0.35f, 0.90f};        // next(h): blue
const vec3 kToVertex{0.05f, 0.60f, 0.15f};    // to_vertex(h): green
const vec3 kFaceOfH{1.00f, 0.85f, 0.35f};     // face(h): yellow
const vec3 kOtherHe{0.55f, 0.55f, 0.58f};     // other half-edges: grey
const vec3 kBoundaryHe{0.80f, 0.55f, 0.80f};  // other boundary half-edges: lilac
const vec3 kVertex{0.85f, 0.10f, 0.10f};      // the selected vertex: red
const vec3 kRing{0.05f, 0.60f, 0.15f};        // one-ring vertices: green
const vec3 kRingFace{1.00f, 0.78f, 0.50f};    // one-ring faces: light orange
const vec3 kFace{1.00f, 0.72f, 0.40f};        // the selected face: orange
const vec3 kNeighbour{0.62f, 0.78f, 1.00f};   // faces across the selected face's edges: light blue
const vec3 kNormal{0.55f, 0.15f, 0.75f};      // normals: purple

// Dark blue → light blue along the walk order of outgoing_halfedges (the first, halfedge(v), is darkest).
vec3 walk_color(std::size_t i, std::size_t n) {
    const float s = n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 0.0f;
    return glm::mix(vec3(0.00f, 0.08f, 0.45f), vec3(0.20f, 0.60f, 1.00f), s);
}

// ---- calling the student's code (gr::attempt records what is missing or throws) -------------------------------

// A handle returned by the student's code, checked before it indexes anything.
bool ok(const Mesh& m, Vertex v) { return v.idx < m.n_vertices(); }
bool ok(const Mesh& m, Face f) { return f.idx < m.n_faces(); }
bool ok(const Mesh& m, Halfedge h) { return h.idx < m.n_halfedges(); }

// ---- input ---------------------------------------------------------------------------------------------------------

const char* kFixtureNames =
    "tetrahedron, cube, cube_tri, octahedron, icosphere, icosphere0..icosphere6, torus, grid, grid_holes, "
    "two_components, hexagon, bowtie, fan, mobius";

// A hexagon fan: 6 triangles around vertex 0, in z = 0 (one boundary loop). The half-edge diagram's mesh.
PolygonSoup hexagon() {
    PolygonSoup s;
    s.positions.push_back({0, 0, 0});
    for (int k = 0; k < 6; ++k) {
        const double a = 2 * 3.14159265358979323846 * k / 6;
        s.positions.push_back({std::cos(a), std::sin(a), 0});
    }
    for (std::uint32_t k = 0; k < 6; ++k) s.add_face({0, 1 + k, 1 + (k + 1) % 6});
    return s;
}

// An 8 × 8 grid with three holes (faces removed): four boundary loops, χ = −2.
PolygonSoup grid_with_holes() {
    const PolygonSoup g = fx::grid(8, 8);
    PolygonSoup s;
    s.positions = g.positions;
    auto removed = [](std::size_t f) {
        const std::size_t cell = f / 2, i = cell % 8, j = cell / 8;
        return (i >= 1 && i <= 2 && j >= 1 && j <= 2 && !(i == 2 && j == 2)) || (i == 5 && j >= 1 && j <= 3) ||
               (i >= 3 && i <= 5 && j == 6 && !(i == 5 && f % 2 == 0));
    };
    for (std::size_t f = 0; f < g.n_faces(); ++f)
        if (!removed(f)) s.add_face(g.face(f));
    return s;
}

PolygonSoup octahedron() {
    PolygonSoup s;
    s.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::uint32_t f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (const auto& t : f) s.add_face({t[0], t[1], t[2]});
    return s;
}

std::optional<PolygonSoup> fixture(const std::string& name) {
    if (name == "tetrahedron") return fx::tetrahedron();
    if (name == "cube") return fx::cube();
    if (name == "cube_tri") return fx::cube(true);
    if (name == "octahedron") return octahedron();
    if (name == "icosphere") return fx::icosphere(3);
    if (name.rfind("icosphere", 0) == 0 && name.size() == 10 && name[9] >= '0' && name[9] <= '6')
        return fx::icosphere(name[9] - '0');
    if (name == "torus") return fx::torus();
    if (name == "grid") return fx::grid(8, 8);
    if (name == "grid_holes") return grid_with_holes();
    if (name == "two_components") return fx::two_components();
    if (name == "hexagon") return hexagon();
    if (name == "bowtie") return fx::bowtie();
    if (name == "fan") return fx::fan();
    if (name == "mobius") return fx::mobius(16);
    return std::nullopt;
}

// A fixture name, a file, or a fetched model name. Throws std::runtime_error with one clear sentence.
PolygonSoup load(const std::string& arg) {
    if (auto s = fixture(arg)) return *s;
    if (std::filesystem::exists(arg)) return geolab::read_mesh(arg);
    if (auto p = geolab::model_path(arg)) return geolab::read_mesh(*p);
    throw std::runtime_error("'" + arg + "' is not a fixture (" + kFixtureNames +
                             "), a mesh file, or a fetched model (run tools/fetch_models.sh for bunny00, cow, ...)");
}

// ---- the demo's state ------------------------------------------------------------------------------------------------

enum class Mode { vertex, face, halfedge };

// What build_mesh's TopologyError names, parsed from its message, to draw on the soup.
struct Rejection {
    std::string message;
    std::vector<std::uint32_t> vertices;                          // a complex vertex
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // a complex edge / the doubly used directed edge
    std::vector<std::uint32_t> faces;                             // the faces named
};

Rejection parse_rejection(const std::string& message) {
    Rejection r{message, {}, {}, {}};
    std::smatch m;
    auto num = [&](int i) { return static_cast<std::uint32_t>(std::stoul(m[i].str())); };
    if (std::regex_search(message, m, std::regex(R"(complex edge between vertex (\d+) and vertex (\d+): used by face (\d+), face (\d+), face (\d+))"))) {
        r.edges.push_back({num(1), num(2)});
        r.faces = {num(3), num(4), num(5)};
    } else if (std::regex_search(message, m, std::regex(R"(face (\d+) and face (\d+) both use the directed edge from vertex (\d+) to vertex (\d+))"))) {
        r.faces = {num(1), num(2)};
        r.edges.push_back({num(3), num(4)});
    } else if (std::regex_search(message, m, std::regex(R"(complex vertex (\d+).*face (\d+) and face (\d+))"))) {
        r.vertices.push_back(num(1));
        r.faces = {num(2), num(3)};
    }
    return r;
}

struct Demo {
    std::string name;
    PolygonSoup soup;                      // faces (and the original positions)
    std::optional<Mesh> mesh;              // when build_mesh worked and validate() passed
    std::string build_problem;             // why there is no mesh
    std::optional<Rejection> rejection;    // build_mesh's TopologyError, parsed
    std::string topology;                  // "V .. E .. F .. χ .. loops .. genus .. components"
    std::vector<std::vector<Halfedge>> loops;
    Issues topology_issues;
    Issues action_issues;  // from the last smoothing step

    Mode mode = Mode::vertex;
    std::optional<std::uint32_t> vertex, face, halfedge;
    int iterations = 0;
    double t = 0.5;
    double noise = 0.0;
    bool show_boundary = true;
    std::optional<bool> wireframe;  // unset: automatic
    float opacity = 1.0f;
    std::string message;            // the last action's result (smoothing, key)

    explicit Demo(std::string n, PolygonSoup s) : name(std::move(n)), soup(std::move(s)) { build(); }

    const std::vector<dvec3>& positions() const { return mesh ? mesh->positions() : soup.positions; }

    // The soup with the current positions (for drawing and picking).
    PolygonSoup current() const {
        PolygonSoup s = soup;
        s.positions = positions();
        return s;
    }

    double mean_edge_length() const {
        const auto& p = positions();
        double sum = 0.0;
        std::size_t n = 0;
        for (std::size_t f = 0; f < soup.n_faces() && n < 20000; ++f) {
            const auto c = soup.face(f);
            for (std::size_t i = 0; i < c.size(); ++i, ++n) sum += glm::length(p[c[i]] - p[c[(i + 1) % c.size()]]);
        }
        return n ? sum / static_cast<double>(n) : 1.0;
    }

    void build() {
        mesh.reset();
        rejection.reset();
        build_problem.clear();
        try {
            Mesh m = build_mesh(soup);
            try {
                validate(m);
                mesh = std::move(m);
            } catch (const std::exception& e) {
                build_problem = std::string("build_mesh returned a broken mesh: ") + e.what();
            }
        } catch (const geolab::NotImplemented&) {
            build_problem = "not implemented yet: build_mesh (showing the polygon soup only)";
        } catch (const geolab::TopologyError& e) {
            build_problem = std::string("rejected: ") + e.what();
            rejection = parse_rejection(e.what());
        } catch (const std::bad_alloc&) {
            build_problem = gr::memory_limit_message("build_mesh");
        } catch (const std::exception& e) {
            build_problem = std::string("build_mesh threw: ") + e.what();
        }
        if (noise > 0.0) jitter(noise);
        summarize();
    }

    // V, E, F, χ, loops, genus, components from the student's Task 3 functions (what works of it).
    void summarize() {
        topology_issues = {};
        loops.clear();
        if (!mesh) {
            topology = "soup: " + std::to_string(soup.n_vertices()) + " vertices, " + std::to_string(soup.n_faces()) +
                       " faces";
            return;
        }
        const Mesh& m = *mesh;
        std::ostringstream os;
        os << "V " << m.n_vertices() << "  E " << m.n_edges() << "  F " << m.n_faces();
        attempt(topology_issues, "euler_characteristic", [&] {
            const int chi = euler_characteristic(m);
            os << "  χ " << chi;
        });
        attempt(topology_issues, "boundary_loops", [&] {
            auto l = boundary_loops(m);
            loops = std::move(l);
            os << "  loops " << loops.size();
        });
        attempt(topology_issues, "genus", [&] {
            const int g = genus(m);
            os << "  genus " << g;
        });
        attempt(topology_issues, "connected_components", [&] {
            const int count = connected_components(m).count;
            os << "  components " << count;
        });
        topology = os.str();
    }

    // Moves every vertex by a random offset of up to `amount` × the mean edge length (same seed every time).
    void jitter(double amount) {
        auto& p = mesh ? mesh->positions() : soup.positions;
        const double scale = amount * mean_edge_length();
        std::mt19937 rng(1234);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (auto& x : p) x += scale * dvec3(u(rng), u(rng), u(rng));
    }

    void smooth(int k) {
        if (!mesh) {
            message = "smoothing needs the half-edge mesh (build_mesh)";
            return;
        }
        action_issues = {};
        if (attempt(action_issues, "laplacian_smoothing", [&] { laplacian_smoothing(*mesh, t, k); }))
            iterations += k;
        message = action_issues.any() ? "" : "smoothed: " + std::to_string(iterations) + " iterations, t = " + fmt(t);
    }

    void reset() {
        action_issues = {};
        build();
        iterations = 0;
        message = "reset to the input positions";
    }

    // Picking: the nearest face under the ray; its nearest vertex / half-edge.
    void pick(const gr::Ray& ray) {
        const auto hit = gr::pick(current(), ray);
        if (!hit) {
            vertex.reset(), face.reset(), halfedge.reset();
            message = "nothing under the cursor";
            return;
        }
        const auto f = static_cast<std::uint32_t>(hit->face);
        if (mode == Mode::vertex) vertex = static_cast<std::uint32_t>(hit->vertex);
        if (mode == Mode::face) face = f;
        if (mode == Mode::halfedge) {
            if (!mesh) {
                message = "half-edges need a mesh: " + build_problem;
                return;
            }
            // the half-edge of face f whose segment is nearest to the hit point
            const dvec3 q(hit->point);
            double best = 1e300;
            const Halfedge h0 = mesh->halfedge(Face{f});
            Halfedge h = h0;
            do {
                const dvec3 a = mesh->position(mesh->from_vertex(h)), b = mesh->position(mesh->to_vertex(h));
                const double s = std::clamp(glm::dot(q - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-300), 0.0, 1.0);
                if (const double d = glm::length(a + s * (b - a) - q); d < best) best = d, halfedge = h.idx;
                h = mesh->next(h);
            } while (h != h0);
        }
        message.clear();
    }
};

// ---- drawing -----------------------------------------------------------------------------------------------------

// The centroid of the loop of half-edges through h (a face or a hole), walking next with the given Mesh.
dvec3 loop_centroid(const Mesh& m, Halfedge h0) {
    dvec3 c(0.0);
    int n = 0;
    Halfedge h = h0;
    do {
        c += m.position(m.to_vertex(h));
        h = m.next(h);
        ++n;
    } while (h != h0 && n < 100000);
    return c / static_cast<double>(n);
}

// Half-edge h drawn as an arrow inside its face, offset towards the face's centroid (a boundary half-edge: offset
// away from its twin's face, i.e. into the hole).
void add_halfedge_arrow(Segments& seg, const Mesh& m, Halfedge h, vec3 color, double offset = 0.16) {
    const dvec3 a = m.position(m.from_vertex(h)), b = m.position(m.to_vertex(h));
    const bool boundary = m.is_boundary(h);
    const dvec3 c = boundary ? loop_centroid(m, m.twin(h)) : loop_centroid(m, h);
    const double sign = boundary ? -1.0 : 1.0;
    // move the segment towards (or away from) the centroid by `offset` × its distance to the edge
    const dvec3 inward = gr::side_towards(a, b, c);
    const double dist = glm::dot(c - a, inward);
    const dvec3 shift = sign * offset * dist * inward;
    gr::add_arrow(seg, a + shift, b + shift, sign * inward, color, {.shrink = 0.14, .head = 0.2, .one_sided = true});
}

// The direction to look at the face left of h from (for the camera only, not a face normal of Task 4): the unit
// normal of the triangle from_vertex(h), to_vertex(h), to_vertex(next(h)), or of the next corner triple when that
// one is degenerate; nullopt when every triple is.
std::optional<dvec3> view_normal(const Mesh& m, Halfedge h) {
    Halfedge x = h;
    for (int k = 0; k < 64; ++k, x = m.next(x)) {
        const dvec3 a = m.position(m.from_vertex(x)), b = m.position(m.to_vertex(x));
        const dvec3 c = m.position(m.to_vertex(m.next(x)));
        const dvec3 n = glm::cross(b - a, c - b);
        if (glm::length(n) > 1e-12 * glm::dot(b - a, b - a) + 1e-300) return glm::normalize(n);
        if (m.next(x) == h) break;
    }
    return std::nullopt;
}

struct View {
    gr::Scene scene;
    std::string status;
    std::optional<dvec3> focus;  // the selection's centre, for zooming
    double focus_radius = 0.0;
    std::optional<dvec3> focus_normal;
};

View draw(const Demo& d) {
    View out;
    Issues issues = d.topology_issues;
    issues.add(d.action_issues);
    const PolygonSoup soup = d.current();
    const auto& P = soup.positions;
    std::vector<vec3> face_color(soup.n_faces(), kGrey);
    Segments seg, thin, bad;
    std::vector<vec3> pts, pts_col, big, big_col;
    std::ostringstream st;

    const bool wire = d.wireframe.value_or(soup.n_faces() <= 6000);
    const double el = d.mean_edge_length();

    if (d.rejection) {  // what build_mesh named: faces in colour, the edge / vertex in red
        const Rejection& r = *d.rejection;
        const vec3 named[] = {{1.00f, 0.72f, 0.40f}, {0.55f, 0.75f, 1.00f}, {0.60f, 0.90f, 0.55f}};
        for (std::size_t i = 0; i < r.faces.size(); ++i)
            if (r.faces[i] < soup.n_faces()) face_color[r.faces[i]] = named[i % 3];
        for (auto [u, v] : r.edges)
            if (u < P.size() && v < P.size()) {
                // the doubly used directed edge u → v gets an arrow head; a complex edge does not
                const dvec3 side = glm::normalize(glm::cross(P[v] - P[u], dvec3(0.3, 0.5, 0.8)));
                gr::add_arrow(bad, P[u], P[v], side, kTwin, {.shrink = 0.0, .head = r.faces.size() == 2 ? 0.25 : 0.0});
            }
        for (auto v : r.vertices)
            if (v < P.size()) big.push_back(vec3(P[v])), big_col.push_back(kVertex);
    }

    if (d.mesh) {
        const Mesh& m = *d.mesh;
        // boundary loops: one colour each
        if (d.show_boundary && d.mode != Mode::halfedge)  // (in half-edge mode red / blue / green mean twin / next / to)
            for (std::size_t i = 0; i < d.loops.size(); ++i)
                for (Halfedge h : d.loops[i])
                    if (ok(m, h)) thin.add(m.position(m.from_vertex(h)), m.position(m.to_vertex(h)), gr::category_color(i));

        if (d.mode == Mode::vertex && d.vertex && *d.vertex < m.n_vertices()) {
            const Vertex v{*d.vertex};
            st << "v" << v.idx;
            std::vector<Halfedge> out_he;
            std::vector<Vertex> ring;
            std::vector<Face> faces;
            attempt(issues, "one_ring_faces", [&] {
                one_ring_faces(m, v, faces);
                for (Face f : faces)
                    if (ok(m, f)) face_color[f.idx] = kRingFace;
            });
            attempt(issues, "valence", [&] {
                const int val = valence(m, v);
                st << ": valence " << val;
            });
            attempt(issues, "outgoing_halfedges", [&] {
                outgoing_halfedges(m, v, out_he);
                for (std::size_t i = 0; i < out_he.size(); ++i) {
                    const Halfedge h = out_he[i];
                    if (!ok(m, h)) continue;
                    const dvec3 a = m.position(m.from_vertex(h)), b = m.position(m.to_vertex(h));
                    // barbs in the plane of the face on the left of h (or of its twin's face on the boundary)
                    const Halfedge in_face = m.is_boundary(h) ? m.twin(h) : h;
                    const dvec3 c = m.position(m.to_vertex(m.next(in_face)));
                    gr::add_arrow(seg, a, b, gr::side_towards(a, b, c), walk_color(i, out_he.size()), {.shrink = 0.06, .head = 0.2});
                }
                st << ", " << out_he.size() << " outgoing";
            });
            attempt(issues, "one_ring_vertices", [&] {
                one_ring_vertices(m, v, ring);
                for (Vertex w : ring)
                    if (ok(m, w)) pts.push_back(vec3(m.position(w))), pts_col.push_back(kRing);
            });
            st << (m.is_boundary(v) ? " (boundary)" : "");
            attempt(issues, "vertex_normal", [&] {
                const dvec3 n = vertex_normal(m, v);
                out.focus_normal = n;
                gr::add_normal(thin, m.position(v), n, 1.5 * el, kNormal);
                st << ", normal " << fmt(n);
            });
            big.push_back(vec3(m.position(v))), big_col.push_back(kVertex);
            out.focus = m.position(v);
        }

        if (d.mode == Mode::face && d.face && *d.face < m.n_faces()) {
            const Face f{*d.face};
            face_color[f.idx] = kFace;
            st << "f" << f.idx;
            std::vector<Halfedge> hs;
            if (attempt(issues, "face_halfedges", [&] { face_halfedges(m, f, hs); })) {
                st << ": " << hs.size() << " half-edges";
                for (std::size_t i = 0; i < hs.size(); ++i)
                    if (ok(m, hs[i])) add_halfedge_arrow(seg, m, hs[i], walk_color(i, hs.size()), 0.2);
                attempt(issues, "edge_faces", [&] {
                    for (Halfedge h : hs) {
                        if (!ok(m, h)) continue;
                        const auto [f0, f1] = edge_faces(m, m.edge(h));
                        for (Face g : {f0, f1})
                            if (ok(m, g) && g != f) face_color[g.idx] = kNeighbour;
                    }
                });
            }
            const dvec3 c = loop_centroid(m, m.halfedge(f));
            attempt(issues, "face_area", [&] {
                const double area = face_area(m, f);
                st << ", area " << fmt(area);
            });
            attempt(issues, "face_normal", [&] {
                const dvec3 n = face_normal(m, f);
                out.focus_normal = n;
                gr::add_normal(thin, c, n, 1.5 * el, kNormal);
                st << ", normal " << fmt(n);
            });
            out.focus = c;
        }

        if (d.mode == Mode::halfedge && d.halfedge && *d.halfedge < m.n_halfedges()) {
            // uses only the given Mesh class: works before any task is done
            const Halfedge h{*d.halfedge}, t = m.twin(h), n = m.next(h);
            if (!m.is_boundary(h)) face_color[m.face(h).idx] = kFaceOfH;
            for (Halfedge g : {h, t}) {  // the other half-edges of the two loops, grey
                Halfedge x = m.next(g);
                while (x != g) {
                    if (x != n && x != t && x != h)
                        add_halfedge_arrow(seg, m, x, m.is_boundary(x) ? kBoundaryHe : kOtherHe);
                    x = m.next(x);
                }
            }
            add_halfedge_arrow(seg, m, t, kTwin);
            add_halfedge_arrow(seg, m, n, kNext);
            add_halfedge_arrow(seg, m, h, kH);
            big.push_back(vec3(m.position(m.to_vertex(h)))), big_col.push_back(kToVertex);
            st << "h" << h.idx << ": " << m.from_vertex(h) << " → " << m.to_vertex(h) << ", twin h" << t.idx
               << ", next h" << n.idx << ", face " << m.face(h) << ", edge " << m.edge(h);
            out.focus = 0.5 * (m.position(m.from_vertex(h)) + m.position(m.to_vertex(h)));
            // zoom onto the face of h (of its twin on the boundary), seen face-on, so both arrows show
            out.focus_normal = view_normal(m, m.is_boundary(h) ? t : h);
        }
    } else if (d.mode == Mode::vertex && d.vertex && *d.vertex < P.size()) {
        big.push_back(vec3(P[*d.vertex])), big_col.push_back(kVertex);
        out.focus = P[*d.vertex];
        st << "v" << *d.vertex;
    } else if (d.mode == Mode::face && d.face && *d.face < soup.n_faces()) {
        face_color[*d.face] = kFace;
        dvec3 c(0.0);
        for (auto i : soup.face(*d.face)) c += P[i];
        out.focus = c / static_cast<double>(soup.face(*d.face).size());
        st << "f" << *d.face;
    }

    // how far to look around the selection: the faces that touch one of its vertices
    if (out.focus) {
        std::set<std::uint32_t> sel;
        if (d.mode == Mode::vertex && d.vertex) sel.insert(*d.vertex);
        if (d.mode == Mode::face && d.face && *d.face < soup.n_faces())
            for (auto i : soup.face(*d.face)) sel.insert(i);
        if (d.mode == Mode::halfedge && d.halfedge && d.mesh && *d.halfedge < d.mesh->n_halfedges()) {
            sel.insert(d.mesh->to_vertex(Halfedge{*d.halfedge}).idx);
            sel.insert(d.mesh->from_vertex(Halfedge{*d.halfedge}).idx);
        }
        double r = 0.0;
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            const auto c = soup.face(f);
            if (std::any_of(c.begin(), c.end(), [&](std::uint32_t i) { return sel.count(i) > 0; }))
                for (auto i : c) r = std::max(r, glm::length(P[i] - *out.focus));
        }
        out.focus_radius = r > 0 ? r : el;
    }

    gr::MeshStyle style{
        .color = kGrey, .smooth = false, .wireframe = wire, .wire_color = kWire, .wire_width = 1.0f, .opacity = d.opacity};
    out.scene.add_mesh_face_colors(soup, face_color, style);
    thin.draw(out.scene, 4.0f);
    seg.draw(out.scene, 3.0f);
    bad.draw(out.scene, 7.0f);
    if (!pts.empty()) out.scene.add_points(pts, pts_col, 10.0f);
    if (!big.empty()) out.scene.add_points(big, big_col, 16.0f);

    // the status line: mode | selection | topology | smoothing | problems
    std::string s = d.name + " | " + d.topology;
    const std::string sel = st.str();
    s += " | " + std::string(d.mode == Mode::vertex ? "vertex" : d.mode == Mode::face ? "face" : "half-edge") +
         " mode" + (sel.empty() ? "" : ": " + sel);
    if (d.iterations) s += " | smoothed " + std::to_string(d.iterations) + "× (t = " + fmt(d.t) + ")";
    if (!d.build_problem.empty()) s += " | " + d.build_problem;
    if (issues.any()) s += " | " + issues.str();
    if (!d.message.empty()) s += " | " + d.message;
    out.status = s;
    return out;
}

// ---- cameras -------------------------------------------------------------------------------------------------------

// The whole scene, or (zoom > 0 and a selection) the selection seen along its normal, `zoom` × its radius wide.
gr::Camera camera_for(const View& v, const Demo& d, double zoom, double aspect = 4.0 / 3.0, float tilt_deg = 0.0f) {
    if (!v.focus || zoom <= 0.0) return gr::whole(v.scene, aspect);
    dvec3 dir = v.focus_normal && glm::length(*v.focus_normal) > 0.5 ? *v.focus_normal : dvec3(0);
    if (glm::length(dir) == 0.0) {  // no normal (not implemented yet): look from the mesh's centre outwards
        dvec3 c(0.0);
        for (const auto& p : d.positions()) c += p;
        c /= static_cast<double>(std::max<std::size_t>(d.positions().size(), 1));
        dir = glm::length(*v.focus - c) > 0 ? *v.focus - c : dvec3(0, 0, 1);
    }
    gr::Camera cam;
    gr::orbit_angles(dir, dvec3(0, 1, 0), cam.yaw_deg, cam.pitch_deg);
    cam.yaw_deg += tilt_deg;  // a little off the normal, so that the normal shows
    return gr::close_up(cam, *v.focus, zoom * v.focus_radius);
}

// ---- figures -------------------------------------------------------------------------------------------------------

// Scale and move a soup so that its bounding box is centred at `at` with largest side `size`.
PolygonSoup normalized(PolygonSoup s, dvec3 at, double size) {
    dvec3 lo(1e300), hi(-1e300);
    for (const auto& p : s.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const dvec3 ext = hi - lo;
    const double k = size / std::max({ext.x, ext.y, ext.z, 1e-300});
    for (auto& p : s.positions) p = at + k * (p - 0.5 * (lo + hi));
    return s;
}

// A point on the surface: the middle of the bounding box's face at +z (where the models look at the viewer).
dvec3 front_point(const std::vector<dvec3>& p, double height = 0.5) {
    dvec3 lo(1e300), hi(-1e300);
    for (const auto& x : p) lo = glm::min(lo, x), hi = glm::max(hi, x);
    return {0.5 * (lo.x + hi.x), lo.y + height * (hi.y - lo.y), hi.z};
}

int render_figures(gr::FigureWriter w) {
    const double aspect = w.aspect();

    // (a) the half-edge diagram: a hexagon fan, seen from above, with h, twin(h), next(h), to_vertex(h), face(h)
    {
        Demo d("hexagon", hexagon());
        if (!d.mesh) {
            w.skip("halfedge_diagram.png", d.build_problem);
        } else {
            const Mesh& m = *d.mesh;
            // h: the spoke from vertex 1 to the centre (vertex 0), in face 5 = (0, 6, 1); twin(h) is in face 0
            Halfedge h;
            for (Halfedge x : m.halfedges())
                if (m.from_vertex(x) == Vertex{1} && m.to_vertex(x) == Vertex{0} && !m.is_boundary(x)) h = x;
            gr::Scene scene;
            std::vector<vec3> face_color(d.soup.n_faces(), kGrey);
            if (h.is_valid() && !m.is_boundary(h)) face_color[m.face(h).idx] = kFaceOfH;
            scene.add_mesh_face_colors(d.soup, face_color,
                                       {.color = kGrey, .smooth = false, .wireframe = true, .wire_color = kWire,
                                        .wire_width = 2.0f});
            Segments seg;
            for (Halfedge x : m.halfedges())
                if (x != h && x != m.twin(h) && x != m.next(h))
                    add_halfedge_arrow(seg, m, x, m.is_boundary(x) ? kBoundaryHe : kOtherHe, 0.18);
            seg.draw(scene, 2.5f);
            seg = {};
            if (h.is_valid()) {
                add_halfedge_arrow(seg, m, m.twin(h), kTwin, 0.18);
                add_halfedge_arrow(seg, m, m.next(h), kNext, 0.18);
                add_halfedge_arrow(seg, m, h, kH, 0.18);
                seg.draw(scene, 5.0f);
            }
            std::vector<vec3> corners;
            for (const auto& p : d.soup.positions) corners.push_back(vec3(p));
            scene.add_points(corners, kWire, 11.0f);
            if (h.is_valid()) scene.add_points({vec3(m.position(m.to_vertex(h)))}, kToVertex, 22.0f);
            w.write("halfedge_diagram.png", scene, gr::whole(scene, aspect, 0.0f, 0.0f),
                    "hexagon fan: h black, twin(h) red, next(h) blue, to_vertex(h) green, face(h) yellow");
        }
    }

    // (b) a one-ring on a real mesh, zoomed in on a vertex of valence 7 on the model's front
    {
        const auto model = gr::first_model({"bunny00", "cow"});
        Demo d(model.value_or("icosphere"), model ? load(*model) : fx::icosphere(3));
        d.mode = Mode::vertex;
        d.vertex = 0;
        d.wireframe = true;
        if (d.mesh) {
            const dvec3 target = front_point(d.positions(), 0.45);
            double best = 1e300;
            for (Vertex v : d.mesh->vertices()) {
                if (d.mesh->is_boundary(v)) continue;
                int val = 0;  // (counted with the given Mesh: the figure must not depend on valence())
                Halfedge x = d.mesh->halfedge(v);
                do ++val, x = d.mesh->next(d.mesh->twin(x)); while (x != d.mesh->halfedge(v) && val < 64);
                if (val != 7) continue;
                if (const double dist = glm::length(d.positions()[v.idx] - target); dist < best) best = dist, d.vertex = v.idx;
            }
        }
        View v = draw(d);
        w.write("onering.png", v.scene, camera_for(v, d, 1.5, aspect), v.status);
    }

    // (b') a face, its half-edges and its neighbours across its edges
    {
        const auto model = gr::first_model({"cow", "bunny00"});
        Demo d(model.value_or("icosphere"), model ? load(*model) : fx::icosphere(3));
        d.mode = Mode::face;
        d.face = 0;
        d.wireframe = true;
        if (d.mesh) {  // a well-shaped triangle near the front
            const auto& P = d.positions();
            const dvec3 target = front_point(P, 0.6);
            double best = 1e300;
            for (std::size_t f = 0; f < d.soup.n_faces(); ++f) {
                const auto c = d.soup.face(f);
                if (c.size() != 3) continue;
                const dvec3 a = P[c[0]], b = P[c[1]], e = P[c[2]];
                const double l2 = glm::dot(b - a, b - a) + glm::dot(e - b, e - b) + glm::dot(a - e, a - e);
                const double quality = 2 * std::sqrt(3.0) * glm::length(glm::cross(b - a, e - a)) / l2;  // 1: equilateral
                if (quality < 0.8) continue;
                if (const double dist = glm::length((a + b + e) / 3.0 - target); dist < best) best = dist, d.face = static_cast<std::uint32_t>(f);
            }
        }
        View v = draw(d);
        w.write("face.png", v.scene, camera_for(v, d, 0.55, aspect, 30.0f), v.status);
    }

    // (c) boundary loops, one colour per loop: a scanned mask with holes, and a grid with holes cut out
    {
        const auto model = gr::first_model({"holes", "head", "lion"});
        if (model) {
            Demo d(*model, load(*model));
            d.mode = Mode::vertex;
            d.wireframe = false;
            View v = draw(d);
            w.write("boundary_loops.png", v.scene, gr::whole(v.scene, aspect, 15.0f, 50.0f), v.status);
        } else {
            w.skip("boundary_loops.png", "no model with holes fetched (tools/fetch_models.sh)");
        }
        Demo g("grid_holes", grid_with_holes());
        View vg = draw(g);
        w.write("boundary_loops_grid.png", vg.scene, gr::whole(vg.scene, aspect, 0.0f, 0.0f), vg.status);
    }

    // (d) smoothing: 0, 10, 50 iterations side by side (t = 0.5), on a jittered mesh; one camera for all three
    {
        const auto model = gr::first_model({"bunny00"});
        const int its[] = {0, 10, 50};
        const int pw = 500, ph = 450;
        std::vector<gr::Image> panels;
        std::optional<gr::Camera> cam;
        std::string status;
        bool smoothed = true;
        for (int i = 0; i < 3; ++i) {
            Demo d(model.value_or("icosphere"), model ? load(*model) : fx::icosphere(4));
            d.noise = 0.35;
            d.build();
            if (its[i]) d.smooth(its[i]);
            smoothed = smoothed && d.iterations == its[i];
            status += (i ? "; " : "") + std::to_string(its[i]) + ": " +
                      (d.action_issues.any() ? d.action_issues.str() : d.message.empty() ? "jittered input" : d.message);
            gr::Scene scene;
            scene.add_mesh(d.current(), {.color = kGrey, .smooth = false});
            if (!cam) cam = gr::whole(scene, static_cast<double>(pw) / ph, 0.0f, 10.0f);  // the input's framing
            panels.push_back(gr::render_image(scene, *cam, pw, ph));
        }
        if (smoothed) {
            w.write("smoothing.png", gr::hstack(panels), status);
        } else {
            w.skip("smoothing.png", status);
        }
    }

    // (e) what build_mesh must reject: bowtie (complex vertex), fan (complex edge), Möbius strip (orientation)
    {
        struct Case {
            const char* name;
            float yaw, pitch;
        };
        for (const Case c : {Case{"bowtie", 0.0f, 0.0f}, Case{"fan", 0.0f, 45.0f}, Case{"mobius", 35.0f, 35.0f}}) {
            PolygonSoup s = *fixture(c.name);
            if (std::string(c.name) != "bowtie")  // the fan's shared edge (along z) upright; the strip lying flat
                for (auto& p : s.positions) p = dvec3(p.x, p.z, -p.y);
            Demo d(c.name, normalized(s, dvec3(0.0), 2.0));
            d.wireframe = true;
            if (std::string(c.name) == "fan") d.opacity = 0.8f;  // the fins hide each other
            View v = draw(d);
            w.write(std::string("nonmanifold_") + c.name + ".png", v.scene, gr::whole(v.scene, aspect, c.yaw, c.pitch),
                    d.build_problem);
        }
    }
    return w.finish();
}

// ---- the window ------------------------------------------------------------------------------------------------------

const char* kKeys =
    "Window keys:\n"
    "  click           pick a vertex / face / half-edge (left drag orbits, right drag pans, wheel zooms)\n"
    "  V, F, H         vertex mode (one-ring), face mode (half-edges, neighbours), half-edge mode\n"
    "  N, T, P, O      half-edge mode: go to next(h), twin(h), prev(h), next(twin(h))\n"
    "  B, W            boundary loops on/off, wireframe on/off\n"
    "  Space, R, J     one smoothing iteration, reset, jitter (add noise)\n"
    "  Z, Home         zoom onto the selection (face-on), whole mesh\n"
    "  S, Esc          screenshot (out/screenshots/), quit";

// Applies key `key`; returns true when the camera should zoom to the selection.
bool on_key(Demo& d, int key) {
    d.message.clear();
    auto walk = [&](const char* what, auto step) {
        if (d.mode != Mode::halfedge || !d.halfedge || !d.mesh) {
            d.message = std::string(what) + ": pick a half-edge first (H, then click)";
            return;
        }
        d.halfedge = step(*d.mesh, Halfedge{*d.halfedge}).idx;
    };
    switch (key) {
        case 'V': d.mode = Mode::vertex; break;
        case 'F': d.mode = Mode::face; break;
        case 'H': d.mode = Mode::halfedge; break;
        case 'B': d.show_boundary = !d.show_boundary; break;
        case 'W': d.wireframe = !d.wireframe.value_or(d.soup.n_faces() <= 6000); break;
        case ' ': d.smooth(1); break;
        case 'R': d.reset(); break;
        case 'J': d.jitter(0.25); d.message = "jittered by up to 0.25 × the mean edge length"; break;
        case 'N': walk("next", [](const Mesh& m, Halfedge h) { return m.next(h); }); break;
        case 'T': walk("twin", [](const Mesh& m, Halfedge h) { return m.twin(h); }); break;
        case 'P': walk("prev", [](const Mesh& m, Halfedge h) { return m.prev(h); }); break;
        case 'O': walk("next(twin)", [](const Mesh& m, Halfedge h) { return m.next(m.twin(h)); }); break;
        case 'Z': return true;
        default: break;
    }
    return false;
}

// The window: the view of `d`, picking, the keys; --zoom frames the selection at the start, Z at any time.
int run_window(const gr::DemoProgram& program, Demo& d, double zoom) {
    bool to_selection = zoom > 0 && (d.vertex || d.face || d.halfedge);  // the next frame looks at the selection
    return program.show({.title = "geolab demo 01: half-edge meshes",
                         .draw =
                             [&] {
                                 if (to_selection && !d.wireframe) d.wireframe = true;  // close up: show the edges
                                 View v = draw(d);
                                 const gr::Camera cam = to_selection ? camera_for(v, d, zoom > 0 ? zoom : 3.0)
                                                                     : gr::Camera::framing(v.scene.bounds());
                                 return gr::Frame{std::move(v.scene), cam, v.status};
                             },
                         .key = [&](int key) { return to_selection = on_key(d, key); },
                         .pick =
                             [&](const gr::Ray& ray) {
                                 d.pick(ray);
                                 return to_selection = false;
                             },
                         .key_hint = [] { return std::string(" | V F H B W Space R J Z, Esc"); }});
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_01_halfedge",
                            "Lab 01 demo: half-edge meshes. Pick a vertex (one-ring), a face or a half-edge (twin, "
                            "next); boundary loops in colour; Laplacian smoothing step by step.",
                            kKeys, 800);
    CLI::App& app = program.cli();
    std::string input;
    std::optional<std::uint32_t> vertex, face, halfedge;
    int smooth = 0;
    double t = 0.5, noise = 0.0, zoom = -1.0;
    bool no_boundary = false;
    app.add_option("mesh", input,
                   std::string("A fixture (") + kFixtureNames +
                       "), a mesh file (.obj .off .ply .stl) or a fetched model (bunny00, cow, ...). "
                       "Default: bunny00 if fetched, else icosphere");
    app.add_option("--vertex", vertex, "Select vertex N (vertex mode: its one-ring)");
    app.add_option("--face", face, "Select face N (face mode: its half-edges and neighbours)");
    app.add_option("--halfedge", halfedge, "Select half-edge N (half-edge mode: twin, next, to_vertex, face)");
    app.add_option("--smooth", smooth, "Apply K iterations of Laplacian smoothing first")->check(CLI::NonNegativeNumber);
    app.add_option("--t", t, "Smoothing step t in [0, 1]")->capture_default_str();
    app.add_option("--noise", noise, "Jitter the vertices by up to A × the mean edge length first")->check(CLI::NonNegativeNumber);
    app.add_option("--zoom", zoom,
                   "Frame the selection, R × its radius (0: the whole mesh; default 2.5 with --png and a selection)");
    app.add_flag("--no-boundary", no_boundary, "Do not draw the boundary loops");
    if (const auto status = program.parse(argc, argv)) return *status;

    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());

        if (input.empty()) input = geolab::model_path("bunny00") ? "bunny00" : "icosphere";
        Demo d(input, load(input));
        d.t = t;
        d.show_boundary = !no_boundary;
        if (noise > 0) {
            d.noise = noise;
            d.build();
        }
        if (vertex) d.mode = Mode::vertex, d.vertex = vertex;
        if (face) d.mode = Mode::face, d.face = face;
        if (halfedge) d.mode = Mode::halfedge, d.halfedge = halfedge;
        if (vertex && *vertex >= d.soup.n_vertices())
            d.message = "there is no vertex " + std::to_string(*vertex) + " (V = " + std::to_string(d.soup.n_vertices()) + ")";
        if (face && *face >= d.soup.n_faces())
            d.message = "there is no face " + std::to_string(*face) + " (F = " + std::to_string(d.soup.n_faces()) + ")";
        if (halfedge && (!d.mesh || *halfedge >= d.mesh->n_halfedges()))
            d.message = "there is no half-edge " + std::to_string(*halfedge) + (d.mesh ? "" : " (no mesh yet)");
        if (smooth > 0) d.smooth(smooth);
        if (!(t >= 0.0 && t <= 1.0)) d.message = "t = " + fmt(t) + " is outside [0, 1]";

        if (!program.png().empty()) {
            const double z = zoom >= 0 ? zoom : 2.5;
            if (z > 0 && (vertex || face || halfedge) && !d.wireframe) d.wireframe = true;  // zoomed: show the edges
            View v = draw(d);
            return program.write_png(v.scene, camera_for(v, d, z, program.aspect()), v.status);
        }
        return run_window(program, d, zoom);
    });
}
