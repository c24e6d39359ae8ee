#pragma once

#include <glm/vec2.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace texsplat::kernel {

/// @brief The kind of small mark a vector splat table draws along x (Crawfis & Max 1993,
/// "Combined Vector and Scalar Textures": "tiny vector particles, or scratch marks").
enum class MarkType {
    Particles, ///< small round dots
    Scratches, ///< short streaks along x with soft ends
};

/// @brief What a VectorSplatTable is made from; equal parameters give the same table bit for bit.
struct VectorTableParameters {
    int rows = 16;             ///< animation phases, 1..256 (the paper's sixteen)
    int columns = 8;           ///< foreshortening levels, 1..64
    int resolution = 64;       ///< texels per side of each texture, 8..1024
    MarkType markType = MarkType::Particles;
    float markDensity = 1.0f;  ///< marks per square voxel of the periodic mark domain, (0, 64]
    float splatExtent = 1.6f;  ///< half-width in voxels of the scalar splat's quad, (0, 8]
    float windowScale = 1.15f; ///< the window's (and table quad's) half-width / splatExtent, [1, 4]
    std::uint32_t seed = 1;    ///< the marks are reproducible from it

    /// @brief Whether every member is equal (floats compared exactly).
    bool operator==(const VectorTableParameters& other) const;
    /// @brief Whether some member differs.
    bool operator!=(const VectorTableParameters& other) const { return !(*this == other); }
};

/// @brief The vector splat table of Crawfis & Max (1993), figure 3: rows × columns small
/// two-channel textures (intensity, opacity) of marks drawn along +x, windowed radially, which the
/// vector and combined splats rotate onto each splat's projected direction. GL-free; the GL
/// renderer uploads texels() as it is and a CPU backend uses sample().
///
/// How it is made (the reference; docs/kernel.md, "The vector splat table (figure 3)"):
/// - Marks lie in a domain periodic in x with period P = 2E (E = extent(); P is the square's
///   width) spanning y ∈ [−E, E]: max(1, round(markDensity · P²)) of them, at positions and with
///   brightnesses from a splitmix64 generator seeded with `seed` (integer arithmetic, so the marks
///   are the same on any machine; the texels are computed in double precision and are the same
///   bit for bit wherever the compiler does not fuse multiply-adds, as on x86-64).
/// - pattern(x, y) is the sum of the marks' profiles (x distances taken modulo P, so marks
///   across the seam are whole), clamped to [0, 1]: intensity from the bright core, opacity from
///   the same marks widened by kOpacityMargin.
/// - Layer (row k, column c): value(x, y) = pattern(wrap(x / L − k·P/rows), y) · W(x, y) with
///   L = projectedLength(c, columns): row k is row 0 propagated forward (+x) by k/rows of the
///   period, cyclically ("each map has the vectors propagated forward (and cyclically) in the map
///   before being windowed"), column c compresses the marks along x by L (the foreshortening of
///   a vector with |v_z| = c / (columns − 1)), and the window W is neither shifted nor
///   compressed.
/// - W(r) = (1 − (r/E)²)² for r = |(x, y)| < E and 0 beyond: 1 at the centre, falling smoothly
///   (zero value and slope) to 0 at E, "slightly larger extent than the scalar splat" since
///   E = windowScale · splatExtent.
/// - Each texel is the mean of an S × (S·n) grid of samples, value(x, y) above at each, with
///   S = clamp(⌊256 / N⌋, 1, 4) (4 at 64², 2 at 128², 1 from 129² on) and n = max(1,
///   round(1 / L)) more samples along x where the marks are compressed, so that marks thinner
///   than a texel are averaged, not aliased.
///
/// rows × columns layers can exceed what a GL texture array holds (GL_MAX_ARRAY_TEXTURE_LAYERS is
/// 2048 on llvmpipe, 256 at least): the renderer checks its own limit.
class VectorSplatTable {
public:
    /// @brief The shortest projected mark length, for vectors along the view axis: a mark never
    /// collapses to a line.
    static constexpr float kMinProjectedLength = 0.1f;
    /// @brief The most rows (animation phases) a table may have.
    static constexpr int kMaxRows = 256;
    /// @brief The most columns (foreshortening levels) a table may have.
    static constexpr int kMaxColumns = 64;
    /// @brief The largest splatExtent (the scalar splat's half-width in voxels).
    static constexpr float kMaxSplatExtent = 8.0f;

