// The viewer's transfer-function controls (its panel's model), tested headless on the CPU
// backend: the viewer needs a display, the fields it edits do not. Only in builds with the viewer.
#ifdef TEXSPLAT_WITH_VIEWER

#include "apps/viewer/TransferFunctionEditor.h"

#include "nodes/NodeTypes.h"
#include "nodes/TextureSplat.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "nodes/render/FrameAction.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/cpu/CpuRenderer.h"
#include "nodes/volume/DenseGrid.h"
#include "scenegraph/Error.h"
#include "scenegraph/Separator.h"
#include "scenegraph/io/SceneReader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace nodes = texsplat::nodes;
namespace sg = texsplat::sg;
using texsplat::apps::TransferFunctionEditor;

// A 16³ ramp from 2 (x = 0) to 5 (x = 15).
texsplat::volume::ScalarGridPtr ramp() {
    auto grid = std::make_shared<texsplat::volume::DenseScalarGrid>(
        texsplat::volume::GridGeometry(glm::i64vec3(16)));
    for (std::int64_t z = 0; z < 16; ++z)
        for (std::int64_t y = 0; y < 16; ++y)
            for (std::int64_t x = 0; x < 16; ++x)
                grid->setValue({x, y, z}, 2.0f + 0.2f * static_cast<float>(x));
    return grid;
}

// The function as a scene file that gives no range writes it: the range from the data.
nodes::TransferFunction::Ptr dataRangeFunction() {
    auto transfer = nodes::TransferFunction::create();
    transfer->opacityValues.setValue({0.0f, 1.0f});
    transfer->opacities.setValue({0.0f, 0.8f});
    return transfer;
}

sg::Node::Ptr scene(const nodes::TransferFunction::Ptr& transfer, int maxSplats = 0) {
    auto data = nodes::VolumeData::create();
    data->setGrid(ramp());
    auto splat = nodes::TextureSplat::create();
    splat->maxSplats.setValue(maxSplats);
    auto root = sg::Separator::create();
    root->addChild(data);
    root->addChild(transfer);
    root->addChild(splat);
    return texsplat::render::framedScene(root, 1.0f);
}

struct Rendered {
    texsplat::image::Image image;
    sg::FrameBuilds builds;
};

Rendered render(sg::Node& root) {
    texsplat::render::FrameAction action(48, 48);
    const texsplat::render::cpu::CpuRenderer renderer(1);
    texsplat::image::Image image = renderer.draw(action.collect(root), action.statistics(), false);
    return {std::move(image), action.statistics().builds};
}

bool samePixels(const texsplat::image::Image& a, const texsplat::image::Image& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.pixel(x, y) != b.pixel(x, y)) {
                return false;
            }
    return true;
}

class TransferFunctionEditorTest : public ::testing::Test {
protected:
    void SetUp() override { nodes::registerNodeTypes(); }
};

