#pragma once
//! \file hostile.hpp
//! Generators of the large hostile inputs of issue 13 (the fuzz corpus keeps the small ones as files): shared by
//! the library tests (tests/lib/test_io_hostile.cpp), the corpus generator (make_corpus) and the benchmark.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "geolab/soup.hpp"

namespace geolab::hostile {

//! The STL vertex-welding hash that geolab used up to issue 13 (an unordered_map keyed by the corner's float
//! bits): kept here only to build inputs that collide in it.
inline std::size_t legacy_weld_hash(float x, float y, float z) {
    std::uint64_t h = std::bit_cast<std::uint32_t>(x);
    h = h * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint32_t>(y);
    h = h * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint32_t>(z);
    return static_cast<std::size_t>(h ^ (h >> 29));
}

//! The bucket count of the legacy welder's table for a binary STL of `triangles` triangles (it reserved
//! 3 × triangles / 4 entries; libstdc++ maps a hash to bucket hash % bucket_count).
inline std::size_t legacy_bucket_count(std::size_t triangles) {
    std::unordered_map<std::uint64_t, std::uint32_t> m;
    m.reserve(3 * triangles / 4);
    return m.bucket_count();
}

//! `n` distinct finite floats z such that every (1, 2, z) lands in bucket 0 of a `buckets`-bucket table of the
//! legacy hash. With x, y fixed, z only changes the low 32 bits w of the hash's pre-mix value B ^ z, and the final
//! h = B' ^ t where t = w ^ (w >> 29) is a bijection of w; so each t whose h is a multiple of `buckets` gives one
//! z (about 2^32 / buckets of them: 71,000 for 60,000 buckets). Empty if there are fewer than n.
inline std::vector<float> colliding_z(std::size_t n, std::size_t buckets) {
    const float x = 1.0f, y = 2.0f;
    std::uint64_t b = std::bit_cast<std::uint32_t>(x);
    b = (b * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint32_t>(y)) * 0x9E3779B97F4A7C15ull;
    const std::uint64_t b_hi = b >> 32, b_lo = b & 0xFFFFFFFFu;
    const std::uint64_t c = (b_hi << 32) ^ (b_hi << 3);  // h = c ^ t
    const std::uint64_t c_hi = c >> 32, c_lo = c & 0xFFFFFFFFu;
    // low = c_lo ^ t must satisfy (c_hi * 2^32 + low) % buckets == 0
    const std::uint64_t m = buckets, first_low = (m - ((c_hi % m) * ((std::uint64_t(1) << 32) % m)) % m) % m;
    std::vector<float> zs;
    for (std::uint64_t low = first_low; low < (std::uint64_t(1) << 32) && zs.size() < n; low += m) {
        const std::uint64_t t = c_lo ^ low, w = t ^ (t >> 29);  // the map is its own inverse on 32 bits
        const auto bits = static_cast<std::uint32_t>(b_lo ^ w);
        const float z = std::bit_cast<float>(bits);
        if (!std::isfinite(z) || bits == 0x80000000u) continue;  // -0 would weld with +0
        zs.push_back(z);
    }
    if (zs.size() < n) zs.clear();
    return zs;
}

//! A binary STL of `triangles` triangles over `vertices` distinct corners (vertices divisible by 3, triangle t
//! uses corners 3t, 3t+1, 3t+2 modulo `vertices`) that all fall into one bucket of the legacy welder: reading it
//! took 18 s with that welder (a random file of the same size: 0.01 s). Empty if no such input was found.
inline std::string colliding_stl(std::size_t triangles = 80000, std::size_t vertices = 60000) {
    const std::vector<float> z = colliding_z(vertices, legacy_bucket_count(triangles));
    if (z.empty()) return {};
    std::string out(80, ' ');
    out.replace(0, 40, "binary STL colliding in the legacy hash ");
    auto put = [&](auto v) {
        char b[sizeof v];
        std::memcpy(b, &v, sizeof v);  // little endian machines only (the tests run on x86-64 / arm64)
        out.append(b, sizeof v);
    };
    put(static_cast<std::uint32_t>(triangles));
    for (std::size_t t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) put(0.0f);  // normal
        for (std::size_t c = 0; c < 3; ++c) {
            const std::size_t v = (3 * t + c) % vertices;
            put(1.0f), put(2.0f), put(z[v]);
        }
        put(std::uint16_t{0});
    }
    return out;
}

//! An open fan of `triangles` triangles around vertex 0 (rim vertices 1 .. triangles + 1 on a circle): one
//! vertex of valence triangles + 1. build_mesh took 55 s on 400,000 of them when it was quadratic in valence.
inline PolygonSoup fan(std::size_t triangles) {
    PolygonSoup s;
    s.positions.reserve(triangles + 2);
    s.positions.emplace_back(0.0, 0.0, 0.0);
    for (std::size_t i = 0; i <= triangles; ++i) {
        const double a = 1.5 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(triangles);
        s.positions.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    s.indices.reserve(3 * triangles);
    s.offsets.reserve(triangles + 1);
    for (std::uint32_t i = 1; i <= triangles; ++i) s.add_face({0, i, i + 1});
    return s;
}

//! One polygon of `n` vertices on a circle (a single face): the soup check took 130 s on 1,000,000 of them
//! when it compared every pair of a face's vertices.
inline PolygonSoup big_polygon(std::size_t n) {
    PolygonSoup s;
    s.positions.reserve(n);
    s.indices.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
        s.positions.emplace_back(std::cos(a), std::sin(a), 0.0);
        s.indices.push_back(static_cast<std::uint32_t>(i));
    }
    s.offsets.push_back(static_cast<std::uint32_t>(n));
    return s;
}

}  // namespace geolab::hostile