    /// @brief The most texels a table may hold, rows × columns × resolution² (1 GiB of two
    /// floats per texel).
    static constexpr std::uint64_t kMaxTexels = std::uint64_t{1} << 27;

    /// @brief Particles: the radius where the dot falls to half its brightness, in voxels of the
    /// mark domain (3.5 texels across at the default 64² over ±1.84), ...
    static constexpr double kParticleRadius = 0.1;
    /// @brief ... and the half-width of its soft edge: the profile falls from 1 at
    /// kParticleRadius − kParticleSoftness to 0 at kParticleRadius + kParticleSoftness (a cubic
    /// smoothstep in the distance from the centre).
    static constexpr double kParticleSoftness = 0.04;
    /// @brief Scratches: half the length along x at half brightness (a streak 0.5 voxels long), ...
    static constexpr double kScratchHalfLength = 0.25;
    /// @brief ... the half-width of the soft ends (a smoothstep in |dx| over 0.25 ± 0.12), ...
    static constexpr double kScratchEndSoftness = 0.12;
    /// @brief ... half the width across at half brightness (a streak 0.08 voxels wide), ...
    static constexpr double kScratchHalfWidth = 0.04;
    /// @brief ... and the half-width of the soft sides (a smoothstep in |dy| over 0.04 ± 0.03).
    /// A scratch's profile is the product of its length and width profiles.
    static constexpr double kScratchSideSoftness = 0.03;
    /// @brief The opacity channel's marks are the intensity's with each half-size (radius,
    /// half-length, half-width) larger by this many voxels, so a mark is opaque slightly beyond
    /// its bright core (a particle's coverage reaches half at 0.14 voxels).
    static constexpr double kOpacityMargin = 0.04;
    /// @brief Each mark's brightness (the peak of its intensity) is uniform in
    /// [kMinBrightness, 1]; its opacity peaks at 1.
    static constexpr double kMinBrightness = 0.75;

    /// @brief Throws DataError naming the first parameter out of its range, e.g.
    /// "vector table: rows must be in 1..256, got 0", "vector table: markDensity must be finite
    /// and in (0, 64], got nan", and "vector table: rows * columns * resolution^2 must be at most
    /// 134217728 texels, got 268435456" for a table above kMaxTexels.
    static void checkParameters(const VectorTableParameters& parameters);

    /// @brief The table for `parameters`, generated on the first request and shared by every
    /// caller while one holds it: one table per distinct parameter set alive at a time (a
    /// mutex-guarded map of weak_ptrs; two threads asking for a new set at once may both generate
    /// it, and both get the first one stored). Thread-safe. Throws as checkParameters.
    static std::shared_ptr<const VectorSplatTable> shared(const VectorTableParameters& parameters);

    /// @brief Generates the table now (checkParameters first).
    explicit VectorSplatTable(const VectorTableParameters& parameters);
    /// @brief A copy (counted by liveTables()).
    VectorSplatTable(const VectorSplatTable& other);
    /// @brief Copies another table's parameters and texels.
    VectorSplatTable& operator=(const VectorSplatTable& other) = default;
    /// @brief Frees the texels; liveTables() counts one fewer.
    ~VectorSplatTable();

    /// @brief What the table was made from.
    const VectorTableParameters& parameters() const { return mParameters; }
    /// @brief Animation phases.
    int rows() const { return mParameters.rows; }
    /// @brief Foreshortening levels.
    int columns() const { return mParameters.columns; }
    /// @brief Texels per side of each texture.
    int resolution() const { return mParameters.resolution; }

    /// @brief The half-width E of each texture's square in voxels at splat size 1:
    /// windowScale · splatExtent (1.84 by default).
    float extent() const { return mExtent; }

