#pragma once
//! \file halfface/mesh.hpp
//! Lab 02 — the half-face volume mesh kernel (GIVEN: you use this class, you do not write it). Handout §2.
//!
//! The paper's half-face structure (Kim, Seo & Oh 2008, "OpenVolMesh"), with index handles instead of pointers:
//!
//! | paper / lecture                | here                          | meaning                                          |
//! |--------------------------------|-------------------------------|--------------------------------------------------|
//! | vertex                         | `Vertex v`                    | a point, `mesh.position(v)`                      |
//! | edge                           | `Edge e`                      | an undirected edge, `mesh.edge_vertices(e)`      |
//! | face                           | `Face f`                      | a polygon shared by at most two cells            |
//! | half-face                      | `HalfFace hf` = 2f or 2f + 1  | one side of a face; `opposite(hf) = hf ^ 1`      |
//! | `hf->cell`                     | `mesh.cell(hf)`               | the cell on this side (invalid: boundary)        |
//! | `hf->halfedge`                 | `mesh.halfedge(hf)`           | the first half-edge of the half-face's loop      |
//! | half-edge                      | `HalfEdge h`                  | one corner of one half-face (directed side)      |
//! | `he->vertex`                   | `mesh.to_vertex(h)`           | the vertex at the END of h                       |
//! | `he->next`, `he->prev`         | `mesh.next(h)`, `mesh.prev(h)`| around the half-face, counter-clockwise outside  |
//! | `he->halfface`, `he->edge`     | `mesh.halfface(h)`, `edge(h)` | the half-face h belongs to; its undirected edge  |
//! | `he->mate` (radial neighbour)  | `mesh.mate(h)`                | the same edge in opposite(halfface(h)), reversed |
//! | twin inside the cell           | `mesh.twin(h)`                | the same edge in the cell's other half-face      |
//! | `cell->halffaces`              | `mesh.halffaces(c)`           | the cell's half-faces, outward                   |
//!
//! A half-face's loop runs counter-clockwise seen from outside its cell (so its normal by the right-hand rule
//! points out of the cell); the opposite half-face runs the other way. Every face has both half-faces, also on
//! the boundary: a boundary half-face has no cell (`cell(hf)` invalid) and its half-edges have no twin.
//!
//! Walking around an edge (the paper's EdgeCellIter): from a half-edge h in cell c, `twin(h)` is the same edge in
//! c's other half-face through it, and `mate(twin(h))` is that edge again in the neighbouring cell.
//!
//! Traits (the paper's memory/speed trade-off, chosen at compile time): `StorePrev` keeps prev per half-edge
//! (else prev walks the loop, O(face size)); `StoreMate` keeps mate per half-edge (else mate searches the opposite
//! loop, O(face size)); `VertexCache` keeps each vertex's incident half-faces (else they are found by a walk over
//! the half-edges around the vertex). Every accessor answers the same in every configuration. The lab's functions
//! take `Mesh`, the configuration that stores everything; `convert<T>(mesh)` gives any other.
//!
//! Deletion marks elements (`is_deleted`); they stay in the arrays, keep their handles, and are skipped by the
//! `*_alive()` ranges until garbage collection removes them. Dynamic properties are arrays beside the elements.
#include <algorithm>
#include <array>
#include <cassert>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <glm/vec3.hpp>
#include <limits>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/memory.hpp"

namespace geolab::halfface {

//! The index of "no element".
inline constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();

//! The element kinds; a handle's kind is part of its type.
enum class Kind : std::uint8_t { vertex, edge, halfedge, face, halfface, cell };
inline constexpr int n_kinds = 6;

//! A typed index. Invalid by default; compares and hashes by index; prints as e.g. `hf12` (or `hf-`). Different
//! kinds do not mix: a Vertex cannot be passed where a Cell is expected.
template <Kind K>
struct Handle {
    std::uint32_t idx = invalid_index;

    constexpr Handle() = default;
    constexpr explicit Handle(std::uint32_t i) : idx(i) {}
    constexpr bool is_valid() const { return idx != invalid_index; }
    static constexpr Kind kind = K;
    GEOLAB_FIELDS(idx)