TEST_F(TransferFunctionEditorTest, findsEachFunctionOnceAndStartsFromTheRangeInEffect) {
    const auto transfer = dataRangeFunction();
    const sg::Node::Ptr root = scene(transfer);
    auto used = std::static_pointer_cast<sg::Separator>(root);
    used->addChild(transfer); // USEd: the same node on a second path
    auto named = nodes::TransferFunction::create();
    named->setName("glow");
    used->addChild(named);

    TransferFunctionEditor editor(*root);
    ASSERT_EQ(editor.count(), 2u);
    EXPECT_EQ(editor.label(0), "TransferFunction 1");
    EXPECT_EQ(editor.label(1), "glow");
    EXPECT_EQ(editor.range(), glm::vec2(2.0f, 5.0f)) << "AUTO without a range: the data's";
    EXPECT_EQ(editor.rangeBounds(), glm::vec2(2.0f, 5.0f));
    EXPECT_FALSE(editor.isEdited());

    editor.select(1); // FIXED over its own range [0, 1], below the data: the bounds hold both
    EXPECT_EQ(named->range.value(), glm::vec2(0.0f, 1.0f));
    named->rangeMode.setValue(nodes::RangeMode::Fixed);
    EXPECT_EQ(editor.range(), glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(editor.rangeBounds(), glm::vec2(0.0f, 5.0f));
}

TEST_F(TransferFunctionEditorTest, anEditDrawsWhatAFreshSceneWithTheEditedFieldsDraws) {
    for (const int maxSplats : {0, 300}) { // full resolution, and a budgeted cut
        SCOPED_TRACE(maxSplats);
        const sg::Node::Ptr root = scene(dataRangeFunction(), maxSplats);
        const Rendered first = render(*root);
        TransferFunctionEditor editor(*root);
        editor.setRange({3.0f, 4.5f});
        editor.setOpacityFactor(2.0f);
        editor.setPreset(nodes::ColorPreset::Hot);
        EXPECT_TRUE(editor.isEdited());
        const Rendered edited = render(*root);
        EXPECT_EQ(edited.builds.valueRanges, 0u) << "an edit keeps the data hierarchy";
        EXPECT_EQ(edited.builds.classifications, 1u);

        auto expected = dataRangeFunction();
        expected->rangeMode.setValue(nodes::RangeMode::Fixed);
        expected->range.setValue(glm::vec2(3.0f, 4.5f));
        expected->opacities.setValue({0.0f, 1.6f});
        expected->preset.setValue(nodes::ColorPreset::Hot);
        EXPECT_TRUE(samePixels(edited.image, render(*scene(expected, maxSplats)).image));
        EXPECT_FALSE(samePixels(edited.image, first.image)) << "the edit shows";
    }
}

TEST_F(TransferFunctionEditorTest, opacityFactorsScaleTheOriginalOpacitiesNotTheLastOnes) {
    const auto transfer = dataRangeFunction();
    TransferFunctionEditor editor(*scene(transfer));
    ASSERT_TRUE(editor.editsOpacity());
    editor.setOpacityFactor(4.0f);
    editor.setOpacityFactor(0.5f);
    EXPECT_FLOAT_EQ(editor.opacityFactor(), 0.5f);
    EXPECT_EQ(transfer->opacities.values(), (std::vector<float>{0.0f, 0.4f}));
}

TEST_F(TransferFunctionEditorTest, opacityPointsStayInOrderAndCarryTheFactor) {
    const auto transfer = dataRangeFunction();
    transfer->opacityValues.setValue({0.0f, 0.5f, 1.0f});
    transfer->opacities.setValue({0.0f, 1.0f, 2.0f});
    TransferFunctionEditor editor(*scene(transfer));
    ASSERT_TRUE(editor.editsOpacity());
    using Points = std::vector<glm::vec2>;
    EXPECT_EQ(editor.opacityPoints(), (Points{{0.0f, 0.0f}, {0.5f, 1.0f}, {1.0f, 2.0f}}));

    editor.moveOpacityPoint(1, {1.5f, -3.0f}); // past its right neighbour, below zero
    EXPECT_EQ(editor.opacityPoints(), (Points{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}}));
    editor.moveOpacityPoint(1, {-1.0f, 0.5f}); // past its left neighbour
    EXPECT_EQ(editor.opacityPoints()[1], glm::vec2(0.0f, 0.5f));
    EXPECT_EQ(editor.addOpacityPoint({0.25f, 0.75f}), 2u);
    editor.setOpacityFactor(2.0f);
    EXPECT_EQ(transfer->opacityValues.values(), (std::vector<float>{0.0f, 0.0f, 0.25f, 1.0f}));
    EXPECT_EQ(transfer->opacities.values(), (std::vector<float>{0.0f, 1.0f, 1.5f, 4.0f}));

    editor.removeOpacityPoint(0);
    editor.removeOpacityPoint(0);
    editor.removeOpacityPoint(0);
    editor.removeOpacityPoint(0); // the last one stays: a function needs one
    EXPECT_EQ(editor.opacityPoints(), (Points{{1.0f, 2.0f}}));
    EXPECT_EQ(transfer->opacities.values(), (std::vector<float>{4.0f}));

    editor.reset();
    EXPECT_EQ(transfer->opacityValues.values(), (std::vector<float>{0.0f, 0.5f, 1.0f}));
    EXPECT_EQ(editor.opacityPoints(), (Points{{0.0f, 0.0f}, {0.5f, 1.0f}, {1.0f, 2.0f}}));
    EXPECT_FALSE(editor.isEdited());
}

