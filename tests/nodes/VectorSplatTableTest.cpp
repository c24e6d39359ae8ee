#include "nodes/kernel/VectorSplatTable.h"

#include "SceneNodesTestSupport.h"
#include "nodes/image/ImageIo.h"
#include "scenegraph/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using texsplat::kernel::MarkType;
using texsplat::kernel::VectorSplatTable;
using texsplat::kernel::VectorTableParameters;
using texsplat::nodes::test::errorOf;
using texsplat::nodes::test::testPath;

namespace {

VectorTableParameters parameters(int rows, int columns, int resolution, float density = 1.0f,
                                 MarkType type = MarkType::Particles) {
    VectorTableParameters result;
    result.rows = rows;
    result.columns = columns;
    result.resolution = resolution;
    result.markDensity = density;
    result.markType = type;
    return result;
}

// Texel centre coordinate of index i, in voxels from the splat centre.
double centre(const VectorSplatTable& table, int i) {
    return -table.extent() + (i + 0.5) * 2.0 * table.extent() / table.resolution();
}

// The documented window at the centre of texel (i, j).
double window(const VectorSplatTable& table, int i, int j) {
    const double x = centre(table, i);
    const double y = centre(table, j);
    const double r2 = (x * x + y * y) / (double(table.extent()) * table.extent());
    return r2 < 1.0 ? (1.0 - r2) * (1.0 - r2) : 0.0;
}

// The cyclic shift d (in texels along +x) that best maps layer `from`'s un-windowed intensity
// onto layer `to`'s: to(i, j) ≈ from(i − d, j). The pattern is estimated as texel / W where the
// window W is large enough for the estimate to be meaningful.
int bestShift(const VectorSplatTable& table, int fromRow, int toRow, int column) {
    const int n = table.resolution();
    int best = -1;
    double bestError = std::numeric_limits<double>::infinity();
    for (int d = 0; d < n; ++d) {
        double error = 0.0;
        int count = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int source = ((i - d) % n + n) % n;
                const double wTo = window(table, i, j);
                const double wFrom = window(table, source, j);
                if (wTo < 0.3 || wFrom < 0.3)
                    continue;
                const double difference = table.texel(toRow, column, i, j).x / wTo -
                                          table.texel(fromRow, column, source, j).x / wFrom;
                error += difference * difference;
                ++count;
            }
        if (count > 0 && error / count < bestError) {
            bestError = error / count;
            best = d;
        }
    }
    return best;
}

// The gradient energies Σ (∂x I)² and Σ (∂y I)² of one layer's intensity (forward differences):
// the diagonal of its structure tensor. A mark elongated along x has most of its gradient
// across it, along y.
std::pair<double, double> gradientEnergies(const VectorSplatTable& table, int row, int column) {
    const int n = table.resolution();
    double xx = 0.0;
    double yy = 0.0;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const double value = table.texel(row, column, i, j).x;
            const double dx = table.texel(row, column, i + 1, j).x - value;
            const double dy = table.texel(row, column, i, j + 1).x - value;
            xx += dx * dx;
            yy += dy * dy;
        }
    return {xx, yy};
}

std::string readFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

} // namespace

TEST(VectorSplatTable, defaultTableHasFigureThreesShapeAndIsWindowed) {
    const VectorSplatTable table{VectorTableParameters{}};
    EXPECT_EQ(table.rows(), 16);
    EXPECT_EQ(table.columns(), 8);
    EXPECT_EQ(table.resolution(), 64);
    EXPECT_FLOAT_EQ(table.extent(), 1.15f * 1.6f);
    EXPECT_EQ(table.layer(3, 5), 29);
    ASSERT_EQ(table.texels().size(), 16u * 8u * 64u * 64u * 2u);
    EXPECT_GE(table.memoryBytes(), table.texels().size() * sizeof(float));
    float brightest = 0.0f;
    for (float value : table.texels()) {
        ASSERT_GE(value, 0.0f);
        ASSERT_LE(value, 1.0f);
        brightest = std::max(brightest, value);
    }
    EXPECT_GT(brightest, 0.5f);
    // Every texel that lies wholly outside the window's circle is zero in every layer.
    const double half = table.extent() / table.resolution();
    for (int row = 0; row < table.rows(); ++row)
        for (int column = 0; column < table.columns(); ++column)
            for (int j = 0; j < 64; ++j)
                for (int i = 0; i < 64; ++i) {
                    const double nearX = std::max(0.0, std::fabs(centre(table, i)) - half);
                    const double nearY = std::max(0.0, std::fabs(centre(table, j)) - half);
                    if (std::hypot(nearX, nearY) >= table.extent()) {
                        ASSERT_EQ(table.texel(row, column, i, j), glm::vec2(0.0f))
                            << row << " " << column << " " << i << " " << j;
                    }
                }
    EXPECT_EQ(table.texel(0, 0, 0, 0), glm::vec2(0.0f));
    EXPECT_EQ(table.texel(15, 7, 63, 63), glm::vec2(0.0f));
}

