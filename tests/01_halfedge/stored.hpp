#pragma once
// Lab 01: meshes for the tests of Tasks 2-5 WITHOUT your build_mesh (DESIGN.md rule 6: a task's tests never depend
// on your answer to another task, so a bug in Task 1 costs Task 1's points only).
//
// tests/01_halfedge/data/<key>.inc holds, for each soup of stored_soups() (fixtures.hpp), the half-edge arrays the
// reference build_mesh makes for it: to_vertex, next and face per half-edge, halfedge per vertex and per face. The
// tests load them into a Mesh through its own building API (add_vertex, add_edge, set_next, ...) and take the
// positions from the soup, so a soup with moved vertices (a jittered grid) shares its key with the original.
// The data is an answer for these few soups only; it says nothing about how to build one (Task 1).
//
// Instructors: hidden/tools/fixture_data.cpp writes the files (`lab01_fixture_data --write tests/01_halfedge/data`)
// and the ctest `lab01_fixture_data` checks that they are what the reference builds today.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "connectivity.hpp"
#include "fixtures.hpp"

namespace lab01 {

// One stored connectivity: the soup's key and its numbers (layout: connectivity.hpp).
struct StoredConnectivity {
    const char* key;
    std::span<const std::int32_t> data;
};

namespace stored_data {
// data/index.inc (generated) defines one array per key and `entries`, the table of all of them.
#include "data/index.inc"
}  // namespace stored_data

// The mesh of `soup` from the stored connectivity of `key` (see stored_soups() in fixtures.hpp), positions from the
// soup. The key's faces must be the soup's (checked). Never calls lab code.
inline geolab::halfedge::Mesh stored_mesh(const std::string& key, const PolygonSoup& soup) {
    for (const auto& e : stored_data::entries)
        if (key == e.key) {
            auto m = mesh_from_connectivity(e.data, soup.positions, key);
            check_connectivity_matches_soup(m, soup, key);
            return m;
        }
    throw std::logic_error("no stored connectivity for '" + key + "' in tests/01_halfedge/data");
}
inline geolab::halfedge::Mesh stored_mesh(const Fixture& f) { return stored_mesh(f.name, f.soup); }

}  // namespace lab01
