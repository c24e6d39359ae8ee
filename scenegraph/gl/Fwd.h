#pragma once

/// @file
/// @brief Forward declarations of the OpenGL layer (namespace texsplat::gl), for headers that
/// only pass its objects by reference (the GL backend, the viewer).

namespace texsplat::gl {

class Buffer;
class Context;
class EglContext;
class Framebuffer;
class ObjectName;
class Program;
class Texture2D;
class VertexArray;
struct ContextInfo;
struct EglContextOptions;
struct TextureSampling;
enum class EglPlatform;
enum class FramebufferColor;
enum class FramebufferDepth;
enum class RowOrder;
enum class TextureFormat;

} // namespace texsplat::gl
