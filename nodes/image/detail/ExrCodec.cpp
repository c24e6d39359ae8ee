#include "nodes/image/detail/ExrCodec.h"

#include "nodes/image/detail/FileBytes.h"
#include "scenegraph/Error.h"
#include "scenegraph/InputFile.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <cerrno>
#include <cstring>
#include <exception>

namespace texsplat::image::detail {
namespace {

constexpr const char* kColorChannels[] = {"R", "G", "B", "A"};
constexpr const char* kDepthChannel = "Z";

/// Slice over one component of the interleaved vec4 pixels (or the depth floats), laid out over
/// the file's data window.
Imf::Slice floatSlice(const float* first, std::size_t stride, const Imath::Box2i& window,
                      double fillValue = 0.0) {
    const auto width = static_cast<std::size_t>(window.max.x - window.min.x + 1);
    return Imf::Slice::Make(Imf::FLOAT, first, window, stride, stride * width, 1, 1, fillValue);
}

std::string channelNames(const Imf::ChannelList& channels) {
    std::string names;
    for (auto it = channels.begin(); it != channels.end(); ++it)
        names += (names.empty() ? "" : ", ") + std::string(it.name());
    return names.empty() ? "none" : names;
}

} // namespace

void writeExr(const Image& image, std::ofstream& stream, const std::string& path) {
    Imf::Header header(image.width(), image.height());
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frameBuffer;
    const Imath::Box2i window = header.dataWindow();
    const float* pixels = &image.pixels().front().r;
    for (int c = 0; c < 4; ++c) {
        header.channels().insert(kColorChannels[c], Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(kColorChannels[c], floatSlice(pixels + c, sizeof(glm::vec4), window));
    }
    if (image.hasDepth()) {
        header.channels().insert(kDepthChannel, Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(kDepthChannel,
                           floatSlice(image.depths().data(), sizeof(float), window));
    }
    try {
        Imf::StdOFStream exrStream(stream, path.c_str());
        Imf::OutputFile file(exrStream, header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(image.height());
    } catch (const std::exception& e) {
        throw IoError(path + ": cannot write OpenEXR: " + e.what());
    }
}

Image readExr(const std::string& path) {
    requireRegularFile(path, "image file");
    std::ifstream stream(path, std::ios::binary);
    if (!stream)
        throw IoError(path + ": cannot open: " + std::strerror(errno));
    try {
        Imf::StdIFStream exrStream(stream, path.c_str());
        Imf::InputFile file(exrStream);
        const Imf::ChannelList& channels = file.header().channels();
        if (!channels.findChannel("R") || !channels.findChannel("G") ||
            !channels.findChannel("B"))
            throw DataError(path + ": OpenEXR file has no R, G, B channels (it has: " +
                            channelNames(channels) + ")");
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (width < 1 || height < 1)
            throw DataError(path + ": OpenEXR data window " + std::to_string(width) + "x" +
                            std::to_string(height) + " is empty");
        checkDecodedSize(path, width, height);
        Image image(static_cast<int>(width), static_cast<int>(height));
        Imf::FrameBuffer frameBuffer;
        float* pixels = &image.data()->r;
        for (int c = 0; c < 4; ++c) {
            const double fill = c == 3 ? 1.0 : 0.0; // a file without alpha is opaque
            frameBuffer.insert(kColorChannels[c],
                               floatSlice(pixels + c, sizeof(glm::vec4), window, fill));
        }
        if (channels.findChannel(kDepthChannel)) {
            image.addDepth();
            frameBuffer.insert(kDepthChannel, floatSlice(image.depthData(), sizeof(float), window));
        }
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw IoError(path + ": not a readable OpenEXR file: " + e.what());
    }
}

} // namespace texsplat::image::detail