    /// @brief The layer of the texture array that holds (row, column): row · columns + column.
    int layer(int row, int column) const { return row * columns() + column; }

    /// @brief All layers in layer() order; each layer resolution² texels, row-major, row 0 at
    /// y = −E, texel (i, j) (column i, row j) centred at (−E + (i + ½)·2E/N, −E + (j + ½)·2E/N)
    /// (as FootprintTexture); 2 floats per texel: (intensity, opacity), each in [0, 1]. The GL
    /// renderer uploads them as an RG8 texture array of rows · columns layers (8 bits hold them
    /// to 0.002 and llvmpipe samples them faster than floats).
    const std::vector<float>& texels() const { return mTexels; }

    /// @brief (intensity, opacity) of texel (i, j) of layer(row, column): i counts along x, j
    /// along y (texels()[2 · ((layer · N + j) · N + i)]).
    glm::vec2 texel(int row, int column, int i, int j) const;

    /// @brief The bilinear lookup at (x, y) voxels from the splat centre with the GL_LINEAR +
    /// GL_CLAMP_TO_EDGE rules, (0, 0) outside the square [−E, E]² (and for NaN): what the GL
    /// shader and a CPU backend see.
    glm::vec2 sample(int row, int column, float x, float y) const;

    /// @brief The column for a vector whose unit view-space direction has |v_z| = towardEye (0: in
    /// the image plane, 1: pointing at the eye): round(towardEye · (columns − 1)), towardEye
    /// clamped to [0, 1]; NaN gives 0; columns ≤ 1 gives 0.
    static int columnOf(float towardEye, int columns);

    /// @brief The projected length of column c's marks: with z = c / (columns − 1),
    /// max(√(1 − z²), kMinProjectedLength); 1 when columns ≤ 1. c is clamped to [0, columns − 1].
    static float projectedLength(int column, int columns);

    /// @brief Number of VectorSplatTable objects alive now (a scene with no vector splat makes
    /// none).
    static std::uint64_t liveTables();

    /// @brief Bytes the table holds (its texels and the object).
    std::size_t memoryBytes() const;

    /// @brief Writes the whole table as one gray image, like the paper's figure 3: the intensity
    /// table (left) and the opacity table (right), kImageGap black texels apart, each with the
    /// columns left to right (column 0, in the image plane, first) and the rows bottom to top
    /// (row 0 at the bottom: "going up the rows" the marks move along +x), every cell framed by
    /// one-texel lines of gray kSeparatorValue (dark, but visible against the cells' black
    /// corners). Each cell shows its texture with y = +E at the top. The whole image is
    /// (2 · (columns · (N + 1) + 1) + kImageGap) × (rows · (N + 1) + 1) pixels. The format is
    /// the extension's (any case):
    /// - `.png`: 8-bit, sRGB-encoded as every texsplat PNG, opaque gray;
    /// - `.pfm`: little-endian grayscale floats ("Pf", rows bottom to top), the values as they are;
    /// - `.exr`: float RGBA, R = G = B = the value, A = 1 (builds with OpenEXR).
    /// Written all at once (scenegraph/AtomicFile.h). Throws IoError, and writes nothing, for
    /// another extension (checkImagePath), for `.exr` in a build without OpenEXR or when the file
    /// cannot be written.
    void writeImage(const std::string& path) const;

    /// @brief Throws IoError("t.tif: unknown image extension '.tif' (supported: .png, .pfm,
    /// .exr)") unless writeImage() can write path's format (and for `.exr` in a build without
    /// OpenEXR): lets a command refuse a path before any work.
    static void checkImagePath(const std::string& path);

    /// @brief Black texels between the intensity and opacity tables in writeImage().
    static constexpr int kImageGap = 4;
    /// @brief The gray of the lines between the cells in writeImage().
    static constexpr float kSeparatorValue = 0.05f;

private:
    void generate();

    static std::atomic<std::uint64_t> sLiveTables;

    VectorTableParameters mParameters;
    float mExtent = 0.0f;
    std::vector<float> mTexels;
};

} // namespace texsplat::kernel
