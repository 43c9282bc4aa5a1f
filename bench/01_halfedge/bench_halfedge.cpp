// Lab 01 benchmark: half-edge construction from a 1M-face triangle soup, and a full one-ring sweep (sum of the
// neighbours' positions at every vertex), geolab's reference vs OpenMesh, in one run; prints the ratios.
// Goal (issue 2): ≤ 1.0× OpenMesh for both.
#include <benchmark/benchmark.h>

#include "common/ratio_main.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/halfedge.hpp"

#ifdef GEOLAB_WITH_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
#endif

namespace {

// 1000 × 500 torus, triangulated: exactly 1,000,000 triangles, 500,000 vertices.
const geolab::PolygonSoup& soup() {
    static const geolab::PolygonSoup s = geolab::fixtures::torus(1000, 500, 1.0, 0.35, true);
    return s;
}

void build_geolab(benchmark::State& state) {
    for (auto _ : state) {
        auto mesh = geolab::halfedge::build_mesh(soup());
        benchmark::DoNotOptimize(mesh.n_edges());
    }
    state.counters["faces"] = static_cast<double>(soup().n_faces());
}

void one_ring_geolab(benchmark::State& state) {
    const auto mesh = geolab::halfedge::build_mesh(soup());
    std::vector<geolab::halfedge::Vertex> ring;
    for (auto _ : state) {
        glm::dvec3 sum(0.0);
        for (auto v : mesh.vertices()) {
            geolab::halfedge::one_ring_vertices(mesh, v, ring);
            for (auto w : ring) sum += mesh.position(w);
        }
        benchmark::DoNotOptimize(sum);
    }
}

#ifdef GEOLAB_WITH_OPENMESH
OMesh build_openmesh_mesh() {
    OMesh m;
    const auto& s = soup();
    m.reserve(s.n_vertices(), s.n_vertices() + s.n_faces(), s.n_faces());
    std::vector<OMesh::VertexHandle> vh(s.n_vertices());
    for (std::size_t i = 0; i < s.n_vertices(); ++i) {
        const auto& p = s.positions[i];
        vh[i] = m.add_vertex(OMesh::Point(float(p.x), float(p.y), float(p.z)));
    }
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto c = s.face(f);
        m.add_face(vh[c[0]], vh[c[1]], vh[c[2]]);
    }
    return m;
}

void build_openmesh(benchmark::State& state) {
    for (auto _ : state) {
        OMesh m = build_openmesh_mesh();
        benchmark::DoNotOptimize(m.n_edges());
    }
}

void one_ring_openmesh(benchmark::State& state) {
    const OMesh m = build_openmesh_mesh();
    for (auto _ : state) {
        OMesh::Point sum(0, 0, 0);
        for (auto v : m.vertices())
            for (auto w : m.vv_range(v)) sum += m.point(w);
        benchmark::DoNotOptimize(sum);
    }
}
#endif

}  // namespace

BENCHMARK(build_geolab)->Name("build 1M faces/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_geolab)->Name("one-ring sweep/geolab")->Unit(benchmark::kMillisecond)->Iterations(5);
#ifdef GEOLAB_WITH_OPENMESH
BENCHMARK(build_openmesh)->Name("build 1M faces/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_openmesh)->Name("one-ring sweep/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(5);
#endif

int main(int argc, char** argv) {
    return geolab::bench::run_with_ratios(argc, argv, {{"build 1M faces", 1.0}, {"one-ring sweep", 1.0}});
}
