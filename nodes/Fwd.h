#pragma once

/// @file
/// @brief Forward declarations of the scene nodes (namespace texsplat::nodes).

namespace texsplat::nodes {

class Camera;
class Coordinate3;
class DirectionalLight;
class Fibers;
class IndexedFaceSet;
class Material;
class Mesh;
class OrthographicCamera;
class PerspectiveCamera;
class TransferFunction;
class Transform;
class VolumeData;
struct CameraElement;
struct Classification;
struct Coordinate3Element;
struct DepthRange;
struct DirectionalLightSource;
struct LightElement;
struct MaterialElement;
struct TransferFunctionElement;
struct TriangleMesh;
struct VolumeElement;

} // namespace texsplat::nodes
