#pragma once
// The blob scene file of `geolab blobby` (lab 04), read and checked: a header of its own so that the fuzz target
// (tests/fuzz/fuzz_blobby_scene.cpp) runs the very code the command runs. The format:
//   { "kernel": "wyvill",            // "blinn", "nishimura" or "wyvill"
//     "threshold": 0.5,              // T > 0
//     "blobs": [ { "center": [0, 0, 0], "strength": 1.0, "radius": 1.0, "a": 1.0 }, ... ] }
// strength (b, default 1; negative subtracts), radius (R of nishimura and wyvill, default 1), a (Blinn's falloff,
// default 1). Unknown keys are errors (a misspelt key would otherwise be silently ignored), and so is a key given
// twice in one object (JSON parsers keep the last one silently). Every error is an IoError naming the file and the
// line (a JSON syntax error) or the element ("blobs[3].radius").
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "geolab/blobby.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"

namespace geolab::cli {

// A string from the file for a message: quoted, at most 40 bytes, unprintable bytes shown as '?'.
inline std::string scene_quote(std::string_view s) {
    std::string q = "\"";
    for (char c : s.substr(0, 40)) q += (c >= 32 && c < 127) ? c : '?';
    return q + (s.size() > 40 ? "...\"" : "\"");
}

//! SAX events of a JSON text: the first key given twice in one object (empty: none).
struct DuplicateKeys : nlohmann::json_sax<nlohmann::json> {
    std::vector<std::set<std::string>> open;  // the keys of each open object
    std::string duplicate;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override {
        open.emplace_back();
        return true;
    }
    bool key(string_t& k) override {
        if (!open.empty() && !open.back().insert(k).second && duplicate.empty()) duplicate = k;
        return true;
    }
    bool end_object() override {
        if (!open.empty()) open.pop_back();
        return true;
    }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

//! Parses the text of a blob scene; `file` names it in errors. \throw IoError naming the file and the element.
inline blobby::BlobScene parse_blob_scene(const std::string& text, const std::string& file) {
    using nlohmann::json;
    auto fail = [&](const std::string& where, const std::string& reason) -> void {
        throw IoError(file, 0, where + ": " + reason);
    };
    auto number = [&](const json& j, const std::string& where) {
        if (!j.is_number()) fail(where, "expected a number, got " + std::string(j.type_name()));
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(where, "not finite");
        return v;
    };
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        const std::size_t at = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        const std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + long(at), '\n'));
        throw IoError(file, line, std::string("not valid JSON: ") + e.what());
    }
    // A key given twice: a second, linear pass over the events (nlohmann's parser callback would do it in one, but
    // it rescans an array at the end of each of its objects: quadratic, 5 s for 200,000 blobs).
    DuplicateKeys keys;
    json::sax_parse(text, &keys);
    const std::string& duplicate = keys.duplicate;
    if (!duplicate.empty()) fail("key " + scene_quote(duplicate), "given twice in one object");
    if (!j.is_object()) fail("top level", "expected an object with \"kernel\", \"threshold\" and \"blobs\"");
    for (const auto& [k, v] : j.items())
        if (k != "kernel" && k != "threshold" && k != "blobs") fail("key " + scene_quote(k), "unknown (kernel, threshold, blobs)");
    blobby::BlobScene s;
    if (!j.contains("kernel") || !j["kernel"].is_string()) fail("kernel", "expected \"blinn\", \"nishimura\" or \"wyvill\"");
    const std::string k = j["kernel"].get<std::string>();
    if (k == "blinn") s.kernel = blobby::Kernel::blinn;
    else if (k == "nishimura") s.kernel = blobby::Kernel::nishimura;
    else if (k == "wyvill") s.kernel = blobby::Kernel::wyvill;
    else fail("kernel", scene_quote(k) + " is not one of blinn, nishimura, wyvill");
    if (!j.contains("threshold")) fail("threshold", "missing");
    s.threshold = number(j["threshold"], "threshold");
    if (!(s.threshold > 0)) fail("threshold", "must be > 0");
    if (!j.contains("blobs") || !j["blobs"].is_array() || j["blobs"].empty())
        fail("blobs", "expected a non-empty array of blobs");
    for (std::size_t i = 0; i < j["blobs"].size(); ++i) {
        const json& b = j["blobs"][i];
        const std::string where = "blobs[" + std::to_string(i) + "]";
        if (!b.is_object()) fail(where, "expected an object");
        for (const auto& [key, v] : b.items())
            if (key != "center" && key != "strength" && key != "radius" && key != "a")
                fail(where + "." + scene_quote(key), "unknown key (center, strength, radius, a)");
        blobby::Blob blob;
        if (!b.contains("center") || !b["center"].is_array() || b["center"].size() != 3)
            fail(where + ".center", "expected [x, y, z]");
        for (int a = 0; a < 3; ++a) blob.center[a] = number(b["center"][a], where + ".center[" + std::to_string(a) + "]");
        if (b.contains("strength")) blob.strength = number(b["strength"], where + ".strength");
        if (b.contains("radius")) blob.radius = number(b["radius"], where + ".radius");
        if (b.contains("a")) blob.a = number(b["a"], where + ".a");
        if (s.kernel == blobby::Kernel::blinn && !(blob.a > 0)) fail(where + ".a", "Blinn's falloff must be > 0");
        if (s.kernel != blobby::Kernel::blinn && !(blob.radius > 0)) fail(where + ".radius", "must be > 0");
        s.blobs.push_back(blob);
    }
    return s;
}

//! Reads (lib's read_text_file: regular files only, GEOLAB_MAX_FILE_MB) and parses a blob scene file.
inline blobby::BlobScene read_blob_scene(const std::string& file) { return parse_blob_scene(read_text_file(file), file); }

}  // namespace geolab::cli