    friend constexpr bool operator==(Handle, Handle) = default;
    friend constexpr auto operator<=>(Handle, Handle) = default;
    friend std::ostream& operator<<(std::ostream& os, Handle h) {
        static constexpr const char* names[] = {"v", "e", "h", "f", "hf", "c"};
        os << names[static_cast<int>(K)];
        return h.is_valid() ? os << h.idx : os << '-';
    }
};

using Vertex = Handle<Kind::vertex>;
using Edge = Handle<Kind::edge>;
using HalfEdge = Handle<Kind::halfedge>;
using Face = Handle<Kind::face>;
using HalfFace = Handle<Kind::halfface>;
using Cell = Handle<Kind::cell>;

//! All handles of one kind, 0 .. n-1 (deleted ones included), for range-for.
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

//! One dynamic property: a name, the element kind, the size of one value and the values' bytes (one value per
//! element, in element order). Values must be trivially copyable. Kept untyped so that it crosses the grading
//! boundary; use it through PropertyHandle<T>.
struct PropertyArray {
    std::string name;
    std::uint8_t kind = 0;       //!< static_cast<std::uint8_t>(Kind)
    std::uint32_t value_size = 0;
    std::uint64_t type_hash = 0;  //!< typeid(T).hash_code(), checked on every typed access
    bool alive = true;           //!< false once removed (its slot is not reused)
    std::vector<std::uint8_t> bytes;
    GEOLAB_FIELDS(name, kind, value_size, type_hash, alive, bytes)
};

//! A typed handle to a property of element kind K with values T.
template <Kind K, class T>
struct PropertyHandle {
    std::uint32_t idx = invalid_index;
    bool is_valid() const { return idx != invalid_index; }
};

//! Compile-time options of the kernel (see the file comment).
template <bool StorePrev, bool StoreMate, bool VertexCache>
struct Traits {
    static constexpr bool store_prev = StorePrev;
    static constexpr bool store_mate = StoreMate;
    static constexpr bool vertex_cache = VertexCache;
};
using FullTraits = Traits<true, true, true>;      //!< everything stored: fastest queries, most memory
using CompactTraits = Traits<false, false, false>;  //!< nothing extra stored: derived by walking

//! The half-face volume mesh. Reading it: the accessors (O(1) unless said). Building it: the low-level `add_*`
//! and `set_*` functions, which check nothing; `build_mesh` (your Task 1) uses them and `validate()` checks.
template <class T>
class BasicMesh {
public:
    using traits = T;

    // ---- sizes and ranges (deleted elements included) -------------------------------------------------------
    std::size_t n_vertices() const { return positions_.size(); }
    std::size_t n_edges() const { return edge_vertices_.size(); }
    std::size_t n_halfedges() const { return to_vertex_.size(); }
    std::size_t n_faces() const { return face_deleted_.size(); }
    std::size_t n_halffaces() const { return halfface_halfedge_.size(); }
    std::size_t n_cells() const { return cell_begin_.size() - 1; }

    HandleRange<Vertex> vertices() const { return HandleRange<Vertex>(n_vertices()); }
    HandleRange<Edge> edges() const { return HandleRange<Edge>(n_edges()); }
    HandleRange<HalfEdge> halfedges() const { return HandleRange<HalfEdge>(n_halfedges()); }
    HandleRange<Face> faces() const { return HandleRange<Face>(n_faces()); }
    HandleRange<HalfFace> halffaces() const { return HandleRange<HalfFace>(n_halffaces()); }
    HandleRange<Cell> cells() const { return HandleRange<Cell>(n_cells()); }

    //! The elements of a kind that are not deleted, in index order.
    template <class H>
    std::vector<H> alive() const {
        std::vector<H> out;
        for (std::uint32_t i = 0; i < count(H::kind); ++i)
            if (!is_deleted(H{i})) out.push_back(H{i});
        return out;
    }
    //! The number of elements of a kind that are not deleted.
    std::size_t n_alive(Kind k) const {
        std::size_t n = 0;
        for (std::uint32_t i = 0; i < count(k); ++i) n += !deleted_flag(k, i);
        return n;
    }

    // ---- half-edges -------------------------------------------------------------------------------------------
    //! The vertex h points to.
    Vertex to_vertex(HalfEdge h) const { return to_vertex_[at(h)]; }
    //! The vertex h starts at: the end of edge(h) that is not to_vertex(h). O(1).
    Vertex from_vertex(HalfEdge h) const {
        const auto& ev = edge_vertices_[edge(h).idx];
        return ev[0] == to_vertex(h) ? ev[1] : ev[0];
    }
    //! The next half-edge around halfface(h).
    HalfEdge next(HalfEdge h) const { return next_[at(h)]; }
    //! The previous half-edge around halfface(h): next(prev(h)) == h. Stored with StorePrev, else O(face size).
    HalfEdge prev(HalfEdge h) const {
        if constexpr (T::store_prev) {
            return prev_[at(h)];
        } else {
            HalfEdge g = h;
            while (next(g) != h) g = next(g);
            return g;
        }
    }
    //! The half-face h belongs to.
    HalfFace halfface(HalfEdge h) const { return halfface_[at(h)]; }
    //! The undirected edge of h.
    Edge edge(HalfEdge h) const { return edge_[at(h)]; }
    //! The half-edge of the same edge in the same cell's other half-face through it (reversed); invalid when
    //! halfface(h) has no cell.
    HalfEdge twin(HalfEdge h) const { return twin_[at(h)]; }
    //! The radial neighbour: the half-edge of the same edge in opposite(halfface(h)), reversed. Always valid.
    //! Stored with StoreMate, else found by walking the opposite loop, O(face size).
    HalfEdge mate(HalfEdge h) const {
        if constexpr (T::store_mate) {
            return mate_[at(h)];
        } else {
            const HalfEdge g0 = halfedge(opposite(halfface(h)));
            HalfEdge g = g0;
            do {
                if (edge(g) == edge(h)) return g;
                g = next(g);
            } while (g != g0);
            return HalfEdge{};
        }
    }

