#pragma once
//! \file soup_bytes.hpp
//! Turns fuzzer bytes into a small polygon soup for build_mesh (shared by the fuzz target and the corpus replay):
//! byte 0 gives the vertex count (1 + b % 64); then each face is a size byte (3 + b % 6 vertices) followed by one
//! byte per vertex, read as index b % (vertex count + 1), so an index one past the end (and repeats) can occur.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geolab/soup.hpp"

namespace geolab::fuzz {

inline PolygonSoup soup_from_bytes(const std::uint8_t* data, std::size_t size) {
    PolygonSoup s;
    if (size == 0) return s;
    const std::uint32_t nv = 1 + data[0] % 64;
    for (std::uint32_t i = 0; i < nv; ++i) s.positions.emplace_back(i % 4, (i / 4) % 4, i / 16);
    std::vector<std::uint32_t> face;
    for (std::size_t at = 1; at < size;) {
        const std::size_t n = 3 + data[at++] % 6;
        face.clear();
        for (std::size_t k = 0; k < n && at < size; ++k) face.push_back(data[at++] % (nv + 1));
        if (face.size() == n) s.add_face(face);
    }
    return s;
}

}  // namespace geolab::fuzz
