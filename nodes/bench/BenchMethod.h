#pragma once

#include "scenegraph/Node.h"

#include <string>
#include <vector>

namespace texsplat::bench {

/// @brief One way of drawing a dataset that `texsplat bench` times: a splat node type, its
/// kernel, and the octree splat budget (the paper's texture splat at full resolution is the
/// "full-quality" image every other method is also compared against).
struct BenchMethod {
    /// @brief The drawing methods.
    enum class Kind {
        TexturePaper,    ///< TextureSplat, the paper's kernel (Crawfis & Max 1993, figure 4b)
        TextureGaussian, ///< TextureSplat with its Gaussian kernel
        PolygonGaussian, ///< GaussianSplat: 3 x 7 Gouraud-shaded polygon (figure 4a)
        Vector,          ///< VectorSplat: marks of the vector table (figure 5), vector data only
        Combined,        ///< CombinedSplat: texture splats with marks (figure 7), vector data only
    };

    Kind kind = Kind::TexturePaper;
    /// Fraction of the full-resolution splat count the octree cut may use (ScalarSplat's
    /// maxSplats); 0: every non-empty voxel (no octree).
    double budget = 0.0;
    /// Whether the volume is shaded (TransferFunction::shade), and lit again every frame as
    /// an orbiting view makes it (the camera turns by a ten-thousandth of a radian between
    /// frames, which moves the headlight and the highlight).
    bool shaded = false;

    /// @brief The method called `name`: `texture`, `texture-gaussian`, `polygon`, `vector`,
    /// `combined`, each optionally followed by `+shade` (shaded; not `vector`: marks are not
    /// shaded) and `@FRACTION` (an octree budget in (0, 1), e.g. `texture+shade@0.1`).
    /// @throws DataError "unknown method 'x' (expected texture, texture-gaussian, polygon,
    /// vector or combined, optionally with +shade and @FRACTION, e.g. texture+shade@0.1)".
    static BenchMethod fromName(const std::string& name);

    /// @brief Methods from a comma-separated list of names.
    /// @throws DataError as fromName(), or "empty method list".
    static std::vector<BenchMethod> parseList(const std::string& names);

    /// @brief The name fromName() reads (`texture+shade@0.1`).
    std::string name() const;

    /// @brief Whether this is the full-quality reference among the methods (texture, paper
    /// kernel, full resolution).
    bool isFullQuality() const { return kind == Kind::TexturePaper && budget == 0.0 && !shaded; }

    /// @brief Whether the method draws a vector field (vector, combined).
    bool needsVectors() const { return kind == Kind::Vector || kind == Kind::Combined; }

    /// @brief A new splat node drawing this way, for a volume whose full-resolution list has
    /// `fullSplats` splats (the budget is a fraction of it; at least 1 splat).
    sg::Node::Ptr makeNode(std::size_t fullSplats) const;
};

} // namespace texsplat::bench