TEST(VectorSplatTable, windowIsTheDocumentedFalloffInEveryLayer) {
    // Dense scratches cover nearly every sample, so the opacity shows the window itself:
    // (1 − (r/E)²)², neither shifted by the rows nor compressed by the columns (column 2 of 3
    // has the marks compressed to a tenth).
    const VectorSplatTable table(parameters(2, 3, 32, 64.0f, MarkType::Scratches));
    double squares = 0.0;
    double worst = 0.0;
    int count = 0;
    for (int row = 0; row < 2; ++row)
        for (int column = 0; column < 3; ++column)
            for (int j = 0; j < 32; ++j)
                for (int i = 0; i < 32; ++i) {
                    const double error = table.texel(row, column, i, j).y - window(table, i, j);
                    squares += error * error;
                    worst = std::max(worst, std::fabs(error));
                    ++count;
                }
    // A smoothstep window, 1 − 3q² + 2q³ with q = r/E, would be 0.035 r.m.s. away.
    EXPECT_LT(std::sqrt(squares / count), 0.01);
    EXPECT_LT(worst, 0.25); // a few samples fall between the marks
}

TEST(VectorSplatTable, opacityIsTheSameMarksWider) {
    for (MarkType type : {MarkType::Particles, MarkType::Scratches}) {
        const VectorSplatTable table(parameters(2, 3, 64, 2.0f, type));
        double intensity = 0.0;
        double opacity = 0.0;
        for (size_t at = 0; at < table.texels().size(); at += 2) {
            ASSERT_GE(table.texels()[at + 1], table.texels()[at]) << at;
            intensity += table.texels()[at];
            opacity += table.texels()[at + 1];
        }
        EXPECT_GT(intensity, 0.0);
        EXPECT_GT(opacity, 1.3 * intensity);
    }
}

TEST(VectorSplatTable, sameSeedGivesIdenticalTexelsAndAnotherSeedDoesNot) {
    VectorTableParameters first = parameters(4, 3, 32);
    first.seed = 7;
    const VectorSplatTable a(first);
    const VectorSplatTable b(first);
    EXPECT_EQ(a.texels(), b.texels());
    VectorTableParameters second = first;
    second.seed = 8;
    const VectorSplatTable c(second);
    EXPECT_NE(a.texels(), c.texels());
    second.markType = MarkType::Scratches;
    second.seed = 7;
    EXPECT_NE(a.texels(), VectorSplatTable(second).texels());
}

TEST(VectorSplatTable, rowsPropagateTheMarksForwardByAFractionOfThePeriod) {
    // 64 texels span one period, so each of 16 rows moves the marks 4 texels along +x.
    const VectorSplatTable table(parameters(16, 1, 64, 4.0f));
    EXPECT_EQ(bestShift(table, 0, 0, 0), 0);
    EXPECT_EQ(bestShift(table, 0, 1, 0), 4);
    EXPECT_EQ(bestShift(table, 0, 5, 0), 20);
    EXPECT_EQ(bestShift(table, 0, 15, 0), 60);
    EXPECT_EQ(bestShift(table, 3, 11, 0), 32);
    // The rows are not merely different: the window stays where it is while the marks move.
    EXPECT_NE(table.texel(0, 0, 10, 32), table.texel(1, 0, 10, 32));
}