    // ---- half-faces, faces, cells, edges, vertices ------------------------------------------------------------
    //! The other side of the same face: hf ^ 1.
    static HalfFace opposite(HalfFace hf) { return HalfFace{hf.idx ^ 1u}; }
    //! The face of hf: hf / 2.
    static Face face(HalfFace hf) { return Face{hf.idx >> 1}; }
    //! Half-face i ∈ {0, 1} of face f: 2f + i.
    static HalfFace halfface(Face f, unsigned i) { return HalfFace{(f.idx << 1) | (i & 1u)}; }
    //! The first half-edge of hf's loop.
    HalfEdge halfedge(HalfFace hf) const { return halfface_halfedge_[at(hf)]; }
    //! The cell on hf's side; invalid for a boundary half-face.
    Cell cell(HalfFace hf) const { return halfface_cell_[at(hf)]; }
    //! True when no cell is on hf's side.
    bool is_boundary(HalfFace hf) const { return !cell(hf).is_valid(); }
    //! True when exactly one side of f has a cell.
    bool is_boundary(Face f) const { return is_boundary(halfface(f, 0)) != is_boundary(halfface(f, 1)); }
    //! The half-faces of cell c, outward, in the order they were given.
    std::span<const HalfFace> halffaces(Cell c) const {
        return {cell_halffaces_.data() + cell_begin_[at(c)], cell_halffaces_.data() + cell_begin_[c.idx + 1]};
    }
    //! The two vertices of e, as given to add_edge.
    std::array<Vertex, 2> edge_vertices(Edge e) const { return edge_vertices_[at(e)]; }
    //! One half-edge of e (any; invalid when e has none).
    HalfEdge halfedge(Edge e) const { return edge_halfedge_[at(e)]; }
    //! One half-edge leaving v (any); invalid when v is used by no face.
    HalfEdge halfedge(Vertex v) const { return vertex_halfedge_[at(v)]; }
    const glm::dvec3& position(Vertex v) const { return positions_[at(v)]; }
    glm::dvec3& position(Vertex v) { return positions_[at(v)]; }
    const std::vector<glm::dvec3>& positions() const { return positions_; }
    std::vector<glm::dvec3>& positions() { return positions_; }

    //! The half-faces that have v on their loop, in increasing index order. With VertexCache: the cache (kept by
    //! rebuild_vertex_cache()), O(n) for the n half-faces at v; without: a walk over the half-edges leaving v
    //! (h → next(twin(h)), next(mate(h)), twin(prev(h)), mate(prev(h))), O(n log n) comparisons, which finds them
    //! all when v is a manifold vertex (its cells connected through faces around v; not, e.g., at the one vertex
    //! two tetrahedra share).
    std::vector<HalfFace> vertex_halffaces(Vertex v) const {
        if constexpr (T::vertex_cache) {
            return {vcache_.begin() + vcache_begin_[at(v)], vcache_.begin() + vcache_begin_[v.idx + 1]};
        } else {
            return walk_vertex_halffaces(v);
        }
    }
    //! The walk that vertex_halffaces uses without the cache (any configuration).
    std::vector<HalfFace> walk_vertex_halffaces(Vertex v) const {
        std::vector<HalfFace> out;
        const HalfEdge h0 = halfedge(v);
        if (!h0.is_valid()) return out;
        std::vector<HalfEdge> stack{h0}, seen{h0};  // seen: sorted, for a binary search
        auto push = [&](HalfEdge g) {
            if (!g.is_valid()) return;
            const auto at = std::lower_bound(seen.begin(), seen.end(), g);
            if (at != seen.end() && *at == g) return;
            seen.insert(at, g);
            stack.push_back(g);
        };
        while (!stack.empty()) {
            const HalfEdge h = stack.back();
            stack.pop_back();
            if (twin(h).is_valid()) push(next(twin(h)));
            push(next(mate(h)));
            const HalfEdge p = prev(h);
            push(twin(p));
            push(mate(p));
        }
        for (HalfEdge h : seen) out.push_back(halfface(h));
        std::sort(out.begin(), out.end());
        return out;
    }

