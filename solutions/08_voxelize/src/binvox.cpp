// Task 6: .binvox (handout §7).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

std::string number(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// The whitespace-separated words of a header line.
std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t p = 0;
    while (p < line.size()) {
        while (p < line.size() && (line[p] == ' ' || line[p] == '\t')) ++p;
        std::size_t e = p;
        while (e < line.size() && line[e] != ' ' && line[e] != '\t') ++e;
        if (e > p) out.push_back(line.substr(p, e - p));
        p = e;
    }
    return out;
}

}  // namespace
// END SOLUTION

std::string encode_binvox(const Binvox& file) {
    // BEGIN SOLUTION
    const Dims d = file.grid.dims;
    if (d.nx != d.ny || d.ny != d.nz) throw std::invalid_argument("encode_binvox: the grid is not cubic");
    if (d.nx < 1) throw std::invalid_argument("encode_binvox: the grid is empty");
    if (file.grid.words.size() != BitGrid(d).words.size()) throw std::invalid_argument("encode_binvox: wrong words size");
    if (!std::isfinite(file.translate.x) || !std::isfinite(file.translate.y) || !std::isfinite(file.translate.z) ||
        !std::isfinite(file.scale))
        throw std::invalid_argument("encode_binvox: translate or scale is not finite");
    const std::int64_t n = d.nx;
    std::string out = "#binvox 1\ndim " + std::to_string(n) + " " + std::to_string(n) + " " + std::to_string(n) +
                      "\ntranslate " + number(file.translate.x) + " " + number(file.translate.y) + " " +
                      number(file.translate.z) + "\nscale " + number(file.scale) + "\ndata\n";
    int value = -1, count = 0;
    auto flush = [&] {
        if (count > 0) {
            out.push_back(char(value));
            out.push_back(char(count));
        }
    };
    // file order: x slowest, then z, y fastest
    for (std::int64_t x = 0; x < n; ++x)
        for (std::int64_t z = 0; z < n; ++z)
            for (std::int64_t y = 0; y < n; ++y) {
                const int v = file.grid.get(x, y, z) ? 1 : 0;
                if (v == value && count < 255) {
                    ++count;
                } else {
                    flush();
                    value = v;
                    count = 1;
                }
            }
    flush();
    return out;
    // END SOLUTION
}