TEST(VectorSplatTable, rowsCycleOneStepFromTheLastRowBackToRowZero) {
    for (int rows : {16, 8, 5}) {
        const VectorSplatTable table(parameters(rows, 1, 80, 4.0f));
        // Row rows − 1 moved forward by one more row (80 / rows texels) is row 0: the phase
        // wraps after a whole period, so an animation that steps the row cyclically is seamless.
        EXPECT_EQ(bestShift(table, rows - 1, 0, 0), 80 / rows) << rows;
        EXPECT_EQ(bestShift(table, 0, rows - 1, 0), 80 - 80 / rows) << rows;
    }
}

TEST(VectorSplatTable, columnsCompressTheMarksAlongXButNotTheWindow) {
    const int columns = 4; // projected lengths 1, 0.943, 0.745, 0.1
    const VectorSplatTable table(parameters(1, columns, 128, 2.0f));
    const int n = table.resolution();
    double previous = std::numeric_limits<double>::infinity();
    double first = 0.0;
    for (int column = 0; column < columns; ++column) {
        // The marks' length along x relative to their width along y.
        const auto [xx, yy] = gradientEnergies(table, 0, column);
        const double aspect = std::sqrt(yy / xx);
        if (column == 0)
            first = aspect;
        EXPECT_LT(aspect, previous) << column;
        previous = aspect;
        if (column < columns - 1) { // above the last column the texels resolve the marks
            EXPECT_NEAR(aspect / first, VectorSplatTable::projectedLength(column, columns), 0.05)
                << column;
        }
        // The window is not compressed: the marks reach out to near the circle along x in every
        // column, and nothing lies beyond it.
        double reach = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (table.texel(0, column, i, j).y > 1e-3f)
                    reach = std::max(reach, std::fabs(centre(table, i)));
        EXPECT_GT(reach, 0.8 * table.extent()) << column;
        EXPECT_LT(reach, table.extent()) << column;
    }
    EXPECT_LT(previous, 0.5 * first);
}

TEST(VectorSplatTable, scratchesAreElongatedAlongXAndParticlesAreRound) {
    const VectorSplatTable scratches(parameters(1, 1, 128, 2.0f, MarkType::Scratches));
    const auto [sxx, syy] = gradientEnergies(scratches, 0, 0);
    EXPECT_GT(syy, 8.0 * sxx);
    const VectorSplatTable particles(parameters(1, 1, 128, 2.0f, MarkType::Particles));
    const auto [pxx, pyy] = gradientEnergies(particles, 0, 0);
    EXPECT_GT(pyy / pxx, 0.75);
    EXPECT_LT(pyy / pxx, 1.33);
}

TEST(VectorSplatTable, sampleIsBilinearWithClampToEdgeAndZeroOutside) {
    const VectorSplatTable table(parameters(2, 2, 16, 8.0f));
    const float step = 2.0f * table.extent() / 16.0f;
    const auto x = [&](int i) { return -table.extent() + (i + 0.5f) * step; };
    const glm::vec2 a = table.texel(1, 1, 7, 9);
    const glm::vec2 b = table.texel(1, 1, 8, 9);
    ASSERT_GT(a.x + b.x, 0.0f);
    EXPECT_NEAR(table.sample(1, 1, x(7), x(9)).x, a.x, 1e-6f);
    EXPECT_NEAR(table.sample(1, 1, x(7), x(9)).y, a.y, 1e-6f);
    const glm::vec2 middle = table.sample(1, 1, 0.5f * (x(7) + x(8)), x(9));
    EXPECT_NEAR(middle.x, 0.5f * (a.x + b.x), 1e-6f);
    EXPECT_NEAR(middle.y, 0.5f * (a.y + b.y), 1e-6f);
    // Within half a texel of the edge the edge texel is repeated (the window makes it 0 here).
    EXPECT_EQ(table.sample(1, 1, table.extent(), x(9)), table.texel(1, 1, 15, 9));
    EXPECT_EQ(table.sample(1, 1, table.extent() * 1.001f, 0.0f), glm::vec2(0.0f));
    EXPECT_EQ(table.sample(1, 1, 0.0f, std::nanf("")), glm::vec2(0.0f));
}

