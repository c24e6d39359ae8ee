#include "nodes/annotation/ImageAnnotations.h"

#include "nodes/annotation/VolumeOutline.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/Error.h"

namespace texsplat::annotation {

ImageAnnotations::ImageAnnotations(const AnnotationRequest& request, sg::Node& root)
    : mRoot(root), mRequest(request) {
    if (request.colorbarTicks < 2 || request.colorbarTicks > LegendStyle::kMaxTicks) {
        throw DataError("colour legend: the tick count must be from 2 to " +
                        std::to_string(LegendStyle::kMaxTicks) + ", got " +
                        std::to_string(request.colorbarTicks));
    }
    if (request.colorbar) {
        mBars = ColorBar::ofScene(root);
    }
}

void ImageAnnotations::setBarTitles(const std::vector<std::string>& titles) {
    if (titles.size() > mBars.size()) {
        throw DataError("given " + std::to_string(titles.size()) + " times, but the scene has " +
                        std::to_string(mBars.size()) + " colour bar" +
                        (mBars.size() == 1 ? "" : "s"));
    }
    for (std::size_t i = 0; i < titles.size(); ++i) {
        mBars[i].title = titles[i];
    }
}

image::Image ImageAnnotations::annotated(const image::Image& picture) const {
    image::Image figure = picture;
    if (mRequest.outline) {
        const VolumeOutline outline =
            VolumeOutline::ofScene(mRoot, picture.width(), picture.height(), *mRequest.outline);
        if (mRequest.layered) {
            // The background with the edges behind the volume, under the rendered layer ("over"
            // on premultiplied colour), then the edges in front over it.
            image::Image under(picture.width(), picture.height());
            under.fill(mRequest.background);
            outline.draw(under, VolumeOutline::Edges::Behind);
            for (std::size_t i = 0; i < figure.pixelCount(); ++i) {
                const glm::vec4& layer = picture.pixels()[i];
                figure.data()[i] = layer + (1.0f - layer.a) * under.pixels()[i];
            }
            outline.draw(figure, VolumeOutline::Edges::InFront);
        } else {
            outline.draw(figure);
        }
    }
    if (!mBars.empty()) {
        const ColorLegend legend(mBars, {mRequest.colorbarPosition, mRequest.colorbarTicks},
                                 picture.width(), picture.height());
        figure = legend.compose(figure, mRequest.background);
    }
    return figure;
}

void ImageAnnotations::write(const image::Image& picture, const std::string& path) const {
    if (mBars.empty() && !mRequest.outline) {
        image::writeImage(picture, path);
        return;
    }
    image::writeImage(annotated(picture), path);
}

} // namespace texsplat::annotation
