#pragma once
//! \file grading/wire.hpp
//! The byte format of recorded calls (record and replay, docs/architecture.md): one codec per type, written
//! once here. Arithmetic types and enums as their bytes, bool as one byte 0/1, std::string and std::vector as a
//! 64-bit count then the elements, pair / tuple / array / optional / glm vectors and matrices element by
//! element, C arrays element by element, std::span (written only: input arguments), lab structs through their
//! GEOLAB_FIELDS list (geolab/boundary.hpp), and lab types with their own `geolab_save(Writer&) const` /
//! `geolab_load(Reader&)` members (e.g. a sparse grid that is not a list of fields). Contiguous arithmetic or glm
//! elements of a vector or span are copied as one block.
//!
//! The Reader reads bytes that the student's process wrote: nothing it reads is trusted. Every read is bounded
//! by the bytes the recording may still hold (a count of n elements needs at least n bytes left), a short read
//! is Error{truncated}, an impossible value (a bool that is 7, a count larger than what is left) Error{malformed}.
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace geolab::wire {

//! Why a recording could not be read.
struct Error : std::runtime_error {
    enum Kind { truncated, malformed } kind;
    Error(Kind k, const std::string& what) : std::runtime_error(what), kind(k) {}
};

//! Appends encoded values to a byte string.
class Writer {
public:
    void bytes(const void* p, std::size_t n) { buf_.append(static_cast<const char*>(p), n); }
    void u8(std::uint8_t v) { bytes(&v, 1); }
    void u32(std::uint32_t v) { bytes(&v, 4); }
    void u64(std::uint64_t v) { bytes(&v, 8); }
    std::string& buffer() { return buf_; }
    //! v through its codec (for lab types' geolab_save members, which cannot name wire::write).
    template <class T>
    void value(const T& v);

private:
    std::string buf_;
};

//! Reads encoded values from a file descriptor (a pipe from the student's process), at most `limit` bytes in
//! all. Blocks until the bytes arrive; end of file in the middle of a value is Error{truncated}.
class Reader {
public:
    Reader(int fd, std::uint64_t limit) : fd_(fd), limit_(limit) {}
    //! n bytes into p.
    void bytes(void* p, std::size_t n);
    std::uint8_t u8() {
        std::uint8_t v;
        bytes(&v, 1);
        return v;
    }
    std::uint32_t u32() {
        std::uint32_t v;
        bytes(&v, 4);
        return v;
    }
    std::uint64_t u64() {
        std::uint64_t v;
        bytes(&v, 8);
        return v;
    }
    //! A count of elements that take at least `min_bytes` each: never more than the recording can still hold.
    std::size_t count(std::size_t min_bytes) {
        const std::uint64_t n = u64();
        if (min_bytes > 0 && n > left() / min_bytes)
            throw Error(Error::malformed, "a count of " + std::to_string(n) + " elements exceeds what the recording holds");
        return static_cast<std::size_t>(n);
    }
    //! Bytes the recording may still hold.
    std::uint64_t left() const { return limit_ - consumed_; }
    std::uint64_t consumed() const { return consumed_; }
    //! True when at least one byte can be read now without blocking (it stays unread).
    bool ready();
    //! True at a clean end of file (nothing more will come).
    bool at_end();
    //! v through its codec (for lab types' geolab_load members).
    template <class T>
    void value(T& v);
    //! A malformed recording (for lab types' geolab_load members): throws Error{malformed}.
    [[noreturn]] void fail(const std::string& what) { throw Error(Error::malformed, what); }

private:
    bool fill();  // at least one byte into buf_; false at end of file
    int fd_;
    std::uint64_t limit_, consumed_ = 0;
    std::string buf_;
    std::size_t pos_ = 0;
};

template <class T, class = void>
struct Codec;

//! The fewest bytes one encoded T takes (bounds counts of untrusted recordings).
template <class T>
constexpr std::size_t min_size() {
    if constexpr (requires { Codec<T>::min_bytes; }) return Codec<T>::min_bytes;
    else return 1;
}

template <class T>
void write(Writer& w, const T& v) {
    Codec<T>::write(w, v);
}
template <class T>
void read(Reader& r, T& v) {
    Codec<T>::read(r, v);
}

template <class T>
struct Codec<T, std::enable_if_t<std::is_arithmetic_v<T> && !std::is_same_v<T, bool>>> {
    static constexpr std::size_t min_bytes = sizeof(T);
    static void write(Writer& w, const T& v) { w.bytes(&v, sizeof v); }
    static void read(Reader& r, T& v) { r.bytes(&v, sizeof v); }
};
template <>
struct Codec<bool> {
    static constexpr std::size_t min_bytes = 1;
    static void write(Writer& w, bool v) { w.u8(v ? 1 : 0); }
    static void read(Reader& r, bool& v) {
        const std::uint8_t b = r.u8();
        if (b > 1) throw Error(Error::malformed, "a bool that is " + std::to_string(b));
        v = b == 1;
    }
};
template <class T>
struct Codec<T, std::enable_if_t<std::is_enum_v<T>>> {
    using U = std::underlying_type_t<T>;
    static constexpr std::size_t min_bytes = sizeof(U);
    static void write(Writer& w, const T& v) { Codec<U>::write(w, static_cast<U>(v)); }
    static void read(Reader& r, T& v) {
        U u;
        Codec<U>::read(r, u);
        v = static_cast<T>(u);
    }
};
template <>
struct Codec<std::string> {
    static constexpr std::size_t min_bytes = 8;
    static void write(Writer& w, const std::string& s) {
        w.u64(s.size());
        w.bytes(s.data(), s.size());
    }
    static void read(Reader& r, std::string& s) {
        s.resize(r.count(1));
        r.bytes(s.data(), s.size());
    }
};
//! Elements copied as one block of bytes: arithmetic types but bool, and glm vectors of them (no padding).
template <class T>
constexpr bool is_blob = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;
template <glm::length_t L, class T, glm::qualifier Q>
constexpr bool is_blob<glm::vec<L, T, Q>> = is_blob<T> && sizeof(glm::vec<L, T, Q>) == L * sizeof(T);

template <class T, class A>
struct Codec<std::vector<T, A>> {
    static constexpr std::size_t min_bytes = 8;
    static void write(Writer& w, const std::vector<T, A>& v) {
        w.u64(v.size());
        if constexpr (is_blob<T>) {
            w.bytes(v.data(), v.size() * sizeof(T));
        } else if constexpr (std::is_same_v<T, bool>) {
            for (bool b : v) w.u8(b ? 1 : 0);
        } else {
            for (const T& x : v) wire::write(w, x);
        }
    }
    static void read(Reader& r, std::vector<T, A>& v) {
        const std::size_t n = r.count(min_size<T>());
        if constexpr (is_blob<T>) {
            v.resize(n);
            r.bytes(v.data(), n * sizeof(T));
            return;
        }
        v.clear();
        v.reserve(n);  // bounded by the bytes left: a hostile count cannot reserve more than the recording holds
        for (std::size_t i = 0; i < n; ++i) {
            T x{};
            wire::read(r, x);
            v.push_back(std::move(x));
        }
    }
};
template <class A, class B>
struct Codec<std::pair<A, B>> {
    static constexpr std::size_t min_bytes = min_size<A>() + min_size<B>();
    static void write(Writer& w, const std::pair<A, B>& p) {
        wire::write(w, p.first);
        wire::write(w, p.second);
    }
    static void read(Reader& r, std::pair<A, B>& p) {
        wire::read(r, p.first);
        wire::read(r, p.second);
    }
};
template <class... T>
struct Codec<std::tuple<T...>> {
    static constexpr std::size_t min_bytes = (std::size_t{0} + ... + min_size<T>());
    static void write(Writer& w, const std::tuple<T...>& t) {
        std::apply([&](const auto&... x) { (wire::write(w, x), ...); }, t);
    }
    static void read(Reader& r, std::tuple<T...>& t) {
        std::apply([&](auto&... x) { (wire::read(r, x), ...); }, t);
    }
};
template <class T, std::size_t N>
struct Codec<std::array<T, N>> {
    static constexpr std::size_t min_bytes = N * min_size<T>();
    static void write(Writer& w, const std::array<T, N>& a) {
        for (const T& x : a) wire::write(w, x);
    }
    static void read(Reader& r, std::array<T, N>& a) {
        for (T& x : a) wire::read(r, x);
    }
};
template <class T>
struct Codec<std::optional<T>> {
    static constexpr std::size_t min_bytes = 1;
    static void write(Writer& w, const std::optional<T>& o) {
        w.u8(o ? 1 : 0);
        if (o) wire::write(w, *o);
    }
    static void read(Reader& r, std::optional<T>& o) {
        bool has = false;
        wire::read(r, has);
        o.reset();
        if (has) {
            T x{};
            wire::read(r, x);
            o = std::move(x);
        }
    }
};
template <glm::length_t L, class T, glm::qualifier Q>
struct Codec<glm::vec<L, T, Q>> {
    static constexpr std::size_t min_bytes = L * min_size<T>();
    static void write(Writer& w, const glm::vec<L, T, Q>& v) {
        for (glm::length_t i = 0; i < L; ++i) wire::write(w, v[i]);
    }
    static void read(Reader& r, glm::vec<L, T, Q>& v) {
        for (glm::length_t i = 0; i < L; ++i) wire::read(r, v[i]);
    }
};
template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
struct Codec<glm::mat<C, R, T, Q>> {
    static constexpr std::size_t min_bytes = C * R * min_size<T>();
    static void write(Writer& w, const glm::mat<C, R, T, Q>& m) {
        for (glm::length_t i = 0; i < C; ++i) wire::write(w, m[i]);
    }
    static void read(Reader& r, glm::mat<C, R, T, Q>& m) {
        for (glm::length_t i = 0; i < C; ++i) wire::read(r, m[i]);
    }
};
template <class T, std::size_t N>
struct Codec<T[N]> {
    static constexpr std::size_t min_bytes = N * min_size<T>();
    static void write(Writer& w, const T (&a)[N]) {
        for (const T& x : a) wire::write(w, x);
    }
    static void read(Reader& r, T (&a)[N]) {
        for (T& x : a) wire::read(r, x);
    }
};
//! A span: written like a vector (input arguments only; nothing is read into a span).
template <class T, std::size_t E>
struct Codec<std::span<T, E>> {
    static constexpr std::size_t min_bytes = 8;
    static void write(Writer& w, const std::span<T, E>& v) {
        w.u64(v.size());
        if constexpr (is_blob<std::remove_cv_t<T>>) {
            w.bytes(v.data(), v.size() * sizeof(T));
        } else {
            for (const auto& x : v) wire::write(w, x);
        }
    }
};
//! A lab type with its own encoding: geolab_save(Writer&) const and geolab_load(Reader&).
template <class T>
struct Codec<T, std::void_t<decltype(std::declval<const T&>().geolab_save(std::declval<Writer&>()))>> {
    static void write(Writer& w, const T& v) { v.geolab_save(w); }
    static void read(Reader& r, T& v) { v.geolab_load(r); }
};
//! A lab struct: its GEOLAB_FIELDS, in order.
template <class T>
struct Codec<T, std::void_t<decltype(std::declval<T&>().geolab_fields())>> {
    static void write(Writer& w, const T& v) {
        std::apply([&](const auto&... x) { (wire::write(w, x), ...); }, v.geolab_fields());
    }
    static void read(Reader& r, T& v) {
        std::apply([&](auto&... x) { (wire::read(r, x), ...); }, v.geolab_fields());
    }
};

template <class T>
void Writer::value(const T& v) {
    wire::write(*this, v);
}
template <class T>
void Reader::value(T& v) {
    wire::read(*this, v);
}

}  // namespace geolab::wire
