#include "nodes/annotation/ImageAnnotations.h"

#include "nodes/annotation/VolumeOutline.h"
#include "nodes/image/ImageIo.h"

namespace texsplat::annotation {

ImageAnnotations::ImageAnnotations(const AnnotationRequest& request, sg::Node& root)
    : mRoot(root), mOutlineColor(request.outline) {
    if (request.colorbar) {
        mLegend = ColorLegend::ofScene(root, *request.colorbar);
    }
}

image::Image ImageAnnotations::annotated(const image::Image& image) const {
    image::Image result = image;
    if (mOutlineColor) {
        VolumeOutline::ofScene(mRoot, image.width(), image.height(), *mOutlineColor)
            .draw(result);
    }
    if (mLegend) {
        mLegend->draw(result);
    }
    return result;
}

void ImageAnnotations::write(const image::Image& image, const std::string& path) const {
    if (!mLegend && !mOutlineColor) {
        image::writeImage(image, path);
        return;
    }
    image::writeImage(annotated(image), path);
}

} // namespace texsplat::annotation
