#include "nodes/annotation/LabelFont.h"

#include "nodes/annotation/NumberFont.h"
#include "nodes/annotation/detail/TrueTypeFace.h"
#include "scenegraph/Error.h"
#include "scenegraph/Log.h"

#include <algorithm>
#include <map>
#include <mutex>

namespace texsplat::annotation {
namespace {

// The face of `file`, read on first use; nullptr, after one warning, when it cannot be read.
std::shared_ptr<const detail::TrueTypeFace> faceOf(const std::string& file) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const detail::TrueTypeFace>> faces;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = faces.find(file);
    if (found != faces.end()) {
        return found->second;
    }
    std::shared_ptr<const detail::TrueTypeFace> face;
    if (file.empty()) {
        log(LogLevel::Warning, "labels use the built-in bitmap font: no TrueType font was found "
                               "when texsplat was built (Debian: fonts-dejavu-core)");
    } else {
        try {
            face = std::make_shared<const detail::TrueTypeFace>(file);
        } catch (const Error& error) {
            log(LogLevel::Warning,
                std::string("labels use the built-in bitmap font: ") + error.what());
        }
    }
    faces.emplace(file, face);
    return face;
}

} // namespace

const std::string LabelFont::kDefaultFile = TEXSPLAT_LABEL_FONT_FILE;

LabelFont LabelFont::forImage(int width, int height, const std::string& file) {
    const int side = std::min(width, height);
    return LabelFont(file, std::max(12, side / 20), 1 + side / 256);
}

LabelFont::LabelFont(const std::string& file, int pixelHeight, int fallbackScale)
    : mFace(faceOf(file)), mPixelHeight(pixelHeight), mFallbackScale(fallbackScale) {}

bool LabelFont::canDraw(std::string_view text) const {
    return mFace || std::all_of(text.begin(), text.end(), NumberFont::hasGlyph);
}

int LabelFont::textWidth(std::string_view text) const {
    return mFace ? mFace->render(text, float(mPixelHeight)).width
                 : NumberFont::textWidth(text, mFallbackScale);
}

int LabelFont::height() const {
    return mFace ? mFace->render("", float(mPixelHeight)).height
                 : NumberFont::kGlyphHeight * mFallbackScale;
}

int LabelFont::shadowOffset() const {
    return mFace ? std::max(1, mPixelHeight / 12) : mFallbackScale;
}

void LabelFont::draw(image::Image& image, glm::ivec2 topLeft, std::string_view text,
                     const glm::vec4& rgba) const {
    if (!mFace) {
        NumberFont::draw(image, topLeft, text, mFallbackScale, rgba);
        return;
    }
    const detail::TrueTypeFace::Coverage coverage = mFace->render(text, float(mPixelHeight));
    for (int y = 0; y < coverage.height; ++y) {
        for (int x = 0; x < coverage.width; ++x) {
            const glm::ivec2 at = topLeft + glm::ivec2(x, y);
            const float cover = coverage.at(x, y);
            if (cover > 0.0f && at.x >= 0 && at.y >= 0 && at.x < image.width() &&
                at.y < image.height()) {
                // "Over", the glyph's coverage scaling the premultiplied colour.
                image.setPixel(at.x, at.y,
                               rgba * cover + image.pixel(at.x, at.y) * (1.0f - rgba.a * cover));
            }
        }
    }
}

void LabelFont::draw(image::Image& image, glm::ivec2 topLeft, std::string_view text,
                     const glm::vec4& rgba, TextDirection direction) const {
    if (direction == TextDirection::LeftToRight) {
        draw(image, topLeft, text, rgba);
        return;
    }
    const int width = textWidth(text);
    const int height = this->height();
    if (width <= 0 || height <= 0) {
        return;
    }
    // The coverage, drawn white on transparent, then turned: the text's column x becomes the
    // row width - 1 - x, its row y the column y.
    image::Image upright(width, height);
    draw(upright, {0, 0}, text, glm::vec4(1.0f));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float cover = upright.pixel(x, y).a;
            const glm::ivec2 at = topLeft + glm::ivec2(y, width - 1 - x);
            if (cover > 0.0f && at.x >= 0 && at.y >= 0 && at.x < image.width() &&
                at.y < image.height()) {
                image.setPixel(at.x, at.y,
                               rgba * cover + image.pixel(at.x, at.y) * (1.0f - rgba.a * cover));
            }
        }
    }
}

} // namespace texsplat::annotation