    // ---- deletion marks -----------------------------------------------------------------------------------------
    bool is_deleted(Vertex v) const { return vertex_deleted_[at(v)] != 0; }
    bool is_deleted(Edge e) const { return edge_deleted_[at(e)] != 0; }
    bool is_deleted(Face f) const { return face_deleted_[at(f)] != 0; }
    bool is_deleted(HalfFace hf) const { return is_deleted(face(hf)); }
    bool is_deleted(HalfEdge h) const { return is_deleted(face(halfface(h))); }
    bool is_deleted(Cell c) const { return cell_deleted_[at(c)] != 0; }
    void set_deleted(Vertex v, bool d) { vertex_deleted_[at(v)] = d; }
    void set_deleted(Edge e, bool d) { edge_deleted_[at(e)] = d; }
    void set_deleted(Face f, bool d) { face_deleted_[at(f)] = d; }
    void set_deleted(Cell c, bool d) { cell_deleted_[at(c)] = d; }
    //! True when some element is marked deleted (garbage_collection has work to do).
    bool has_garbage() const {
        for (int k = 0; k < n_kinds; ++k)
            if (n_alive(Kind(k)) != count(Kind(k))) return true;
        return false;
    }

    // ---- building (low level: nothing is checked) ---------------------------------------------------------------
    Vertex add_vertex(const glm::dvec3& p) {
        positions_.push_back(p);
        vertex_halfedge_.emplace_back();
        vertex_deleted_.push_back(0);
        grow_properties(Kind::vertex, positions_.size());
        return Vertex{std::uint32_t(positions_.size() - 1)};
    }
    //! A new edge between a and b (no half-edge yet).
    Edge add_edge(Vertex a, Vertex b) {
        edge_vertices_.push_back({a, b});
        edge_halfedge_.emplace_back();
        edge_deleted_.push_back(0);
        grow_properties(Kind::edge, edge_vertices_.size());
        return Edge{std::uint32_t(edge_vertices_.size() - 1)};
    }
    //! A new face with its two half-faces 2f, 2f+1 (no half-edges, no cells yet).
    Face add_face() {
        face_deleted_.push_back(0);
        halfface_halfedge_.resize(halfface_halfedge_.size() + 2);
        halfface_cell_.resize(halfface_cell_.size() + 2);
        grow_properties(Kind::face, face_deleted_.size());
        grow_properties(Kind::halfface, halfface_halfedge_.size());
        return Face{std::uint32_t(face_deleted_.size() - 1)};
    }
    //! A new half-edge of edge e pointing to `to`, in half-face hf (next, twin, mate, prev invalid until set).
    HalfEdge add_halfedge(Edge e, Vertex to, HalfFace hf) {
        to_vertex_.push_back(to);
        edge_.push_back(e);
        halfface_.push_back(hf);
        next_.emplace_back();
        twin_.emplace_back();
        if constexpr (T::store_prev) prev_.emplace_back();
        if constexpr (T::store_mate) mate_.emplace_back();
        grow_properties(Kind::halfedge, to_vertex_.size());
        return HalfEdge{std::uint32_t(to_vertex_.size() - 1)};
    }
    //! A new cell bounded by the given half-faces (it does not set cell(hf): use set_cell).
    Cell add_cell(std::span<const HalfFace> hfs) {
        cell_halffaces_.insert(cell_halffaces_.end(), hfs.begin(), hfs.end());
        cell_begin_.push_back(std::uint32_t(cell_halffaces_.size()));
        cell_deleted_.push_back(0);
        grow_properties(Kind::cell, n_cells());
        return Cell{std::uint32_t(n_cells() - 1)};
    }
    //! Room for nv vertices, ne edges, nh half-edges, nf faces (2 nf half-faces) and nc cells with n_cell_hf
    //! half-faces in all, so that adding that many moves no array.
    void reserve(std::size_t nv, std::size_t ne, std::size_t nh, std::size_t nf, std::size_t nc,
                 std::size_t n_cell_hf = 0) {
        positions_.reserve(nv), vertex_halfedge_.reserve(nv), vertex_deleted_.reserve(nv);
        edge_vertices_.reserve(ne), edge_halfedge_.reserve(ne), edge_deleted_.reserve(ne);
        to_vertex_.reserve(nh), edge_.reserve(nh), halfface_.reserve(nh), next_.reserve(nh), twin_.reserve(nh);
        if constexpr (T::store_prev) prev_.reserve(nh);
        if constexpr (T::store_mate) mate_.reserve(nh);
        face_deleted_.reserve(nf), halfface_halfedge_.reserve(2 * nf), halfface_cell_.reserve(2 * nf);
        cell_begin_.reserve(nc + 1), cell_deleted_.reserve(nc), cell_halffaces_.reserve(n_cell_hf);
        // large arrays: 2 MiB pages, fewer page faults on the first write (lib memory.hpp)
        prefer_huge_pages(to_vertex_), prefer_huge_pages(edge_), prefer_huge_pages(halfface_);
        prefer_huge_pages(next_), prefer_huge_pages(twin_), prefer_huge_pages(prev_), prefer_huge_pages(mate_);
        prefer_huge_pages(halfface_halfedge_), prefer_huge_pages(halfface_cell_), prefer_huge_pages(cell_halffaces_);
    }
    void set_next(HalfEdge h, HalfEdge n) { next_[at(h)] = n; }
    //! Stores prev (does nothing without StorePrev: prev is then derived).
    void set_prev(HalfEdge h, HalfEdge p) {
        if constexpr (T::store_prev) prev_[at(h)] = p;
    }
    //! Stores mate (does nothing without StoreMate: mate is then derived).
    void set_mate(HalfEdge h, HalfEdge m) {
        if constexpr (T::store_mate) mate_[at(h)] = m;
    }
    void set_twin(HalfEdge h, HalfEdge t) { twin_[at(h)] = t; }
    void set_edge(HalfEdge h, Edge e) { edge_[at(h)] = e; }
    void set_halfedge(HalfFace hf, HalfEdge h) { halfface_halfedge_[at(hf)] = h; }
    void set_cell(HalfFace hf, Cell c) { halfface_cell_[at(hf)] = c; }
    void set_halfedge(Edge e, HalfEdge h) { edge_halfedge_[at(e)] = h; }
    void set_halfedge(Vertex v, HalfEdge h) { vertex_halfedge_[at(v)] = h; }
    //! Recomputes the vertex → half-face cache from the half-edges (not deleted ones). O(#half-edges + #vertices)
    //! when half-edges are numbered in the order of their half-faces (as build_mesh and garbage_collection leave
    //! them); otherwise each vertex's list is sorted too. Does nothing without VertexCache.
    void rebuild_vertex_cache() {
        if constexpr (T::vertex_cache) {
            const std::size_t nv = n_vertices();
            vcache_begin_.assign(nv + 1, 0);
            // one entry per (vertex, half-face) corner: a half-face visits a vertex once in a valid mesh
            for (HalfEdge h : halfedges())
                if (!is_deleted(h)) ++vcache_begin_[to_vertex(h).idx + 1];
            for (std::size_t i = 0; i < nv; ++i) vcache_begin_[i + 1] += vcache_begin_[i];
            vcache_.assign(vcache_begin_[nv], HalfFace{});
            std::vector<std::uint32_t> fill(vcache_begin_.begin(), vcache_begin_.end() - 1);
            for (HalfEdge h : halfedges())
                if (!is_deleted(h)) vcache_[fill[to_vertex(h).idx]++] = halfface(h);
            for (std::size_t v = 0; v < nv; ++v) {  // sorted already when half-faces grow with their half-edges
                const auto first = vcache_.begin() + vcache_begin_[v], last = vcache_.begin() + vcache_begin_[v + 1];
                if (!std::is_sorted(first, last)) std::sort(first, last);
            }
        }
    }
    //! The raw cache, for checks: per vertex v the entries [begin[v], begin[v+1]).
    const std::vector<std::uint32_t>& vertex_cache_begin() const { return vcache_begin_; }
    const std::vector<HalfFace>& vertex_cache_entries() const { return vcache_; }