TEST(VectorSplatTable, columnOfAndProjectedLengthHandleTheEdges) {
    EXPECT_EQ(VectorSplatTable::columnOf(0.0f, 8), 0);
    EXPECT_EQ(VectorSplatTable::columnOf(1.0f, 8), 7);
    EXPECT_EQ(VectorSplatTable::columnOf(0.5f, 8), 4); // 3.5 rounds up
    EXPECT_EQ(VectorSplatTable::columnOf(0.49f, 8), 3);
    EXPECT_EQ(VectorSplatTable::columnOf(std::nanf(""), 8), 0);
    EXPECT_EQ(VectorSplatTable::columnOf(1.5f, 8), 7);
    EXPECT_EQ(VectorSplatTable::columnOf(std::numeric_limits<float>::infinity(), 8), 7);
    EXPECT_EQ(VectorSplatTable::columnOf(-0.2f, 8), 0);
    EXPECT_EQ(VectorSplatTable::columnOf(0.9f, 1), 0);
    EXPECT_EQ(VectorSplatTable::columnOf(1.0f, 2), 1);
    EXPECT_EQ(VectorSplatTable::projectedLength(0, 8), 1.0f);
    EXPECT_EQ(VectorSplatTable::projectedLength(7, 8), VectorSplatTable::kMinProjectedLength);
    EXPECT_FLOAT_EQ(VectorSplatTable::projectedLength(3, 7), std::sqrt(0.75f));
    EXPECT_FLOAT_EQ(VectorSplatTable::projectedLength(6, 8), std::sqrt(1.0f - 36.0f / 49.0f));
    EXPECT_EQ(VectorSplatTable::projectedLength(0, 1), 1.0f);
    EXPECT_EQ(VectorSplatTable::projectedLength(9, 8), VectorSplatTable::kMinProjectedLength);
    EXPECT_EQ(VectorSplatTable::projectedLength(-1, 8), 1.0f);
    // The two agree: the column of a direction is foreshortened to about its projected length
    // (columns are linear in |v_z|, so the steps in length grow towards |v_z| = 1).
    for (float towardEye : {0.0f, 0.3f, 0.6f, 0.8f}) {
        const float length = VectorSplatTable::projectedLength(
            VectorSplatTable::columnOf(towardEye, 16), 16);
        EXPECT_NEAR(length, std::sqrt(1.0f - towardEye * towardEye), 0.07f) << towardEye;
    }
}

TEST(VectorSplatTable, sharedTablesAreOnePerParameterSetAndFreedWhenReleased) {
    const std::uint64_t before = VectorSplatTable::liveTables();
    const VectorTableParameters p = parameters(2, 2, 16);
    VectorTableParameters q = p;
    q.seed = 2;
    {
        const auto a = VectorSplatTable::shared(p);
        const auto b = VectorSplatTable::shared(p);
        const auto c = VectorSplatTable::shared(q);
        EXPECT_EQ(a, b);
        EXPECT_NE(a, c);
        EXPECT_EQ(a->parameters(), p);
        EXPECT_EQ(c->parameters(), q);
        EXPECT_EQ(VectorSplatTable::liveTables(), before + 2);
        const VectorSplatTable copy = *a;
        EXPECT_EQ(VectorSplatTable::liveTables(), before + 3);
    }
    EXPECT_EQ(VectorSplatTable::liveTables(), before);
    // Threads asking at once all get the one table.
    std::vector<std::shared_ptr<const VectorSplatTable>> results(4);
    std::vector<std::thread> threads;
    for (auto& result : results)
        threads.emplace_back([&result, &p] { result = VectorSplatTable::shared(p); });
    for (std::thread& thread : threads)
        thread.join();
    for (const auto& result : results)
        EXPECT_EQ(result, results[0]);
    EXPECT_EQ(VectorSplatTable::liveTables(), before + 1);
    results.clear();
    EXPECT_EQ(VectorSplatTable::liveTables(), before);
}

