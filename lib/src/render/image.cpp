// The one translation unit of geolab that compiles stb_image_write.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "geolab/render/image.hpp"

#include <stb/stb_image_write.h>

#include "geolab/errors.hpp"

namespace geolab::render {

void Image::write_png(const std::filesystem::path& file) const {
    if (width <= 0 || height <= 0 || rgba.size() != 4 * std::size_t(width) * height)
        throw IoError(file.string(), 0, "cannot write an empty or inconsistent image as PNG");
    if (!stbi_write_png(file.c_str(), width, height, 4, rgba.data(), 4 * width))
        throw IoError(file.string(), 0, "cannot write the PNG file (does the folder exist and is it writable?)");
}

}  // namespace geolab::render