    // ---- compaction helpers for garbage collection --------------------------------------------------------------
    //! Keep the elements of kind k whose new index is valid, moving element i to new_of_old[i] (the kept ones
    //! numbered 0..n-1 in increasing old order), in every connectivity array of that kind. Properties are NOT
    //! moved (compact_properties does that) and handles stored inside the arrays are NOT renumbered
    //! (remap_handles does that): both are the caller's job.
    //! For Kind::halfface pass the half-face map (both sides of a face kept or dropped together); the face arrays
    //! are compacted with Kind::face.
    void compact(Kind k, const std::vector<std::uint32_t>& new_of_old) {
        auto keep = [&](auto& v) { compact_array(v, new_of_old); };
        switch (k) {
            case Kind::vertex: keep(positions_), keep(vertex_halfedge_), keep(vertex_deleted_); break;
            case Kind::edge: keep(edge_vertices_), keep(edge_halfedge_), keep(edge_deleted_); break;
            case Kind::halfedge:
                keep(to_vertex_), keep(edge_), keep(halfface_), keep(next_), keep(twin_);
                if constexpr (T::store_prev) keep(prev_);
                if constexpr (T::store_mate) keep(mate_);
                break;
            case Kind::face: keep(face_deleted_); break;
            case Kind::halfface: keep(halfface_halfedge_), keep(halfface_cell_); break;
            case Kind::cell: {
                std::vector<std::uint32_t> begin{0};
                std::vector<HalfFace> hfs;
                for (std::uint32_t c = 0; c + 1 < cell_begin_.size(); ++c)
                    if (new_of_old[c] != invalid_index) {
                        hfs.insert(hfs.end(), cell_halffaces_.begin() + cell_begin_[c],
                                   cell_halffaces_.begin() + cell_begin_[c + 1]);
                        begin.push_back(std::uint32_t(hfs.size()));
                    }
                cell_begin_ = std::move(begin), cell_halffaces_ = std::move(hfs);
                keep(cell_deleted_);
                break;
            }
        }
    }
    //! Keep the values of the properties of kind k whose element's new index is valid, in the new order.
    void compact_properties(Kind k, const std::vector<std::uint32_t>& new_of_old) {
        for (PropertyArray& p : props_)
            if (p.alive && p.kind == std::uint8_t(k)) {
                std::vector<std::uint8_t> out;
                out.reserve(p.bytes.size());
                const std::size_t n = p.value_size ? p.bytes.size() / p.value_size : 0;
                for (std::size_t i = 0; i < n && i < new_of_old.size(); ++i)
                    if (new_of_old[i] != invalid_index)
                        out.insert(out.end(), p.bytes.begin() + i * p.value_size,
                                   p.bytes.begin() + (i + 1) * p.value_size);
                p.bytes = std::move(out);
            }
    }
    //! Rewrites every handle stored in the connectivity arrays through the maps (one per kind, indexed by old
    //! index; invalid entries map to invalid). A map that is empty leaves that kind's handles unchanged.
    void remap_handles(const std::vector<std::uint32_t>& v, const std::vector<std::uint32_t>& e,
                       const std::vector<std::uint32_t>& h, const std::vector<std::uint32_t>& hf,
                       const std::vector<std::uint32_t>& c) {
        auto map = [](auto& x, const std::vector<std::uint32_t>& m) {
            if (!m.empty() && x.is_valid()) x.idx = x.idx < m.size() ? m[x.idx] : invalid_index;
        };
        for (auto& x : vertex_halfedge_) map(x, h);
        for (auto& ev : edge_vertices_) map(ev[0], v), map(ev[1], v);
        for (auto& x : edge_halfedge_) map(x, h);
        for (auto& x : to_vertex_) map(x, v);
        for (auto& x : edge_) map(x, e);
        for (auto& x : halfface_) map(x, hf);
        for (auto& x : next_) map(x, h);
        for (auto& x : twin_) map(x, h);
        for (auto& x : prev_) map(x, h);
        for (auto& x : mate_) map(x, h);
        for (auto& x : halfface_halfedge_) map(x, h);
        for (auto& x : halfface_cell_) map(x, c);
        for (auto& x : cell_halffaces_) map(x, hf);
    }

