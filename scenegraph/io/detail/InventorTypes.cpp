#include "scenegraph/io/detail/InventorTypes.h"

#include <algorithm>
#include <iterator>

namespace texsplat::sg::detail {

bool isInventorType(std::string_view typeName) {
    // The node and engine classes of Open Inventor 2.1 (as Coin 4 registers them), sorted.
    static constexpr std::string_view kTypes[] = {
        "Annotation", "AntiSquish", "Array", "AsciiText", "BaseColor", "Billboard", "Blinker",
        "BoolOperation", "Calculator", "Callback", "ClipPlane", "Color", "ColorIndex",
        "Complexity", "ComposeMatrix", "ComposeRotation", "ComposeRotationFromTo", "ComposeVec2f",
        "ComposeVec3f", "ComposeVec4f", "ComputeBoundingBox", "Concatenate", "Cone",
        "Coordinate3", "Coordinate4", "Counter", "Cube", "Cylinder", "DecomposeMatrix",
        "DecomposeRotation", "DecomposeVec2f", "DecomposeVec3f", "DecomposeVec4f",
        "DirectionalLight", "DrawStyle", "ElapsedTime", "Environment", "EventCallback",
        "FaceSet", "File", "Font", "FontStyle", "Gate", "Group", "IndexedFaceSet",
        "IndexedLineSet", "IndexedNurbsCurve", "IndexedNurbsSurface", "IndexedTriangleStripSet",
        "Info", "InterpolateFloat", "InterpolateRotation", "InterpolateVec2f",
        "InterpolateVec3f", "InterpolateVec4f", "LOD", "Label", "LevelOfDetail", "LightModel",
        "LineSet", "LinearProfile", "LocateHighlight", "Material", "MaterialBinding",
        "MaterialIndex", "MatrixTransform", "MultipleCopy", "Normal", "NormalBinding",
        "NurbsCurve", "NurbsProfile", "NurbsSurface", "OnOff", "OneShot", "OrthographicCamera",
        "PackedColor", "PathSwitch", "Pendulum", "PerspectiveCamera", "PickStyle", "PointLight",
        "PointSet", "PolygonOffset", "ProfileCoordinate2", "ProfileCoordinate3", "QuadMesh",
        "ResetTransform", "Rotation", "RotationXYZ", "Rotor", "Scale", "Select1Bool",
        "Select1Float", "Select1Int32", "Select1Node", "Select1Rotation", "Select1String",
        "Select1Vec3f", "Selection", "Separator", "ShapeHints", "Shuttle", "Sphere",
        "SpotLight", "Switch", "Text2", "Text3", "Texture2", "Texture2Transform",
        "TextureCoordinate2", "TextureCoordinateBinding", "TextureCoordinateDefault",
        "TextureCoordinateEnvironment", "TextureCoordinatePlane", "TimeCounter", "Transform",
        "TransformSeparator", "TransformVec3f", "Translation", "TriangleStripSet",
        "TriggerAny", "Units", "VertexProperty", "WWWAnchor", "WWWInline"};
    return std::binary_search(std::begin(kTypes), std::end(kTypes), typeName);
}

} // namespace texsplat::sg::detail
