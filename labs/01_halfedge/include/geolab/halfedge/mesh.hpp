#pragma once
//! \file halfedge/mesh.hpp
//! Lab 01 — the half-edge mesh (GIVEN: you use this class, you do not write it). Handout §2.
//!
//! The lecture's half-edge (DCEL) structure, with index handles instead of pointers:
//!
//! | lecture                 | here                          | meaning                                        |
//! |-------------------------|-------------------------------|------------------------------------------------|
//! | `HE_edge* e`            | `Halfedge h`                  | one directed side of an edge                   |
//! | `e->vert`               | `mesh.to_vertex(h)`           | the vertex at the END of h                     |
//! | `e->pair`               | `mesh.twin(h)`                | the same edge, opposite direction              |
//! | `e->face`               | `mesh.face(h)`                | the face on the left of h (invalid: a hole)    |
//! | `e->next`               | `mesh.next(h)`                | the next half-edge around that face, CCW       |
//! | `v->edge`               | `mesh.halfedge(v)`            | one half-edge LEAVING v                        |
//! | `f->edge`               | `mesh.halfedge(f)`            | one half-edge of f                             |
//! | `v->x, v->y, v->z`      | `mesh.position(v)`            | glm::dvec3                                     |
//!
//! Layout: the two half-edges of edge e are 2e and 2e+1, so `twin(h) = h ^ 1` and `edge(h) = h / 2`.
//! Why: twin is free (no array to fill or keep consistent), edges need no storage of their own, and the two
//! sides of an edge sit next to each other in memory. OpenMesh, PMP and Scotty3D use the same layout. The price:
//! half-edges are created in pairs (`add_edge`), so a twin must be known — or be a boundary half-edge — when the
//! edge is created.
//!
//! Boundary: every edge has two half-edges, also on the border of a hole. A half-edge with no face (`face(h)`
//! invalid) is a boundary half-edge; its `next` is the next boundary half-edge around the hole, so each hole is
//! a closed loop of boundary half-edges, just like a face. A boundary vertex stores a boundary half-edge as its
//! `halfedge(v)` (as OpenMesh and PMP do): then `is_boundary(v)` is O(1) and a walk around v starting at
//! `halfedge(v)` sees the faces as one fan, from one side of the hole to the other.
#include <cassert>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <ostream>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/memory.hpp"

namespace geolab::halfedge {

//! The index of "no element".
inline constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();

//! A typed index: `Handle<'v'>` (Vertex), `Handle<'h'>` (Halfedge), `Handle<'e'>` (Edge), `Handle<'f'>` (Face).
//! Invalid by default; compares and hashes by index; prints as e.g. `v12` (or `v-` when invalid). Different
//! kinds do not mix: a Vertex cannot be passed where a Face is expected.
template <char Kind>
struct Handle {
    std::uint32_t idx = invalid_index;

    constexpr Handle() = default;
    constexpr explicit Handle(std::uint32_t i) : idx(i) {}
    constexpr bool is_valid() const { return idx != invalid_index; }
    GEOLAB_FIELDS(idx)  // what crosses the grading boundary (geolab/boundary.hpp)

    friend constexpr bool operator==(Handle, Handle) = default;
    friend constexpr auto operator<=>(Handle, Handle) = default;
    friend std::ostream& operator<<(std::ostream& os, Handle h) {
        os << Kind;
        return h.is_valid() ? os << h.idx : os << '-';
    }
};

using Vertex = Handle<'v'>;
using Halfedge = Handle<'h'>;
using Edge = Handle<'e'>;
using Face = Handle<'f'>;

//! All handles of one kind, 0 .. n-1, for range-for: `for (Vertex v : mesh.vertices())`.
template <class H>
class HandleRange {
public:
    class iterator {
    public:
        using value_type = H;
        using difference_type = std::ptrdiff_t;
        iterator() = default;
        explicit iterator(std::uint32_t i) : i_(i) {}
        H operator*() const { return H{i_}; }
        iterator& operator++() {
            ++i_;
            return *this;
        }
        iterator operator++(int) {
            iterator old = *this;
            ++i_;
            return old;
        }
        bool operator==(const iterator&) const = default;