TEST_F(TransferFunctionEditorTest, theHistogramCountsTheDataOverItsRange) {
    TransferFunctionEditor editor(*scene(dataRangeFunction()));
    EXPECT_EQ(editor.dataRange(), glm::vec2(2.0f, 5.0f));
    // 16 values (2, 2.2, ..., 5), 256 voxels each, into 7 bins of width 3/7 (no value on an edge;
    // the largest, 5, counts into the last bin).
    EXPECT_EQ(editor.histogram(7), (std::vector<std::uint64_t>{3 * 256, 2 * 256, 2 * 256, 2 * 256,
                                                               2 * 256, 2 * 256, 3 * 256}));
    EXPECT_EQ(editor.histogram(1), (std::vector<std::uint64_t>{16 * 256}));

    auto root = sg::Separator::create();
    root->addChild(nodes::TransferFunction::create());
    TransferFunctionEditor withoutData(*root);
    EXPECT_EQ(withoutData.histogram(3), (std::vector<std::uint64_t>{0, 0, 0}));
}

TEST_F(TransferFunctionEditorTest, resetRestoresTheFieldsAndTakesTheRangeFromTheDataAgain) {
    const auto transfer = dataRangeFunction();
    const sg::Node::Ptr root = scene(transfer);
    const Rendered first = render(*root);
    TransferFunctionEditor editor(*root);
    editor.setRange({2.5f, 3.0f});
    editor.setOpacityFactor(3.0f);
    editor.setPreset(nodes::ColorPreset::Turbo);
    render(*root);

    editor.reset();
    EXPECT_FALSE(editor.isEdited());
    EXPECT_TRUE(transfer->range.isDefault()) << "AUTO takes the range from the data again";
    EXPECT_TRUE(transfer->rangeMode.isDefault());
    EXPECT_TRUE(transfer->preset.isDefault());
    EXPECT_FLOAT_EQ(editor.opacityFactor(), 1.0f);
    EXPECT_EQ(editor.range(), glm::vec2(2.0f, 5.0f));
    EXPECT_TRUE(samePixels(render(*root).image, first.image));
}

TEST_F(TransferFunctionEditorTest, theTextOfAnEditedFunctionReadsBackAsThatFunction) {
    const auto transfer = dataRangeFunction();
    transfer->setName("clouds");
    TransferFunctionEditor editor(*scene(transfer));
    editor.setRange({2.5f, 4.0f});
    editor.addOpacityPoint({0.5f, 0.25f});
    editor.setPreset(nodes::ColorPreset::Magma);
    const std::string text = editor.sceneText();
    EXPECT_EQ(text.rfind("DEF clouds TransferFunction {", 0), 0u) << text;
    const auto read = std::dynamic_pointer_cast<nodes::TransferFunction>(
        texsplat::sg::SceneReader::readString("#Inventor V2.1 ascii\n" + text));
    ASSERT_TRUE(read);
    EXPECT_EQ(read->range.value(), glm::vec2(2.5f, 4.0f));
    EXPECT_EQ(read->rangeMode.as<nodes::RangeMode>(), nodes::RangeMode::Fixed);
    EXPECT_EQ(read->opacityValues.values(), transfer->opacityValues.values());
    EXPECT_EQ(read->opacities.values(), transfer->opacities.values());
    EXPECT_EQ(read->preset.as<nodes::ColorPreset>(), nodes::ColorPreset::Magma);
}

TEST_F(TransferFunctionEditorTest, offersOnlyFieldsItMaySet) {
    const auto transfer = dataRangeFunction();
    const auto source = nodes::TransferFunction::create();
    transfer->opacities.connectFrom(source->opacities);
    transfer->colors.setValue({glm::vec3(1.0f, 0.0f, 0.0f)});
    TransferFunctionEditor editor(*scene(transfer));
    EXPECT_TRUE(editor.editsRange());
    EXPECT_FALSE(editor.editsOpacity()) << "a connected field follows its connection";
    const auto mismatched = dataRangeFunction();
    mismatched->opacityValues.setValue({0.0f, 0.5f, 1.0f}); // three positions, two opacities
    EXPECT_FALSE(TransferFunctionEditor(*scene(mismatched)).editsOpacity());
    EXPECT_FALSE(editor.editsPreset()) << "explicit colours replace the preset";

    transfer->range.connectFrom(source->range);
    EXPECT_FALSE(editor.editsRange());
}