    // ---- dynamic properties -------------------------------------------------------------------------------------
    //! A new property named `name` on elements of kind K, every value `init`.
    template <Kind K, class V>
    PropertyHandle<K, V> add_property(const std::string& name, const V& init = V{}) {
        static_assert(std::is_trivially_copyable_v<V>, "property values must be trivially copyable");
        PropertyArray p;
        p.name = name, p.kind = std::uint8_t(K), p.value_size = sizeof(V), p.type_hash = typeid(V).hash_code();
        p.bytes.resize(count(K) * sizeof(V));
        for (std::size_t i = 0; i < count(K); ++i) std::memcpy(p.bytes.data() + i * sizeof(V), &init, sizeof(V));
        props_.push_back(std::move(p));
        return {std::uint32_t(props_.size() - 1)};
    }
    //! The property of kind K named `name` with values V; invalid when there is none.
    template <Kind K, class V>
    PropertyHandle<K, V> find_property(const std::string& name) const {
        for (std::uint32_t i = 0; i < props_.size(); ++i)
            if (props_[i].alive && props_[i].kind == std::uint8_t(K) && props_[i].name == name &&
                props_[i].type_hash == typeid(V).hash_code())
                return {i};
        return {};
    }
    //! Removes a property; its handle becomes unusable.
    template <Kind K, class V>
    void remove_property(PropertyHandle<K, V> p) {
        PropertyArray& a = prop(p);
        a.alive = false;
        a.bytes.clear();
    }
    template <Kind K, class V>
    V get(PropertyHandle<K, V> p, Handle<K> x) const {
        const PropertyArray& a = prop(p);
        if (std::size_t(x.idx) * sizeof(V) + sizeof(V) > a.bytes.size())
            throw std::out_of_range("property '" + a.name + "': no value for element " + std::to_string(x.idx));
        V v;
        std::memcpy(&v, a.bytes.data() + std::size_t(x.idx) * sizeof(V), sizeof(V));
        return v;
    }
    template <Kind K, class V>
    void set(PropertyHandle<K, V> p, Handle<K> x, const V& v) {
        PropertyArray& a = prop(p);
        if (std::size_t(x.idx) * sizeof(V) + sizeof(V) > a.bytes.size())
            throw std::out_of_range("property '" + a.name + "': no value for element " + std::to_string(x.idx));
        std::memcpy(a.bytes.data() + std::size_t(x.idx) * sizeof(V), &v, sizeof(V));
    }
    //! All property arrays (removed ones included, marked not alive).
    const std::vector<PropertyArray>& properties() const { return props_; }

