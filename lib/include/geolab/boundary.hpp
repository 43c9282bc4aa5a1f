#pragma once
//! \file boundary.hpp
//! What crosses the grading boundary between a student's code and the tests (see docs/architecture.md,
//! "Grading protocol"). A lab declares it in its API header and nowhere else:
//!
//! - every struct a student function returns or fills lists its fields once, inside the struct:
//!
//!       struct Components { int count = 0; std::vector<int> vertex_component; GEOLAB_FIELDS(count, vertex_component) };
//!
//! - the end of the lab's API header lists the student's functions, one `GEOLAB_BOUNDARY(name, signature)` per
//!   function (the signature picks the overload), inside `#ifdef GEOLAB_BOUNDARY`:
//!
//!       #ifdef GEOLAB_BOUNDARY
//!       GEOLAB_BOUNDARY(build_mesh, Mesh(const PolygonSoup&))
//!       GEOLAB_BOUNDARY(face_halfedges, void(const Mesh&, Face, std::vector<Halfedge>&))
//!       #endif
//!
//! Student code never sees GEOLAB_BOUNDARY defined: the list is read only by the grader's record and replay
//! layers (lib/src/grading/boundary_shim.cpp), which give every listed call a recorder (in the program that runs
//! the student's code) and a replayer (in the judge, which has no student code and decides the verdict).
#include <tuple>

//! The fields of a struct that cross the boundary, in order (inside the struct; private members allowed).
#define GEOLAB_FIELDS(...)                                                                                       \
    auto geolab_fields() { return std::tie(__VA_ARGS__); }                                                      \
    auto geolab_fields() const { return std::tie(__VA_ARGS__); }