Binvox decode_binvox(const std::string& bytes, const std::string& name) {
    // BEGIN SOLUTION
    std::size_t pos = 0, line_no = 0;
    auto next_line = [&]() -> std::string_view {
        ++line_no;
        if (pos >= bytes.size()) throw IoError(name, line_no, "the header ends before its \"data\" line");
        const std::size_t e = bytes.find('\n', pos);
        if (e == std::string::npos || e - pos > 256)
            throw IoError(name, line_no, "a header line longer than 256 bytes, or without a line end");
        std::string_view line(bytes.data() + pos, e - pos);
        pos = e + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        return line;
    };
    const std::string_view first = next_line();
    int version = 0;
    if (first == "#binvox 1") version = 1;
    else if (first == "#binvox 2") version = 2;
    else throw IoError(name, line_no, "not a .binvox file (the first line must be \"#binvox 1\" or \"#binvox 2\")");
    Binvox out;
    bool have_dim = false, have_translate = false, have_scale = false;
    std::int64_t n = 0;
    auto read_double = [&](std::string_view w) {
        double x = 0;
        const char* const end = w.data() + w.size();
        const auto [p, ec] = std::from_chars(w.data(), end, x);
        if (ec != std::errc() || p != end || !std::isfinite(x))
            throw IoError(name, line_no, "\"" + std::string(w) + "\" is not a finite number");
        return x;
    };
    for (;;) {
        const std::string_view line = next_line();
        const auto w = words_of(line);
        if (w.size() == 1 && w[0] == "data") break;
        if (w.empty()) throw IoError(name, line_no, "an empty header line");
        if (w[0] == "dim") {
            if (have_dim) throw IoError(name, line_no, "a second \"dim\" line");
            if (w.size() != 4) throw IoError(name, line_no, "\"dim\" needs three sizes");
            std::int64_t s[3];
            for (int t = 0; t < 3; ++t) {
                const std::string_view word = w[t + 1];
                const char* const end = word.data() + word.size();
                const auto [p, ec] = std::from_chars(word.data(), end, s[t]);
                if (ec != std::errc() || p != end || s[t] < 1)
                    throw IoError(name, line_no, "\"" + std::string(word) + "\" is not a size >= 1");
            }
            if (s[0] != s[1] || s[1] != s[2])
                throw IoError(name, line_no, "dims " + std::to_string(s[0]) + " " + std::to_string(s[1]) + " " +
                                                 std::to_string(s[2]) + " are not equal (the format wants a cube)");
            n = s[0];
            have_dim = true;
        } else if (w[0] == "translate") {
            if (have_translate) throw IoError(name, line_no, "a second \"translate\" line");
            if (w.size() != 4) throw IoError(name, line_no, "\"translate\" needs three numbers");
            out.translate = {read_double(w[1]), read_double(w[2]), read_double(w[3])};
            have_translate = true;
        } else if (w[0] == "scale") {
            if (have_scale) throw IoError(name, line_no, "a second \"scale\" line");
            if (w.size() != 2) throw IoError(name, line_no, "\"scale\" needs one number");
            out.scale = read_double(w[1]);
            have_scale = true;
        } else {
            throw IoError(name, line_no, "unknown header line \"" + std::string(line.substr(0, 40)) + "\"");
        }
    }
    if (!have_dim) throw IoError(name, line_no, "no \"dim\" line before \"data\"");
    // Before allocating: the pairs left can hold at most 255 voxels each.
    const std::uint64_t pairs = (bytes.size() - pos) / 2;
    const long double voxels = static_cast<long double>(n) * n * n;
    if (voxels > 255.0L * static_cast<long double>(pairs))
        throw IoError(name, 0, "dim " + std::to_string(n) + " needs " +
                                   // n³ may not fit in 64 bits: converting it would be undefined
                                   (voxels < 1e19L ? std::to_string(std::uint64_t(voxels)) : std::to_string(n) + "³") +
                                   " voxels, more than the " + std::to_string(pairs) + " run-length pairs can hold");
    out.grid = BitGrid(Dims{n, n, n});
    const std::uint64_t total = std::uint64_t(n) * std::uint64_t(n) * std::uint64_t(n), nn = std::uint64_t(n);
    std::uint64_t p = 0;
    std::size_t pair = 0;
    while (p < total) {
        if (pos + 2 > bytes.size())
            throw IoError(name, 0, "the data ends after " + std::to_string(p) + " of " + std::to_string(total) + " voxels" +
                                       (pos < bytes.size() ? " (a truncated pair)" : ""));
        const auto value = static_cast<unsigned char>(bytes[pos]), count = static_cast<unsigned char>(bytes[pos + 1]);
        pos += 2;
        if (count == 0) throw IoError(name, 0, "run-length pair " + std::to_string(pair) + " has count 0");
        if (version == 1 && value > 1)
            throw IoError(name, 0, "run-length pair " + std::to_string(pair) + " has value " + std::to_string(value) +
                                       " (version 1 allows 0 or 1)");
        if (p + count > total)
            throw IoError(name, 0, "run-length pair " + std::to_string(pair) + " runs past the " + std::to_string(total) +
                                       " voxels");
        if (value != 0)
            for (std::uint64_t q = p; q < p + count; ++q) {
                // file position q = x·n² + z·n + y
                const std::uint64_t x = q / (nn * nn), z = q / nn % nn, y = q % nn;
                out.grid.set(std::int64_t(x), std::int64_t(y), std::int64_t(z));
            }
        p += count;
        ++pair;
    }
    if (pos != bytes.size())
        throw IoError(name, 0, std::to_string(bytes.size() - pos) + " bytes after the last voxel");
    return out;
    // END SOLUTION
}

}  // namespace geolab::voxels
