#include "nodes/kernel/VectorSplatTable.h"

#include "nodes/image/GrayPfm.h"
#include "nodes/kernel/detail/BilinearSample.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"
#include "scenegraph/Random.h"
#include "scenegraph/FileExtension.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

namespace texsplat::kernel {

namespace {

constexpr int kMinResolution = 8;
constexpr int kMaxResolution = 1024;
constexpr float kMaxMarkDensity = 64.0f;
constexpr float kMinWindowScale = 1.0f;
constexpr float kMaxWindowScale = 4.0f;

struct Mark {
    double x;          ///< centre in the mark domain, in [−E, E) (periodic with period 2E)
    double y;          ///< centre, in [−E, E)
    double brightness; ///< peak intensity
};

// The half-sizes of one channel's mark shape.
struct MarkShape {
    double halfLength; ///< particle: the radius; scratch: half the length along x
    double endSoftness;
    double halfWidth; ///< scratch only: half the width along y
    double sideSoftness;

    double reachX() const { return halfLength + endSoftness; }
    double reachY(MarkType type) const {
        return type == MarkType::Particles ? reachX() : halfWidth + sideSoftness;
    }
};

// 1 up to halfSize − softness, a cubic smoothstep down to 0 at halfSize + softness.
double softEdge(double distance, double halfSize, double softness) {
    const double t = std::clamp((distance - (halfSize - softness)) / (2.0 * softness), 0.0, 1.0);
    return 1.0 - t * t * (3.0 - 2.0 * t);
}

MarkShape intensityShape(MarkType type) {
    using Table = VectorSplatTable;
    if (type == MarkType::Particles)
        return {Table::kParticleRadius, Table::kParticleSoftness, 0.0, 0.0};
    return {Table::kScratchHalfLength, Table::kScratchEndSoftness, Table::kScratchHalfWidth,
            Table::kScratchSideSoftness};
}

MarkShape opacityShape(MarkType type) {
    MarkShape shape = intensityShape(type);
    shape.halfLength += VectorSplatTable::kOpacityMargin;
    if (type == MarkType::Scratches)
        shape.halfWidth += VectorSplatTable::kOpacityMargin;
    return shape;
}

// A mark's profile at (dx, dy) from its centre, in the mark domain's voxels.
double profile(MarkType type, const MarkShape& shape, double dx, double dy) {
    if (type == MarkType::Particles)
        return softEdge(std::sqrt(dx * dx + dy * dy), shape.halfLength, shape.endSoftness);
    return softEdge(std::fabs(dx), shape.halfLength, shape.endSoftness) *
           softEdge(std::fabs(dy), shape.halfWidth, shape.sideSoftness);
}

std::vector<Mark> makeMarks(const VectorTableParameters& parameters, double extent) {
    const double period = 2.0 * extent;
    const auto count = std::max<long long>(
        1, std::llround(static_cast<double>(parameters.markDensity) * period * period));
    sg::Random random(parameters.seed);
    std::vector<Mark> marks(static_cast<std::size_t>(count));
    for (Mark& mark : marks) {
        mark.x = -extent + period * random.uniform();
        mark.y = -extent + period * random.uniform();
        mark.brightness = VectorSplatTable::kMinBrightness +
                          (1.0 - VectorSplatTable::kMinBrightness) * random.uniform();
    }
    return marks;
}

// Samples per texel along y; along x it is this times round(1 / L).
int supersampling(int resolution) { return std::clamp(256 / resolution, 1, 4); }

std::string text(float value) {
    std::ostringstream stream;
    stream << value;
    return stream.str();
}

void checkRange(const char* name, int value, int low, int high) {
    if (value < low || value > high) {
        std::ostringstream message;
        message << "vector table: " << name << " must be in " << low << ".." << high << ", got "
                << value;
        throw DataError(message.str());
    }
}

void checkReal(const char* name, float value, bool valid, const char* range) {
    if (!(std::isfinite(value) && valid))
        throw DataError(std::string("vector table: ") + name + " must be finite and in " + range +
                        ", got " + text(value));
}

struct ParametersLess {
    static auto key(const VectorTableParameters& p) {
        return std::tie(p.rows, p.columns, p.resolution, p.markType, p.markDensity,
                        p.splatExtent, p.windowScale, p.seed);
    }
    bool operator()(const VectorTableParameters& a, const VectorTableParameters& b) const {
        return key(a) < key(b);
    }
};

struct Registry {
    std::mutex mutex;
    std::map<VectorTableParameters, std::weak_ptr<const VectorSplatTable>, ParametersLess> tables;
};

Registry& registry() {
    static Registry instance;
    return instance;
}

// The intensity and opacity shapes of one mark type, and how far either reaches.
struct MarkShapes {
    MarkType type;
    MarkShape intensity;
    MarkShape opacity;