    // ---- configurations ------------------------------------------------------------------------------------------
    //! The same mesh in configuration T2: stored relations copied or dropped, the cache rebuilt or dropped.
    template <class T1>
    static BasicMesh from(const BasicMesh<T1>& m) {
        BasicMesh r;
        r.positions_ = m.positions_, r.vertex_halfedge_ = m.vertex_halfedge_, r.vertex_deleted_ = m.vertex_deleted_;
        r.edge_vertices_ = m.edge_vertices_, r.edge_halfedge_ = m.edge_halfedge_, r.edge_deleted_ = m.edge_deleted_;
        r.to_vertex_ = m.to_vertex_, r.edge_ = m.edge_, r.halfface_ = m.halfface_, r.next_ = m.next_;
        r.twin_ = m.twin_;
        r.face_deleted_ = m.face_deleted_, r.halfface_halfedge_ = m.halfface_halfedge_;
        r.halfface_cell_ = m.halfface_cell_, r.cell_begin_ = m.cell_begin_, r.cell_halffaces_ = m.cell_halffaces_;
        r.cell_deleted_ = m.cell_deleted_, r.props_ = m.props_;
        if constexpr (T::store_prev) {
            r.prev_.resize(r.to_vertex_.size());
            for (HalfEdge h : r.halfedges()) r.prev_[h.idx] = m.prev(h);
        }
        if constexpr (T::store_mate) {
            r.mate_.resize(r.to_vertex_.size());
            for (HalfEdge h : r.halfedges()) r.mate_[h.idx] = m.mate(h);
        }
        r.rebuild_vertex_cache();
        return r;
    }
    //! Bytes held by the connectivity arrays of each element kind (their capacity; positions and properties
    //! excluded), for the benchmark. `faces` counts the per-face and the per-half-face arrays.
    struct MemoryUse {
        std::size_t vertices = 0, edges = 0, halfedges = 0, faces = 0, cells = 0, vertex_cache = 0;
        std::size_t total() const { return vertices + edges + halfedges + faces + cells + vertex_cache; }
    };
    MemoryUse memory_use() const {
        auto b = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
        MemoryUse u;
        u.vertices = b(vertex_halfedge_) + b(vertex_deleted_);
        u.edges = b(edge_vertices_) + b(edge_halfedge_) + b(edge_deleted_);
        u.halfedges = b(to_vertex_) + b(edge_) + b(halfface_) + b(next_) + b(twin_) + b(prev_) + b(mate_);
        u.faces = b(face_deleted_) + b(halfface_halfedge_) + b(halfface_cell_);
        u.cells = b(cell_begin_) + b(cell_halffaces_) + b(cell_deleted_);
        u.vertex_cache = b(vcache_begin_) + b(vcache_);
        return u;
    }
    //! Bytes held by all connectivity arrays: memory_use().total().
    std::size_t connectivity_bytes() const { return memory_use().total(); }

    //! The number of elements of kind k.
    std::size_t count(Kind k) const {
        switch (k) {
            case Kind::vertex: return n_vertices();
            case Kind::edge: return n_edges();
            case Kind::halfedge: return n_halfedges();
            case Kind::face: return n_faces();
            case Kind::halfface: return n_halffaces();
            case Kind::cell: return n_cells();
        }
        return 0;
    }

private:
    template <class>
    friend class BasicMesh;

    bool deleted_flag(Kind k, std::uint32_t i) const {
        switch (k) {
            case Kind::vertex: return vertex_deleted_[i];
            case Kind::edge: return edge_deleted_[i];
            case Kind::halfedge: return face_deleted_[halfface_[i].idx >> 1];
            case Kind::face: return face_deleted_[i];
            case Kind::halfface: return face_deleted_[i >> 1];
            case Kind::cell: return cell_deleted_[i];
        }
        return false;
    }
    template <class A>
    static void compact_array(A& a, const std::vector<std::uint32_t>& new_of_old) {
        std::size_t n = 0;
        for (std::size_t i = 0; i < a.size() && i < new_of_old.size(); ++i)
            if (new_of_old[i] != invalid_index) a[n++] = a[i];
        a.resize(n);
    }
    void grow_properties(Kind k, std::size_t n) {
        for (PropertyArray& p : props_)
            if (p.alive && p.kind == std::uint8_t(k)) p.bytes.resize(n * p.value_size);
    }
    template <Kind K, class V>
    PropertyArray& prop(PropertyHandle<K, V> p) {
        return const_cast<PropertyArray&>(std::as_const(*this).prop(p));
    }
    template <Kind K, class V>
    const PropertyArray& prop(PropertyHandle<K, V> p) const {
        if (p.idx >= props_.size() || !props_[p.idx].alive || props_[p.idx].type_hash != typeid(V).hash_code())
            throw std::invalid_argument("property handle " + std::to_string(p.idx) + " is invalid or removed");
        return props_[p.idx];
    }