    private:
        std::uint32_t i_ = 0;
    };
    explicit HandleRange(std::size_t n) : n_(static_cast<std::uint32_t>(n)) {}
    iterator begin() const { return iterator{0}; }
    iterator end() const { return iterator{n_}; }
    std::size_t size() const { return n_; }

private:
    std::uint32_t n_;
};

//! A polygonal surface mesh in half-edge form. Elements are numbered 0..n-1 and never deleted.
//!
//! Reading it: the accessors below (all O(1) except `prev`). Building it: `reserve`, `add_vertex`, `add_edge`,
//! `add_face` and the `set_*` functions — low-level tools that check nothing; `build_mesh` (your Task 1) uses
//! them and `validate()` checks the result.
class Mesh {
public:
    // ---- sizes and ranges ----------------------------------------------------------------------------------
    std::size_t n_vertices() const { return positions_.size(); }
    std::size_t n_halfedges() const { return to_vertex_.size(); }
    std::size_t n_edges() const { return to_vertex_.size() / 2; }
    std::size_t n_faces() const { return face_halfedge_.size(); }

    HandleRange<Vertex> vertices() const { return HandleRange<Vertex>(n_vertices()); }
    HandleRange<Halfedge> halfedges() const { return HandleRange<Halfedge>(n_halfedges()); }
    HandleRange<Edge> edges() const { return HandleRange<Edge>(n_edges()); }
    HandleRange<Face> faces() const { return HandleRange<Face>(n_faces()); }

    // ---- half-edge connectivity: the lecture's HE_edge fields ----------------------------------------------
    //! The vertex h points to (the lecture's `vert`).
    Vertex to_vertex(Halfedge h) const { return to_vertex_[at(h)]; }
    //! The next half-edge around the face (or hole) on the left of h: counter-clockwise seen from outside.
    Halfedge next(Halfedge h) const { return next_[at(h)]; }
    //! The face on the left of h; invalid when h is a boundary half-edge (a hole is on its left).
    Face face(Halfedge h) const { return face_[at(h)]; }
    //! The opposite half-edge of the same edge (the lecture's `pair`): h ^ 1.
    Halfedge twin(Halfedge h) const { return Halfedge{h.idx ^ 1u}; }
    //! The vertex h starts at: to_vertex(twin(h)).
    Vertex from_vertex(Halfedge h) const { return to_vertex(twin(h)); }
    //! The half-edge before h in its face (or hole): next(prev(h)) == h. Not stored: found by turning around
    //! from_vertex(h) (the incoming half-edges there are twin(h), twin(next(twin(h))), ...), O(valence).
    //! \pre the mesh passes validate().
    Halfedge prev(Halfedge h) const {
        Halfedge in = twin(h);
        while (next(in) != h) in = twin(next(in));
        return in;
    }
    //! The edge h belongs to: h / 2.
    Edge edge(Halfedge h) const { return Edge{h.idx >> 1}; }

    // ---- vertex, edge and face entry points -----------------------------------------------------------------
    //! One half-edge leaving v (the lecture's `vert->edge`): a boundary one if v is on the boundary; invalid
    //! if v is isolated (used by no face).
    Halfedge halfedge(Vertex v) const { return vertex_halfedge_[at(v)]; }
    //! One half-edge of face f (the lecture's `face->edge`); the face is on its left.
    Halfedge halfedge(Face f) const { return face_halfedge_[at(f)]; }
    //! Half-edge i ∈ {0, 1} of edge e: 2e + i. halfedge(e, 1) == twin(halfedge(e, 0)).
    Halfedge halfedge(Edge e, unsigned i) const {
        assert(i < 2);
        return Halfedge{(e.idx << 1) | i};
    }

    // ---- boundary tests ------------------------------------------------------------------------------------
    //! True when no face is on the left of h.
    bool is_boundary(Halfedge h) const { return !face(h).is_valid(); }
    //! True when either side of e is a boundary half-edge.
    bool is_boundary(Edge e) const { return is_boundary(halfedge(e, 0)) || is_boundary(halfedge(e, 1)); }
    //! True when v is on the border of a hole, or isolated. O(1), because a boundary vertex's halfedge(v) is a
    //! boundary half-edge (see validate()).
    bool is_boundary(Vertex v) const {
        Halfedge h = halfedge(v);
        return !h.is_valid() || is_boundary(h);
    }
    //! True when v is used by no face (halfedge(v) is invalid).
    bool is_isolated(Vertex v) const { return !halfedge(v).is_valid(); }

    // ---- geometry ------------------------------------------------------------------------------------------
    const glm::dvec3& position(Vertex v) const { return positions_[at(v)]; }
    glm::dvec3& position(Vertex v) { return positions_[at(v)]; }
    //! All positions, indexed by vertex index.
    const std::vector<glm::dvec3>& positions() const { return positions_; }
    std::vector<glm::dvec3>& positions() { return positions_; }