    double reachX() const { return std::max(intensity.reachX(), opacity.reachX()); }
    double reachY() const { return std::max(intensity.reachY(type), opacity.reachY(type)); }
};

// The samples of one row of texels (samplesY rows of n · samplesX samples), where the marks are
// summed before they are clamped, windowed and averaged into texels.
class TexelBand {
public:
    TexelBand(int resolution, double extent, int samplesX, int samplesY)
        : mResolution(resolution), mExtent(extent), mTexelSize(2.0 * extent / resolution),
          mSamplesX(samplesX), mSamplesY(samplesY), mWidth(resolution * samplesX),
          mIntensity(static_cast<std::size_t>(mWidth) * samplesY),
          mOpacity(mIntensity.size()) {}

    /// Starts texel row j.
    void clear(int j) {
        mRow = j;
        std::fill(mIntensity.begin(), mIntensity.end(), 0.0);
        std::fill(mOpacity.begin(), mOpacity.end(), 0.0);
    }

    /// Adds a mark centred at x = centre in the texture, compressed along x by `length`.
    void add(const MarkShapes& shapes, const Mark& mark, double centre, double length) {
        const double reach = length * shapes.reachX();
        const double sample = mTexelSize / mSamplesX;
        const int first = static_cast<int>(
            std::max(0.0, std::ceil((centre - reach + mExtent) / sample - 0.5)));
        const int last = static_cast<int>(
            std::min(mWidth - 1.0, std::floor((centre + reach + mExtent) / sample - 0.5)));
        for (int b = 0; b < mSamplesY; ++b) {
            const double dy = sampleY(b) - mark.y;
            if (std::fabs(dy) >= shapes.reachY())
                continue;
            double* intensity = &mIntensity[static_cast<std::size_t>(b) * mWidth];
            double* opacity = &mOpacity[static_cast<std::size_t>(b) * mWidth];
            for (int a = first; a <= last; ++a) {
                const double dx = (-mExtent + (a + 0.5) * sample - centre) / length;
                intensity[a] += mark.brightness * profile(shapes.type, shapes.intensity, dx, dy);
                opacity[a] += profile(shapes.type, shapes.opacity, dx, dy);
            }
        }
    }

    /// Clamps the summed marks to 1, multiplies by the window W and averages each texel's
    /// samples into (intensity, opacity) pairs at `texels`.
    void resolve(float* texels) const {
        const double sample = mTexelSize / mSamplesX;
        const double weight = 1.0 / (static_cast<double>(mSamplesX) * mSamplesY);
        for (int i = 0; i < mResolution; ++i) {
            double intensity = 0.0;
            double opacity = 0.0;
            for (int b = 0; b < mSamplesY; ++b) {
                const double y = sampleY(b);
                for (int a = i * mSamplesX; a < (i + 1) * mSamplesX; ++a) {
                    const double x = -mExtent + (a + 0.5) * sample;
                    const double r2 = (x * x + y * y) / (mExtent * mExtent);
                    if (r2 >= 1.0)
                        continue;
                    const double window = (1.0 - r2) * (1.0 - r2);
                    const std::size_t at = static_cast<std::size_t>(b) * mWidth + a;
                    intensity += std::min(mIntensity[at], 1.0) * window;
                    opacity += std::min(mOpacity[at], 1.0) * window;
                }
            }
            texels[2 * i] = static_cast<float>(intensity * weight);
            texels[2 * i + 1] = static_cast<float>(opacity * weight);
        }
    }

private:
    double sampleY(int b) const { return -mExtent + (mRow + (b + 0.5) / mSamplesY) * mTexelSize; }

