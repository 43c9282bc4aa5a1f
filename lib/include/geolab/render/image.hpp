#pragma once
//! \file render/image.hpp
//! An RGBA8 image, top row first, as produced by the renderers; written as PNG.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "geolab/boundary.hpp"

namespace geolab::render {

//! width × height pixels, 4 bytes (R, G, B, A) each, rows stored top to bottom.
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  //!< size 4 · width · height
    GEOLAB_FIELDS(width, height, rgba)  // what crosses the grading boundary (lab 03 renders images)

    //! The (R, G, B, A) of pixel (x, y); (0, 0) is the top-left corner. \pre 0 ≤ x < width, 0 ≤ y < height.
    std::array<std::uint8_t, 4> pixel(int x, int y) const {
        const std::uint8_t* p = rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
        return {p[0], p[1], p[2], p[3]};
    }
    //! Writes the image as a PNG file. \throw geolab::IoError if the file cannot be written.
    void write_png(const std::filesystem::path& file) const;
};

}  // namespace geolab::render