TEST(VectorSplatTable, parametersCompareMemberByMember) {
    const VectorTableParameters base;
    EXPECT_EQ(base, VectorTableParameters{});
    const auto differs = [&](auto change) {
        VectorTableParameters other = base;
        change(other);
        return other != base && !(other == base);
    };
    EXPECT_TRUE(differs([](auto& p) { p.rows = 15; }));
    EXPECT_TRUE(differs([](auto& p) { p.columns = 7; }));
    EXPECT_TRUE(differs([](auto& p) { p.resolution = 32; }));
    EXPECT_TRUE(differs([](auto& p) { p.markType = MarkType::Scratches; }));
    EXPECT_TRUE(differs([](auto& p) { p.markDensity = 2.0f; }));
    EXPECT_TRUE(differs([](auto& p) { p.splatExtent = 1.5f; }));
    EXPECT_TRUE(differs([](auto& p) { p.windowScale = 1.2f; }));
    EXPECT_TRUE(differs([](auto& p) { p.seed = 2; }));
}

TEST(VectorSplatTable, badParametersThrowWithClearMessages) {
    const auto message = [](auto change) {
        VectorTableParameters p;
        change(p);
        const std::string checked =
            errorOf<texsplat::DataError>([&] { VectorSplatTable::checkParameters(p); });
        // The constructor and shared() check first too.
        EXPECT_EQ(errorOf<texsplat::DataError>([&] { VectorSplatTable{p}; }), checked);
        EXPECT_EQ(errorOf<texsplat::DataError>([&] { VectorSplatTable::shared(p); }), checked);
        return checked;
    };
    const float nan = std::nanf("");
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(message([](auto& p) { p.rows = 0; }), "vector table: rows must be in 1..256, got 0");
    EXPECT_EQ(message([](auto& p) { p.rows = 257; }),
              "vector table: rows must be in 1..256, got 257");
    EXPECT_EQ(message([](auto& p) { p.columns = -1; }),
              "vector table: columns must be in 1..64, got -1");
    EXPECT_EQ(message([](auto& p) { p.columns = 65; }),
              "vector table: columns must be in 1..64, got 65");
    EXPECT_EQ(message([](auto& p) { p.resolution = 7; }),
              "vector table: resolution must be in 8..1024, got 7");
    EXPECT_EQ(message([](auto& p) { p.resolution = 1025; }),
              "vector table: resolution must be in 8..1024, got 1025");
    EXPECT_EQ(message([](auto& p) { p.markType = static_cast<MarkType>(5); }),
              "vector table: markType must be Particles or Scratches, got 5");
    EXPECT_EQ(message([](auto& p) { p.markDensity = 0.0f; }),
              "vector table: markDensity must be finite and in (0, 64], got 0");
    EXPECT_EQ(message([](auto& p) { p.markDensity = 64.5f; }),
              "vector table: markDensity must be finite and in (0, 64], got 64.5");
    EXPECT_EQ(message([nan](auto& p) { p.markDensity = nan; }),
              "vector table: markDensity must be finite and in (0, 64], got nan");
    EXPECT_EQ(message([](auto& p) { p.splatExtent = -1.6f; }),
              "vector table: splatExtent must be finite and in (0, 8], got -1.6");
    EXPECT_EQ(message([inf](auto& p) { p.splatExtent = inf; }),
              "vector table: splatExtent must be finite and in (0, 8], got inf");
    EXPECT_EQ(message([](auto& p) { p.windowScale = 0.99f; }),
              "vector table: windowScale must be finite and in [1, 4], got 0.99");
    EXPECT_EQ(message([](auto& p) { p.windowScale = 4.01f; }),
              "vector table: windowScale must be finite and in [1, 4], got 4.01");
    EXPECT_EQ(message([](auto& p) {
                  p.rows = 256;
                  p.columns = 64;
                  p.resolution = 128;
              }),
              "vector table: rows * columns * resolution^2 must be at most 134217728 texels, got "
              "268435456");
    // The limits themselves are accepted.
    VectorTableParameters limits = parameters(1, 1, 8, 64.0f);
    limits.splatExtent = 8.0f;
    limits.windowScale = 4.0f;
    EXPECT_NO_THROW(VectorSplatTable::checkParameters(limits));
    limits = parameters(256, 64, 90, 1e-6f);
    limits.windowScale = 1.0f;
    EXPECT_NO_THROW(VectorSplatTable::checkParameters(limits));
    EXPECT_NO_THROW(VectorSplatTable(parameters(1, 1, 8, 1e-6f))); // one mark at least
}

