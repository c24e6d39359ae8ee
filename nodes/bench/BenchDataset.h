#pragma once

#include "nodes/render/SceneFraming.h"
#include "scenegraph/Separator.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief A procedural volume the benchmark renders, named `<source><resolution>`: `ml41`
/// (Marschner–Lobb 41³), `ml128`, `tornado128` (the tornado's speed), `blob256` (a sum of
/// Gaussians), or any other resolution from 2 to 1024 (`ml8` for a quick test).
///
/// Each source comes with the transfer function of its example scene (examples/*.iv) and a
/// viewing direction; the scene a method draws is made by scene().
class BenchDataset {
public:
    /// @brief The data sources.
    enum class Source { MarschnerLobb, Tornado, Blob };

    /// @brief The dataset called `name`.
    /// @throws DataError "unknown dataset 'x' (expected ml<N>, tornado<N> or blob<N> with N from
    /// 2 to 1024, e.g. ml41, ml128, tornado128, blob256)".
    static BenchDataset fromName(const std::string& name);

    /// @brief Datasets from a comma-separated list of names ("ml41,tornado128").
    /// @throws DataError as fromName(), or "empty dataset list" for an empty list.
    static std::vector<BenchDataset> parseList(const std::string& names);

    /// @brief The name it was made from, canonical (`ml41`).
    std::string name() const;

    /// @brief A longer description ("Marschner-Lobb 41^3").
    std::string description() const;

    /// @brief The source.
    Source source() const { return mSource; }

    /// @brief Samples per axis.
    int resolution() const { return mResolution; }

    /// @brief The direction the camera looks along (root space).
    glm::vec3 viewDirection() const;

    /// @brief A scene of a camera of kind `camera` framing the volume for an image of `aspect`
    /// (width / height), the dataset's TransferFunction and VolumeData, then `splatNode`:
    /// the separator holds them in that order.
    sg::Separator::Ptr scene(const sg::Node::Ptr& splatNode, float aspect,
                             render::FramingCamera camera = render::FramingCamera::Perspective) const;

private:
    BenchDataset(Source source, int resolution) : mSource(source), mResolution(resolution) {}

    Source mSource;
    int mResolution;
};

} // namespace texsplat::bench
