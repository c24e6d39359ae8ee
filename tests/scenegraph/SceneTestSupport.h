#pragma once

// Node types with every field type, their registration, and a structural graph comparison for
// the scene-file tests (reader, writer, Coin interop) and the scene-reader fuzzer.

#include "scenegraph/Declare.h"
#include "scenegraph/EnumNames.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/fields/Fields.h"
#include "scenegraph/fields/MFNode.h"
#include "scenegraph/fields/SFEnum.h"
#include "scenegraph/fields/SFNode.h"
#include "scenegraph/io/SceneReader.h"
#include "tests/scenegraph/TestNodes.h"

#include <map>
#include <string>

namespace texsplat::sg::test {

enum class Quality { Draft, Final };
inline const EnumNames kQualityNames{{"DRAFT", Quality::Draft}, {"FINAL", Quality::Final}};

/// An extension group node with one field of every type the core has.
class AllFields : public Declare<AllFields, Group> {
public:
    static constexpr const char* kTypeName = "AllFields";
    SFBool flag;
    SFInt32 count;
    SFFloat size;
    SFString label;
    SFVec2f offset;
    SFVec3f position;
    SFColor color;
    SFRotation orientation;
    SFMatrix matrix;
    SFEnum quality;
    SFNode node;
    MFInt32 indices;
    MFFloat weights;
    MFVec3f points;
    MFColor colors;
    MFString names;
    MFNode nodes;

protected:
    AllFields() {
        addField(flag, "flag", true, "The flag of the test");
        addField(count, "count", 3, "The count of the test");
        addField(size, "size", 1.6f, "The size of the test");
        addField(label, "label", std::string("splat"), "The label of the test");
        addField(offset, "offset", glm::vec2(0.0f), "The offset of the test");
        addField(position, "position", glm::vec3(0.0f), "The position of the test");
        addField(color, "color", glm::vec3(1.0f), "The color of the test");
        addField(orientation, "orientation", Rotation(), "The orientation of the test");
        addField(matrix, "matrix", glm::mat4(1.0f), "The matrix of the test");
        addField(quality, "quality", Quality::Draft, kQualityNames, "The quality of the test");
        addField(node, "node", std::shared_ptr<Node>(), "The node of the test");
        addField(indices, "indices", std::vector<std::int32_t>{}, "The indices of the test");
        addField(weights, "weights", std::vector<float>{0.5f}, "The weights of the test");
        addField(points, "points", std::vector<glm::vec3>{}, "The points of the test");
        addField(colors, "colors", std::vector<glm::vec3>{}, "The colors of the test");
        addField(names, "names", std::vector<std::string>{}, "The names of the test");
        addField(nodes, "nodes", std::vector<std::shared_ptr<Node>>{}, "The nodes of the test");
    }
};

/// Registers the test types (and the core engines) so files can name them.
inline void registerSceneTestTypes() {
    NodeRegistry& registry = NodeRegistry::instance();
    registry.add<AllFields>();
    registry.add<TestCube>();
    registry.add<TestDoubler>();
    registerEngineTypes(registry);
}

/// Describes where two graphs first differ ("" when they are the same): types, names, which
/// fields are default, field values, connections, children, and which nodes are shared (a
/// one-to-one map between the graphs' containers).
class GraphComparison {
public:
    std::string compare(const FieldContainer& a, const FieldContainer& b) {
        const auto mapped = mMap.find(&a);
        if (mapped != mMap.end()) {
            return mapped->second == &b ? "" : "sharing differs at " + a.describe();
        }
        if (mReverse.count(&b) != 0) {
            return "sharing differs at " + b.describe();
        }
        mMap[&a] = &b;
        mReverse[&b] = &a;
        if (a.typeName() != b.typeName() || a.name() != b.name()) {
            return a.describe() + " vs " + b.describe();
        }
        if (a.fields().size() != b.fields().size()) {
            return a.describe() + ": field count differs";
        }
        for (std::size_t i = 0; i < a.fields().size(); ++i) {
            std::string difference = compareFields(*a.fields()[i], *b.fields()[i]);
            if (!difference.empty()) {
                return difference;
            }
        }
        const auto* groupA = dynamic_cast<const Group*>(&a);
        const auto* groupB = dynamic_cast<const Group*>(&b);
        if ((groupA == nullptr) != (groupB == nullptr)) {
            return a.describe() + ": group vs not a group";
        }
        if (groupA == nullptr) {
            return "";
        }
        if (groupA->childCount() != groupB->childCount()) {
            return a.describe() + ": " + std::to_string(groupA->childCount()) + " vs " +
                   std::to_string(groupB->childCount()) + " children";
        }
        for (std::size_t i = 0; i < groupA->childCount(); ++i) {
            std::string difference = compare(*groupA->child(i), *groupB->child(i));
            if (!difference.empty()) {
                return difference;
            }
        }
        return "";
    }

private:
    std::string compareFields(const Field& a, const Field& b) {
        const std::string where = a.fullName();
        if (a.name() != b.name() || a.typeName() != b.typeName() ||
            a.isDefault() != b.isDefault() || a.valueText() != b.valueText()) {
            return where + ": " + a.valueText() + (a.isDefault() ? " (default)" : "") + " vs " +
                   b.fullName() + ": " + b.valueText() + (b.isDefault() ? " (default)" : "");
        }
        if ((a.connectedField() == nullptr) != (b.connectedField() == nullptr) ||
            (a.connectedOutput() == nullptr) != (b.connectedOutput() == nullptr)) {
            return where + ": connection differs";
        }
        if (a.connectedField() != nullptr && a.connectedField()->container() != nullptr) {
            if (a.connectedField()->name() != b.connectedField()->name()) {
                return where + ": connected from a different field";
            }
            return compare(*a.connectedField()->container(), *b.connectedField()->container());
        }
        if (a.connectedOutput() != nullptr) {
            if (a.connectedOutput()->name() != b.connectedOutput()->name()) {
                return where + ": connected from a different output";
            }
            return compare(a.connectedOutput()->engine(), b.connectedOutput()->engine());
        }
        if (const auto* single = dynamic_cast<const SFNode*>(&a)) {
            const auto& other = static_cast<const SFNode&>(b).value();
            return single->value() ? compare(*single->value(), *other) : "";
        }
        if (const auto* multiple = dynamic_cast<const MFNode*>(&a)) {
            const auto& other = static_cast<const MFNode&>(b);
            for (std::size_t i = 0; i < multiple->size(); ++i) {
                if ((*multiple)[i]) {
                    std::string difference = compare(*(*multiple)[i], *other[i]);
                    if (!difference.empty()) {
                        return difference;
                    }
                }
            }
        }
        return "";
    }

    std::map<const FieldContainer*, const FieldContainer*> mMap;
    std::map<const FieldContainer*, const FieldContainer*> mReverse;
};

/// "" when the graphs under `a` and `b` are the same (see GraphComparison).
inline std::string graphDifference(const FieldContainer& a, const FieldContainer& b) {
    return GraphComparison().compare(a, b);
}

/// The message of the ParseError that reading `text` (header included) as `fileName` throws, or
/// "no error".
inline std::string readError(const std::string& text, const std::string& fileName) {
    try {
        SceneReader::readString(text, fileName);
    } catch (const ParseError& error) {
        return error.what();
    }
    return "no error";
}

} // namespace texsplat::sg::test