    // Index checks in debug builds only.
    std::size_t at(Vertex v) const { return assert(v.idx < positions_.size()), v.idx; }
    std::size_t at(Edge e) const { return assert(e.idx < edge_vertices_.size()), e.idx; }
    std::size_t at(HalfEdge h) const { return assert(h.idx < to_vertex_.size()), h.idx; }
    std::size_t at(Face f) const { return assert(f.idx < face_deleted_.size()), f.idx; }
    std::size_t at(HalfFace hf) const { return assert(hf.idx < halfface_halfedge_.size()), hf.idx; }
    std::size_t at(Cell c) const { return assert(c.idx + 1 < cell_begin_.size()), c.idx; }

    // per vertex
    std::vector<glm::dvec3> positions_;
    std::vector<HalfEdge> vertex_halfedge_;
    std::vector<std::uint8_t> vertex_deleted_;
    // per edge
    std::vector<std::array<Vertex, 2>> edge_vertices_;
    std::vector<HalfEdge> edge_halfedge_;
    std::vector<std::uint8_t> edge_deleted_;
    // per half-edge
    std::vector<Vertex> to_vertex_;
    std::vector<Edge> edge_;
    std::vector<HalfFace> halfface_;
    std::vector<HalfEdge> next_;
    std::vector<HalfEdge> twin_;
    std::vector<HalfEdge> prev_;  // StorePrev only
    std::vector<HalfEdge> mate_;  // StoreMate only
    // per face (deleted flag) and half-face (2f, 2f + 1)
    std::vector<std::uint8_t> face_deleted_;
    std::vector<HalfEdge> halfface_halfedge_;
    std::vector<Cell> halfface_cell_;
    // per cell: half-faces cell_halffaces_[cell_begin_[c] .. cell_begin_[c+1])
    std::vector<std::uint32_t> cell_begin_{0};
    std::vector<HalfFace> cell_halffaces_;
    std::vector<std::uint8_t> cell_deleted_;
    // VertexCache only: per vertex v the half-faces vcache_[vcache_begin_[v] .. vcache_begin_[v+1])
    std::vector<std::uint32_t> vcache_begin_;
    std::vector<HalfFace> vcache_;
    // dynamic properties
    std::vector<PropertyArray> props_;

public:
    GEOLAB_FIELDS(positions_, vertex_halfedge_, vertex_deleted_, edge_vertices_, edge_halfedge_, edge_deleted_,
                  to_vertex_, edge_, halfface_, next_, twin_, prev_, mate_, face_deleted_, halfface_halfedge_,
                  halfface_cell_, cell_begin_, cell_halffaces_, cell_deleted_, vcache_begin_, vcache_, props_)
};

//! The configuration the lab's functions take: everything stored.
using Mesh = BasicMesh<FullTraits>;

//! The same mesh in configuration T2.
template <class T2, class T1>
BasicMesh<T2> convert(const BasicMesh<T1>& m) {
    return BasicMesh<T2>::from(m);
}

//! Check every invariant of a half-face mesh (deleted elements skipped); throw geolab::TopologyError naming the
//! FIRST broken one and the element. Checked: index ranges; each half-face loop closes (next), has ≥ 3 half-edges,
//! all in that half-face, consecutive (to_vertex(h) == from_vertex(next(h))); prev and mate as the accessors say
//! (next(prev(h)) == h; mate(h) in the opposite half-face, same edge, reversed; mate(mate(h)) == h); twin(h) is
//! valid exactly when halfface(h) has a cell, lies in another half-face of that cell, same edge, reversed, and
//! twin(twin(h)) == h; each cell's half-faces name it as their cell and each half-face is in its cell's list;
//! halfedge(e) and halfedge(v) are alive half-edges of e / leaving v (v used by a face); no face is alive with
//! both sides without a cell; with VertexCache, the cache lists exactly the alive half-faces around each vertex.
void validate(const Mesh& mesh);

}  // namespace geolab::halfface

template <geolab::halfface::Kind K>
struct std::hash<geolab::halfface::Handle<K>> {
    std::size_t operator()(geolab::halfface::Handle<K> h) const noexcept { return std::hash<std::uint32_t>{}(h.idx); }
};