    // ---- building (low level: nothing is checked; run validate() when done) --------------------------------
    //! Reserve room for nv vertices, ne edges (2·ne half-edges) and nf faces. Large arrays ask for 2 MiB pages
    //! (geolab/memory.hpp): fewer page faults when they are first written; what they hold is the same.
    void reserve(std::size_t nv, std::size_t ne, std::size_t nf) {
        positions_.reserve(nv);
        vertex_halfedge_.reserve(nv);
        to_vertex_.reserve(2 * ne);
        next_.reserve(2 * ne);
        face_.reserve(2 * ne);
        face_halfedge_.reserve(nf);
        prefer_huge_pages(positions_), prefer_huge_pages(vertex_halfedge_), prefer_huge_pages(face_halfedge_);
        prefer_huge_pages(to_vertex_), prefer_huge_pages(next_), prefer_huge_pages(face_);
    }
    //! A new vertex at p, with no half-edge yet (isolated).
    Vertex add_vertex(const glm::dvec3& p) {
        positions_.push_back(p);
        vertex_halfedge_.emplace_back();
        return Vertex{static_cast<std::uint32_t>(positions_.size() - 1)};
    }
    //! A new edge between two existing vertices: creates half-edges h = from→to and twin(h) = to→from and
    //! returns h. Their next and face are invalid until set.
    Halfedge add_edge(Vertex from, Vertex to) {
        const auto h = static_cast<std::uint32_t>(to_vertex_.size());
        to_vertex_.push_back(to);
        to_vertex_.push_back(from);
        next_.resize(next_.size() + 2);
        face_.resize(face_.size() + 2);
        return Halfedge{h};
    }
    //! A new face with no half-edge yet; set one with set_halfedge(f, h).
    Face add_face() {
        face_halfedge_.emplace_back();
        return Face{static_cast<std::uint32_t>(face_halfedge_.size() - 1)};
    }
    void set_next(Halfedge h, Halfedge n) { next_[at(h)] = n; }
    void set_face(Halfedge h, Face f) { face_[at(h)] = f; }
    void set_halfedge(Vertex v, Halfedge h) { vertex_halfedge_[at(v)] = h; }
    void set_halfedge(Face f, Halfedge h) { face_halfedge_[at(f)] = h; }

private:
    // Index checks in debug builds only (Release is the default build type: validate() is the safety net).
    std::size_t at(Vertex v) const {
        assert(v.idx < positions_.size());
        return v.idx;
    }
    std::size_t at(Halfedge h) const {
        assert(h.idx < to_vertex_.size());
        return h.idx;
    }
    std::size_t at(Face f) const {
        assert(f.idx < face_halfedge_.size());
        return f.idx;
    }

    // per vertex
    std::vector<glm::dvec3> positions_;
    std::vector<Halfedge> vertex_halfedge_;
    // per half-edge (2e, 2e+1 are the two sides of edge e)
    std::vector<Vertex> to_vertex_;
    std::vector<Halfedge> next_;
    std::vector<Face> face_;
    // per face
    std::vector<Halfedge> face_halfedge_;

public:
    GEOLAB_FIELDS(positions_, vertex_halfedge_, to_vertex_, next_, face_, face_halfedge_)  // (geolab/boundary.hpp)
};

//! Check every invariant of a half-edge mesh; throw geolab::TopologyError naming the FIRST broken one and the
//! element, e.g. "validate: halfedge 12: to_vertex(h) = 3 but next(h) starts at vertex 5". Checked, in order:
//!  1. index ranges: to_vertex, next valid and in range; face invalid or in range; halfedge(v) invalid or in
//!     range; halfedge(f) valid and in range; at least one half-edge per edge pair (even count);
//!  2. no edge is a loop: from_vertex(h) != to_vertex(h);
//!  3. next is a permutation: every half-edge is the next of exactly one half-edge (so next(prev(h)) == h
//!     and every face and hole is a closed loop);
//!  4. next continues where h ends: from_vertex(next(h)) == to_vertex(h);
//!  5. a loop of next has one face: face(next(h)) == face(h);
//!  6. faces: face(halfedge(f)) == f, and every face has at least 3 half-edges;
//!  7. no dangling edge: not both sides of an edge are boundary;
//!  8. vertices: halfedge(v) starts at v; a vertex that some half-edge starts at has a valid halfedge(v);
//!     a vertex with a boundary half-edge leaving it has halfedge(v) on the boundary;
//!  9. manifold vertices: turning around v from halfedge(v) (h → next(twin(h))) meets every half-edge that
//!     leaves v, and at most one of them is a boundary half-edge.
//! Runs in O(#half-edges). Call it after building or changing a mesh.
void validate(const Mesh& mesh);

}  // namespace geolab::halfedge

template <char Kind>
struct std::hash<geolab::halfedge::Handle<Kind>> {
    std::size_t operator()(geolab::halfedge::Handle<Kind> h) const noexcept {
        return std::hash<std::uint32_t>{}(h.idx);
    }
};
