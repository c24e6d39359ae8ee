#include "nodes/image/detail/PngCodec.h"

#include "nodes/image/detail/FileBytes.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

// The one translation unit that compiles stb's implementations. They are made static so that
// another library in the same program that also embeds stb (tinygltf does) cannot clash with
// ours at link time, and the reader is limited to PNG, the only format it is asked to read.
#define STB_IMAGE_STATIC
#define STB_IMAGE_WRITE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>

namespace texsplat::image::detail {
namespace {

std::uint8_t toByte(float unit) {
    return static_cast<std::uint8_t>(glm::clamp(unit, 0.0f, 1.0f) * 255.0f + 0.5f);
}

void appendToStream(void* context, void* data, int size) {
    static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

struct StbFree {
    void operator()(void* data) const { stbi_image_free(data); }
};

} // namespace

void writePng(const Image& image, std::ostream& stream, const std::string& path) {
    std::vector<std::uint8_t> bytes(image.pixelCount() * 4);
    std::size_t nonFinite = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const glm::vec4& rgba = image.pixels()[i];
        if (!isFinite(rgba)) {
            ++nonFinite; // left transparent black, and reported below
            continue;
        }
        // PNG stores straight alpha: un-premultiply, so that a viewer compositing the PNG over
        // black shows the premultiplied color the renderer produced.
        const float alpha = glm::clamp(rgba.a, 0.0f, 1.0f);
        const glm::vec3 color = alpha > 0.0f ? glm::vec3(rgba) / alpha : glm::vec3(0.0f);
        for (int c = 0; c < 3; ++c)
            bytes[4 * i + c] = toByte(color[c]);
        bytes[4 * i + 3] = toByte(alpha);
    }
    if (nonFinite > 0)
        log(LogLevel::Warning, path + ": " + std::to_string(nonFinite) +
                                   " non-finite pixels written as transparent black");
    if (!stbi_write_png_to_func(appendToStream, &stream, image.width(), image.height(), 4,
                                bytes.data(), image.width() * 4))
        throw IoError(path + ": PNG encoding failed");
}

Image readPng(const std::string& path) {
    const std::vector<char> file = readFileBytes(path);
    if (file.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw IoError(path + ": PNG file too large to decode (over 2 GiB)");
    const auto* data = reinterpret_cast<const stbi_uc*>(file.data());
    const int length = static_cast<int>(file.size());
    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels))
        throw IoError(path + ": not a readable PNG file (" + stbi_failure_reason() + ")");
    checkDecodedSize(path, width, height);
    // The 16-bit loader also reads 8-bit files, scaled exactly (v · 257), so one path serves both.
    const std::unique_ptr<stbi_us, StbFree> samples(
        stbi_load_16_from_memory(data, length, &width, &height, &channels, 4));
    if (!samples)
        throw IoError(path + ": cannot decode the PNG file (" + stbi_failure_reason() + ")");
    Image image(width, height);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const stbi_us* rgba = samples.get() + 4 * i;
        const float alpha = rgba[3] / 65535.0f;
        glm::vec4& pixel = image.data()[i];
        for (int c = 0; c < 3; ++c)
            pixel[c] = rgba[c] / 65535.0f * alpha;
        pixel.a = alpha;
    }
    return image;
}

} // namespace texsplat::image::detail