    int mResolution;
    double mExtent;
    double mTexelSize;
    int mSamplesX;
    int mSamplesY;
    int mWidth;
    int mRow = 0;
    std::vector<double> mIntensity;
    std::vector<double> mOpacity;
};

} // namespace

// Constant-initialized, so it is usable from any static initializer or destructor.
std::atomic<std::uint64_t> VectorSplatTable::sLiveTables{0};

bool VectorTableParameters::operator==(const VectorTableParameters& other) const {
    return ParametersLess::key(*this) == ParametersLess::key(other);
}

void VectorSplatTable::checkParameters(const VectorTableParameters& parameters) {
    const VectorTableParameters& p = parameters;
    checkRange("rows", p.rows, 1, VectorSplatTable::kMaxRows);
    checkRange("columns", p.columns, 1, VectorSplatTable::kMaxColumns);
    checkRange("resolution", p.resolution, kMinResolution, kMaxResolution);
    if (p.markType != MarkType::Particles && p.markType != MarkType::Scratches)
        throw DataError("vector table: markType must be Particles or Scratches, got " +
                        std::to_string(static_cast<int>(p.markType)));
    checkReal("markDensity", p.markDensity,
              p.markDensity > 0.0f && p.markDensity <= kMaxMarkDensity, "(0, 64]");
    checkReal("splatExtent", p.splatExtent,
              p.splatExtent > 0.0f && p.splatExtent <= VectorSplatTable::kMaxSplatExtent,
              "(0, 8]");
    checkReal("windowScale", p.windowScale,
              p.windowScale >= kMinWindowScale && p.windowScale <= kMaxWindowScale, "[1, 4]");
    const std::uint64_t texels = static_cast<std::uint64_t>(p.rows) *
                                 static_cast<std::uint64_t>(p.columns) *
                                 static_cast<std::uint64_t>(p.resolution) *
                                 static_cast<std::uint64_t>(p.resolution);
    if (texels > kMaxTexels)
        throw DataError("vector table: rows * columns * resolution^2 must be at most " +
                        std::to_string(kMaxTexels) + " texels, got " + std::to_string(texels));
}

std::shared_ptr<const VectorSplatTable>
VectorSplatTable::shared(const VectorTableParameters& parameters) {
    checkParameters(parameters);
    Registry& tables = registry();
    {
        const std::lock_guard<std::mutex> lock(tables.mutex);
        const auto found = tables.tables.find(parameters);
        if (found != tables.tables.end())
            if (auto table = found->second.lock())
                return table;
    }
    // Generated outside the lock, so that tables of other parameters are not held up.
    auto table = std::make_shared<const VectorSplatTable>(parameters);
    const std::lock_guard<std::mutex> lock(tables.mutex);
    for (auto it = tables.tables.begin(); it != tables.tables.end();)
        it = it->second.expired() ? tables.tables.erase(it) : std::next(it);
    auto [slot, inserted] = tables.tables.emplace(parameters, table);
    if (!inserted) {
        if (auto first = slot->second.lock())
            return first; // another thread stored one while this one was generated
        slot->second = table;
    }
    return table;
}

VectorSplatTable::VectorSplatTable(const VectorTableParameters& parameters)
    : mParameters(parameters) {
    checkParameters(parameters);
    mExtent = parameters.windowScale * parameters.splatExtent;
    generate();
    sLiveTables.fetch_add(1, std::memory_order_relaxed);
}

VectorSplatTable::VectorSplatTable(const VectorSplatTable& other)
    : mParameters(other.mParameters), mExtent(other.mExtent), mTexels(other.mTexels) {
    sLiveTables.fetch_add(1, std::memory_order_relaxed);
}

VectorSplatTable::~VectorSplatTable() { sLiveTables.fetch_sub(1, std::memory_order_relaxed); }

std::uint64_t VectorSplatTable::liveTables() { return sLiveTables.load(); }

std::size_t VectorSplatTable::memoryBytes() const {
    return sizeof(*this) + mTexels.capacity() * sizeof(float);
}

void VectorSplatTable::generate() {
    const int n = resolution();
    const MarkType type = mParameters.markType;
    const double extent = mExtent;
    const double period = 2.0 * extent;
    const double texelSize = period / n;
    const std::vector<Mark> marks = makeMarks(mParameters, extent);
    const MarkShapes shapes{type, intensityShape(type), opacityShape(type)};

    // The marks that reach into each texel row: the same for every layer, since rows and
    // columns move and compress the marks along x only.
    std::vector<std::vector<const Mark*>> marksOfRow(static_cast<std::size_t>(n));
    for (const Mark& mark : marks) {
        const auto toRow = [&](double y) { return std::floor((y + extent) / texelSize); };
        const int first = static_cast<int>(std::max(0.0, toRow(mark.y - shapes.reachY())));
        const int last = static_cast<int>(std::min(n - 1.0, toRow(mark.y + shapes.reachY())));
        for (int row = first; row <= last; ++row)
            marksOfRow[static_cast<std::size_t>(row)].push_back(&mark);
    }

    const std::size_t layerSize = static_cast<std::size_t>(n) * n * 2;
    mTexels.assign(layerSize * static_cast<std::size_t>(rows()) * columns(), 0.0f);
    for (int column = 0; column < columns(); ++column) {
        const double length = projectedLength(column, columns());
        const int samplesY = supersampling(n);
        const int samplesX = samplesY * std::max(1, static_cast<int>(std::lround(1.0 / length)));
        TexelBand band(n, extent, samplesX, samplesY);
        for (int row = 0; row < rows(); ++row) {
            // Row k: the marks propagated forward by k/rows of the period (paper, "Inventor /
            // Explorer": "each map has the vectors propagated forward (and cyclically)").
            const double shift = row * period / rows();
            float* layerTexels =
                &mTexels[static_cast<std::size_t>(layer(row, column)) * layerSize];
            for (int j = 0; j < n; ++j) {
                band.clear(j);
                for (const Mark* mark : marksOfRow[static_cast<std::size_t>(j)]) {
                    // Every periodic copy of the mark that reaches into [−E, E] once compressed:
                    // the mark domain spans [−E/L, E/L] there.
                    const double low = -extent / length - shapes.reachX() - mark->x - shift;
                    const double high = extent / length + shapes.reachX() - mark->x - shift;
                    const auto firstCopy = static_cast<long long>(std::ceil(low / period));
                    const auto lastCopy = static_cast<long long>(std::floor(high / period));
                    for (long long copy = firstCopy; copy <= lastCopy; ++copy)
                        band.add(shapes, *mark,
                                 length * (mark->x + shift + static_cast<double>(copy) * period),
                                 length);
                }
                band.resolve(layerTexels + static_cast<std::size_t>(j) * n * 2);
            }
        }
    }
}

glm::vec2 VectorSplatTable::texel(int row, int column, int i, int j) const {
    const int n = resolution();
    TEXSPLAT_ASSERT(row >= 0 && row < rows() && column >= 0 && column < columns() && i >= 0 &&
                        i < n && j >= 0 && j < n,
                    "VectorSplatTable::texel(): index out of range");
    const std::size_t at =
        ((static_cast<std::size_t>(layer(row, column)) * n + static_cast<std::size_t>(j)) * n +
         static_cast<std::size_t>(i)) *
        2;
    return {mTexels[at], mTexels[at + 1]};
}

glm::vec2 VectorSplatTable::sample(int row, int column, float x, float y) const {
    return detail::bilinearSample(x, y, mExtent, resolution(),
                                  [&](int i, int j) { return texel(row, column, i, j); });
}

int VectorSplatTable::columnOf(float towardEye, int columns) {
    if (columns <= 1 || std::isnan(towardEye))
        return 0;
    const float clamped = std::clamp(towardEye, 0.0f, 1.0f);
    return static_cast<int>(std::lround(clamped * static_cast<float>(columns - 1)));
}

float VectorSplatTable::projectedLength(int column, int columns) {
    if (columns <= 1)
        return 1.0f;
    const float z =
        static_cast<float>(std::clamp(column, 0, columns - 1)) / static_cast<float>(columns - 1);
    return std::max(std::sqrt(1.0f - z * z), kMinProjectedLength);
}

void VectorSplatTable::checkImagePath(const std::string& path) {
    requireFileExtension(path, {".png", ".pfm", ".exr"}, "image");
    if (fileExtension(path) != ".pfm")
        image::supportedImageFormatOf(path);
}

void VectorSplatTable::writeImage(const std::string& path) const {
    checkImagePath(path);
    const int n = resolution();
    const int tableWidth = columns() * (n + 1) + 1;
    const int width = 2 * tableWidth + kImageGap;
    const int height = rows() * (n + 1) + 1;
    // Rows bottom to top, as PFM stores them: row 0 of the table at the bottom.
    std::vector<float> gray(static_cast<std::size_t>(width) * height, 0.0f);
    for (int channel = 0; channel < 2; ++channel) {
        const int left = channel * (tableWidth + kImageGap);
        for (int y = 0; y < height; ++y)
            std::fill_n(gray.begin() + static_cast<std::ptrdiff_t>(y) * width + left, tableWidth,
                        kSeparatorValue);
        for (int row = 0; row < rows(); ++row)
            for (int column = 0; column < columns(); ++column)
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        const int x = left + 1 + column * (n + 1) + i;
                        const int y = 1 + row * (n + 1) + j;
                        gray[static_cast<std::size_t>(y) * width + x] =
                            texel(row, column, i, j)[channel];
                    }
    }
    if (fileExtension(path) == ".pfm") {
        image::writeGrayPfm(path, width, height, gray);
        return;
    }
    image::Image picture(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float value = gray[static_cast<std::size_t>(y) * width + x];
            picture.setPixel(x, height - 1 - y, glm::vec4(value, value, value, 1.0f));
        }
    image::writeImage(picture, path);
}

} // namespace texsplat::kernel