TEST(VectorSplatTable, writeImageLaysTheTablesOutLikeFigureThree) {
    const VectorSplatTable table(parameters(3, 2, 8, 16.0f));
    // Each table: 2 columns of 8 texels and 3 separators wide, 3 rows of 8 and 4 separators high.
    const int width = 2 * 19 + VectorSplatTable::kImageGap;
    const int height = 28;
    const std::string pfm = testPath("table.pfm");
    table.writeImage(pfm);
    const std::string contents = readFile(pfm);
    const std::string header = "Pf\n42 28\n-1.0\n";
    ASSERT_EQ(contents.size(), header.size() + size_t{42} * 28 * 4);
    EXPECT_EQ(contents.substr(0, header.size()), header);
    // PFM rows run bottom to top, as the table's rows do.
    const auto value = [&](int x, int y) {
        float result = 0.0f;
        std::memcpy(&result, contents.data() + header.size() + (size_t(y) * width + x) * 4, 4);
        return result;
    };
    // Texel (i = 3, j = 4) of row 2, column 1, in the intensity table and the opacity table.
    const int x = 1 + 1 * 9 + 3;
    const int y = 1 + 2 * 9 + 4;
    EXPECT_EQ(value(x, y), table.texel(2, 1, 3, 4).x);
    EXPECT_EQ(value(19 + VectorSplatTable::kImageGap + x, y), table.texel(2, 1, 3, 4).y);
    EXPECT_EQ(value(0, 5), VectorSplatTable::kSeparatorValue);
    EXPECT_EQ(value(9, 5), VectorSplatTable::kSeparatorValue);
    EXPECT_EQ(value(5, 9), VectorSplatTable::kSeparatorValue);
    EXPECT_EQ(value(20, 5), 0.0f); // the gap
    std::remove(pfm.c_str());

    std::vector<std::string> names = {"table.png", "table.PNG"};
    if (texsplat::image::isExrSupported())
        names.push_back("table.exr");
    for (const std::string& name : names) {
        const std::string path = testPath(name);
        table.writeImage(path);
        const texsplat::image::Image image = texsplat::image::readImage(path);
        EXPECT_EQ(image.sizeString(), "42x28") << name;
        // Images run from the top: the same texel is at row height − 1 − y.
        const glm::vec4 pixel = image.pixel(x, height - 1 - y);
        EXPECT_NEAR(pixel.r, table.texel(2, 1, 3, 4).x, 0.006f) << name;
        EXPECT_EQ(pixel.a, 1.0f) << name;
        std::remove(path.c_str());
    }
}

TEST(VectorSplatTable, writeImageRejectsOtherExtensionsAndWritesNothing) {
    const VectorSplatTable table(parameters(1, 1, 8));
    const std::string path = testPath("table.tif");
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { table.writeImage(path); }),
              path + ": unknown image extension '.tif' (supported: .png, .pfm, .exr)");
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { VectorSplatTable::checkImagePath(path); }),
              path + ": unknown image extension '.tif' (supported: .png, .pfm, .exr)");
    EXPECT_FALSE(std::ifstream(path).good());
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { table.writeImage("table"); }),
              "table: no image extension (supported: .png, .pfm, .exr)");
    if (!texsplat::image::isExrSupported()) {
        EXPECT_EQ(errorOf<texsplat::IoError>([&] { table.writeImage("t.exr"); }),
                  "t.exr: OpenEXR support is not built in (configure with "
                  "-DTEXSPLAT_WITH_EXR=ON)");
    }
    const std::string unwritable = "/nonexistent-directory/table.pfm";
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { table.writeImage(unwritable); }),
              unwritable + ": cannot create a file in directory "
                           "/nonexistent-directory: No such file or directory");
    EXPECT_EQ(errorOf<texsplat::IoError>([&] { table.writeImage("/nonexistent-directory/t.png"); }),
              "/nonexistent-directory/t.png: cannot create a file in directory "
              "/nonexistent-directory: No such file or directory");
}
