#include "nodes/NodeTypes.h"

#include "SceneNodesTestSupport.h"
#include "nodes/PerspectiveCamera.h"
#include "nodes/TransferFunction.h"
#include "nodes/VolumeData.h"
#include "scenegraph/Engine.h"
#include "scenegraph/EngineOutputBase.h"
#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "tests/scenegraph/FieldSamples.h"
#include "tests/scenegraph/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace texsplat::nodes {
namespace {

TEST(NodeTypes, registersEveryNodeTypeOnceAndTheRegistryCreatesThem) {
    registerNodeTypes();
    registerNodeTypes(); // idempotent
    const sg::NodeRegistry& registry = sg::NodeRegistry::instance();
    for (const std::string name :
         {"PerspectiveCamera", "OrthographicCamera", "Transform", "Material", "DirectionalLight",
          "TransferFunction", "VolumeData", "Coordinate3", "IndexedFaceSet", "Mesh", "Fibers"}) {
        const std::shared_ptr<sg::FieldContainer> node = registry.create(name);
        ASSERT_NE(node, nullptr) << name;
        EXPECT_EQ(node->typeName(), name);
        EXPECT_NE(node->asNode(), nullptr) << name;
    }
    // The abstract base is known by name (for searches) but cannot be made.
    ASSERT_NE(registry.find("Camera"), nullptr);
    EXPECT_EQ(test::errorOf<DataError>([&] { registry.create("Camera"); }),
              "cannot create a Camera: it is an abstract type");
}

TEST(NodeTypes, sceneFilesReadAndWriteTheNodes) {
    registerNodeTypes();
    const std::string text = R"(#Inventor V2.1 ascii
Separator {
    PerspectiveCamera { position 0 0 5 heightAngle 0.5 }
    Transform { translation 1 2 3 scaleFactor 2 2 2 }
    Material { diffuseColor 1 0 0 }
    DirectionalLight { direction 0 -1 0 }
    TransferFunction { preset HOT opacityValues [ 0, 1 ] opacities [ 0, 2 ] emission 1 }
    VolumeData { source TORNADO resolution 8 8 8 time 3 }
    Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }
    IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }
    Fibers { segments 5 }
}
)";
    const std::shared_ptr<sg::Node> root = sg::SceneReader::readString(text, "nodes.iv");
    const auto& children = static_cast<sg::Group&>(*root).children();
    ASSERT_EQ(children.size(), 9u);
    const auto& camera = static_cast<const PerspectiveCamera&>(*children[0]);
    EXPECT_EQ(camera.heightAngle.value(), 0.5f);
    const auto& tf = static_cast<const TransferFunction&>(*children[4]);
    EXPECT_EQ(tf.preset.as<ColorPreset>(), ColorPreset::Hot);
    EXPECT_FLOAT_EQ(tf.classify(1.0f).extinction, 2.0f);
    const auto& volume = static_cast<const VolumeData&>(*children[5]);
    EXPECT_EQ(volume.source.as<VolumeSource>(), VolumeSource::Tornado);
    EXPECT_FALSE(volume.isLoaded()); // reading a scene loads nothing

    // Written and read again, the graph writes the same text.
    const std::string written = sg::WriteAction::writeString(*root);
    EXPECT_EQ(sg::WriteAction::writeString(*sg::SceneReader::readString(written, "again.iv")),
              written);
    EXPECT_NE(written.find("    TransferFunction {\n        fields ["), std::string::npos) << written;
}

// read → write → read gives the same graph for every registered type (the core's and this
// library's), with every field at a value that is not its default: a sample chosen by the
// field's type (tests/scenegraph/FieldSamples.h), so a new type or field is covered as it is
// declared.
TEST(NodeTypes, everyTypeRoundTripsWithEveryFieldSet) {
    registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());
    std::set<std::string> covered;
    for (const sg::NodeType* type : sg::NodeRegistry::instance().types()) {
        if (type->isAbstract()) {
            continue;
        }
        SCOPED_TRACE(type->name());
        const sg::Node::Ptr first =
            sg::SceneReader::readString(sg::test::sampleSceneText(*type), "sample.iv");
        // An engine is read as the source of a connection into a holder node.
        const sg::FieldContainer& container =
            first->typeName() == type->name()
                ? static_cast<const sg::FieldContainer&>(*first)
                : first->fields().front()->connectedOutput()->engine();
        const std::shared_ptr<sg::FieldContainer> fresh = type->create();
        ASSERT_EQ(container.fields().size(), fresh->fields().size());
        for (std::size_t i = 0; i < fresh->fields().size(); ++i) {
            const sg::Field& field = *container.fields()[i];
            if (sg::test::fieldsKeptDefault().count(type->name() + "." + field.name()) != 0) {
                continue;
            }
            EXPECT_FALSE(field.isDefault()) << field.name();
            if (field.typeName() != "SFTrigger") { // it has no value to differ
                EXPECT_NE(field.valueText(), fresh->fields()[i]->valueText()) << field.name();
            }
        }
        const std::string written = sg::WriteAction::writeString(*first);
        const sg::Node::Ptr second = sg::SceneReader::readString(written, "written.iv");
        EXPECT_EQ(sg::test::graphDifference(*first, *second), "") << written;
        EXPECT_EQ(sg::WriteAction::writeString(*second), written);
        covered.insert(type->name());
    }
    for (const std::string name :
         {"PerspectiveCamera", "OrthographicCamera", "Transform", "Material", "DirectionalLight",
          "TransferFunction", "VolumeData", "Coordinate3", "IndexedFaceSet", "Mesh", "Fibers",
          "TextureSplat", "GaussianSplat", "Separator", "Switch", "ElapsedTime"}) {
        EXPECT_EQ(covered.count(name), 1u) << name;
    }
}

// The reference, `texsplat info --reference` and tools show each field's meaning: every field and
// engine output of every registered type (the library's and the engines') declares one line.
TEST(NodeTypes, everyFieldOfEveryTypeHasAOneLineDescription) {
    registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());
    std::size_t described = 0;
    for (const sg::NodeType* type : sg::NodeRegistry::instance().types()) {
        if (type->isAbstract()) {
            continue;
        }
        const std::shared_ptr<sg::FieldContainer> instance = type->create();
        std::vector<std::string> names;
        for (const sg::Field* field : instance->fields()) {
            names.push_back(field->name());
        }
        if (const auto* engine = dynamic_cast<const sg::Engine*>(instance.get())) {
            for (const sg::EngineOutputBase* output : engine->outputs()) {
                names.push_back(output->name());
            }
        }
        for (const std::string& name : names) {
            const std::string& description = type->fieldDescription(name);
            EXPECT_GE(description.size(), 10u) << type->name() << "." << name << ": '"
                                               << description << "'";
            EXPECT_EQ(description.find('\n'), std::string::npos) << type->name() << "." << name;
            ++described;
        }
    }
    // Over a hundred fields: the loop did see the types.
    EXPECT_GT(described, 100u);
}

} // namespace
} // namespace texsplat::nodes