TEST_F(TransferFunctionEditorTest, refusesWhatNoFunctionCanTake) {
    const auto transfer = dataRangeFunction();
    TransferFunctionEditor editor(*scene(transfer));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(editor.setRange({4.0f, 3.0f}), texsplat::DataError);
    EXPECT_THROW(editor.setRange({3.0f, 3.0f}), texsplat::DataError);
    EXPECT_THROW(editor.setRange({nan, 3.0f}), texsplat::DataError);
    EXPECT_THROW(editor.setOpacityFactor(0.0f), texsplat::DataError);
    EXPECT_THROW(editor.setOpacityFactor(std::numeric_limits<float>::infinity()),
                 texsplat::DataError);
    EXPECT_THROW(editor.select(1), texsplat::DataError);
    EXPECT_THROW(editor.moveOpacityPoint(2, {0.5f, 1.0f}), texsplat::DataError);
    EXPECT_THROW(editor.moveOpacityPoint(0, {nan, 1.0f}), texsplat::DataError);
    EXPECT_THROW(editor.addOpacityPoint({0.5f, nan}), texsplat::DataError);
    EXPECT_THROW(editor.removeOpacityPoint(2), texsplat::DataError);
    EXPECT_FALSE(editor.isEdited()) << "a refused edit changes nothing";
}

TEST_F(TransferFunctionEditorTest, eachFunctionShowsTheDataItClassifies) {
    // As examples/figure8-clouds-winds.iv: two separators, each a function, a volume and a
    // splat node; then a function that no splat node uses.
    const auto branch = [](const nodes::TransferFunction::Ptr& transfer, float offset) {
        auto grid = std::make_shared<texsplat::volume::DenseScalarGrid>(
            texsplat::volume::GridGeometry(glm::i64vec3(4)), offset);
        grid->setValue({0, 0, 0}, offset + 1.0f);
        auto data = nodes::VolumeData::create();
        data->setGrid(grid);
        auto separator = sg::Separator::create();
        separator->addChild(transfer);
        separator->addChild(data);
        separator->addChild(nodes::TextureSplat::create());
        return separator;
    };
    auto root = sg::Separator::create();
    root->addChild(branch(dataRangeFunction(), 10.0f));
    root->addChild(branch(dataRangeFunction(), 20.0f));
    root->addChild(dataRangeFunction());
    TransferFunctionEditor editor(*root);
    ASSERT_EQ(editor.count(), 3u);
    EXPECT_EQ(editor.dataRange(), glm::vec2(10.0f, 11.0f));
    EXPECT_EQ(editor.range(), glm::vec2(10.0f, 11.0f));
    editor.select(1);
    EXPECT_EQ(editor.dataRange(), glm::vec2(20.0f, 21.0f));
    EXPECT_EQ(editor.range(), glm::vec2(20.0f, 21.0f));
    EXPECT_EQ(editor.histogram(2), (std::vector<std::uint64_t>{63, 1}));
    editor.select(2);
    EXPECT_EQ(editor.dataRange(), glm::vec2(10.0f, 11.0f)) << "unused: the first volume's";
}

TEST_F(TransferFunctionEditorTest, withoutVolumeDataTheBoundsWidenTheFunctionsOwnRange) {
    auto root = sg::Separator::create();
    auto transfer = nodes::TransferFunction::create();
    transfer->range.setValue(glm::vec2(10.0f, 14.0f));
    root->addChild(transfer);
    TransferFunctionEditor editor(*root);
    EXPECT_EQ(editor.range(), glm::vec2(10.0f, 14.0f));
    EXPECT_EQ(editor.rangeBounds(), glm::vec2(8.0f, 16.0f));
    EXPECT_TRUE(TransferFunctionEditor(*sg::Separator::create()).isEmpty());
}

} // namespace

#endif
