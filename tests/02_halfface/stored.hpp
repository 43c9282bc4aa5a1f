#pragma once
// Lab 02: meshes for the tests of Tasks 2-5 WITHOUT your build_mesh (DESIGN.md rule 6: a task's tests never depend
// on your answer to another task). tests/02_halfface/data/<key>.inc holds, for each fixture of stored_fixtures()
// (fixtures.hpp), every field of the Mesh the reference build_mesh makes for it, flattened into 32-bit words
// (flatten() below). The data is an answer for these few inputs only; it says nothing about how to build one.
//
// Instructors: hidden/tools/fixture_data.cpp writes the files (`lab02_fixture_data --write tests/02_halfface/data`)
// and the ctest `lab02_fixture_data` checks that they are what the reference builds today.
#include <array>
#include <cstdint>
#include <cstring>
#include <glm/vec3.hpp>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "fixtures.hpp"
#include "geolab/halfface/mesh.hpp"

namespace lab02 {

// ---- flattening any GEOLAB_FIELDS value into 32-bit words and back ---------------------------------------------
template <class T>
void flatten(const T& x, std::vector<std::uint32_t>& out);
template <class T>
void unflatten(T& x, std::span<const std::uint32_t> in, std::size_t& pos);

namespace detail {
template <class T, class = void>
struct has_fields : std::false_type {};
template <class T>
struct has_fields<T, std::void_t<decltype(std::declval<const T&>().geolab_fields())>> : std::true_type {};
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_array : std::false_type {};
template <class T, std::size_t N>
struct is_array<std::array<T, N>> : std::true_type {};
inline std::uint32_t take(std::span<const std::uint32_t> in, std::size_t& pos) {
    if (pos >= in.size()) throw std::logic_error("stored mesh data is truncated");
    return in[pos++];
}
}  // namespace detail

template <class T>
void flatten(const T& x, std::vector<std::uint32_t>& out) {
    if constexpr (detail::has_fields<T>::value) {
        std::apply([&](const auto&... f) { (flatten(f, out), ...); }, x.geolab_fields());
    } else if constexpr (detail::is_vector<T>::value || std::is_same_v<T, std::string>) {
        out.push_back(std::uint32_t(x.size()));
        for (const auto& e : x) flatten(e, out);
    } else if constexpr (detail::is_array<T>::value) {
        for (const auto& e : x) flatten(e, out);
    } else if constexpr (std::is_same_v<T, glm::dvec3>) {
        flatten(x.x, out), flatten(x.y, out), flatten(x.z, out);
    } else if constexpr (std::is_same_v<T, double> || (std::is_integral_v<T> && sizeof(T) == 8)) {
        std::uint64_t b;
        std::memcpy(&b, &x, 8);
        out.push_back(std::uint32_t(b)), out.push_back(std::uint32_t(b >> 32));
    } else {
        static_assert(std::is_integral_v<T> || std::is_enum_v<T>);
        out.push_back(std::uint32_t(x));
    }
}

template <class T>
void unflatten(T& x, std::span<const std::uint32_t> in, std::size_t& pos) {
    if constexpr (detail::has_fields<T>::value) {
        std::apply([&](auto&... f) { (unflatten(f, in, pos), ...); }, x.geolab_fields());
    } else if constexpr (detail::is_vector<T>::value || std::is_same_v<T, std::string>) {
        const std::uint32_t n = detail::take(in, pos);
        if (n > in.size()) throw std::logic_error("stored mesh data: bad count");
        x.resize(n);
        for (auto& e : x) unflatten(e, in, pos);
    } else if constexpr (detail::is_array<T>::value) {
        for (auto& e : x) unflatten(e, in, pos);
    } else if constexpr (std::is_same_v<T, glm::dvec3>) {
        unflatten(x.x, in, pos), unflatten(x.y, in, pos), unflatten(x.z, in, pos);
    } else if constexpr (std::is_same_v<T, double> || (std::is_integral_v<T> && sizeof(T) == 8)) {
        const std::uint64_t lo = detail::take(in, pos), hi = detail::take(in, pos);
        const std::uint64_t b = lo | (hi << 32);
        std::memcpy(&x, &b, 8);
    } else {
        x = static_cast<T>(detail::take(in, pos));
    }
}

// One stored mesh: the fixture's name and its words.
struct StoredMesh {
    const char* key;
    std::span<const std::uint32_t> data;
};

namespace stored_data {
// data/index.inc (generated) defines one array per key and `entries`, the table of all of them.
#include "data/index.inc"
}  // namespace stored_data

// The mesh the reference builds for the stored fixture `key`. Never calls lab code.
inline geolab::halfface::Mesh stored_mesh(const std::string& key) {
    for (const auto& e : stored_data::entries)
        if (key == e.key) {
            geolab::halfface::Mesh m;
            std::size_t pos = 0;
            unflatten(m, e.data, pos);
            if (pos != e.data.size()) throw std::logic_error("stored mesh '" + key + "' has trailing data");
            return m;
        }
    throw std::logic_error("no stored mesh for '" + key + "' in tests/02_halfface/data");
}
inline geolab::halfface::Mesh stored_mesh(const Fixture& f) { return stored_mesh(f.name); }

}  // namespace lab02
