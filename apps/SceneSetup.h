#pragma once

#include "nodes/render/SceneFraming.h"
#include "nodes/volume/VolumeFileInfo.h"
#include "scenegraph/io/DataRoots.h"
#include "scenegraph/Node.h"
#include "scenegraph/WorkProgress.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <optional>
#include <string>

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief "WxH" with whole numbers from 1 to 16384 (beyond any GL framebuffer limit we could
/// meet). Throws DataError naming `option` otherwise.
glm::ivec2 parseSize(const std::string& text, const std::string& option = "--size");

/// @brief "x,y,z", finite and not all zero. Throws DataError naming `option` otherwise.
glm::vec3 parseDirection(const std::string& text, const std::string& option = "--direction");

/// @brief The premultiplied clear colour `--background` names: "black" (the default), "white",
/// "transparent" (alpha 0: the layer alone, for compositing) or "r,g,b" (0 to 1, opaque; display
/// values, as colour maps give them).
/// Throws DataError naming --background otherwise.
glm::vec4 parseBackground(const std::string& text);

/// @brief The opaque colour an option such as `--outline-color` names: "black", "white" or
/// "r,g,b" (0 to 1). Throws DataError naming `option` otherwise.
glm::vec4 parseOpaqueColor(const std::string& text, const std::string& option);

/// @brief What --max-splats and --error-threshold ask of every splat node of a scene.
struct BudgetOverride {
    std::string maxSplats;      ///< "" (the scene's own) or a whole number >= 0 (0: none)
    std::string errorThreshold; ///< "" (the scene's own) or a finite number >= 0
};

/// @brief Sets `maxSplats` and `errorThreshold` of every splat node under `scene` (TextureSplat,
/// GaussianSplat, VectorSplat, CombinedSplat) as `budget` asks; answers how many nodes it set.
/// Throws DataError naming the option for a value out of range, or when the scene has no splat
/// node to set.
int applyBudget(sg::Node& scene, const BudgetOverride& budget);

/// @brief What a command draws: a scene file, a data file, or the built-in default scene.
struct SceneSource {
    /// @brief A scene file; a data file (texsplat-raw, .npy, NRRD, NetCDF, .vdb), drawn with the
    /// scene `texsplat info FILE --scene` prints (volume::quickLookScene()); or empty for the
    /// built-in default scene (the tornado with fibres).
    std::string path;
    /// @brief Set: `path` is a headerless raw file laid out so (drawn as a data file).
    std::optional<volume::HeaderlessRawLayout> headerless;
    /// @brief How the command line gave `headerless` (" --dims 256,256,180 --type uint8"), for
    /// the message that says how to print the data file's scene.
    std::string headerlessArguments;
    /// @brief The folders every file the scene reads must lie in; null: any.
    std::shared_ptr<const sg::DataRoots> dataRoots;
};

/// @brief Registers every node and engine type, then reads `source`: its scene file, the scene
/// of its data file (saying on stderr which one, and how to save it to edit it), or the built-in
/// default scene.
/// @throws what the scene reader or volume::quickLookScene() throws; IoError for a data file
/// outside the data roots.
sg::Node::Ptr loadScene(const SceneSource& source);

/// @brief loadScene() of the scene file (or data file) `path`, or of the default scene when it
/// is empty.
sg::Node::Ptr loadScene(const std::string& path);

/// @brief How to frame a scene that has no camera of its own, or change the view of its camera
/// (the --camera, --direction, --up, --azimuth, --elevation and --zoom options of `render` and
/// `view`).
struct Framing {
    std::string sceneName; ///< the scene file ("" for the default scene), for messages
    std::string camera;    ///< "perspective" (default when empty) or "orthographic"
    std::string direction; ///< "x,y,z" viewing direction; empty: the scene's usual one
    std::string up;        ///< "x,y,z" up in the image; empty: the smallest turn from +y
    std::string azimuth;   ///< degrees about the camera's up axis through its focal point
    std::string elevation; ///< degrees about its right axis through the focal point, after azimuth
    std::string zoom;      ///< magnification > 0 (2: things look twice as large)
};

/// @brief Checks the view and budget options (throws DataError as withCamera() and applyBudget()
/// would) before any work: every option is checked before the scene is read.
void checkSceneOptions(const Framing& framing, const BudgetOverride& budget);

/// @brief The camera `--camera` names: "perspective" (or empty) or "orthographic".
/// @throws DataError for anything else.
render::FramingCamera parseFramingCamera(const std::string& camera);

/// @brief Adds --camera, --direction, --up, --azimuth, --elevation and --zoom to `command`,
/// filling `framing`.
void addViewOptions(CLI::App& command, Framing& framing);

/// @brief The scene as drawn: `scene` itself when it has a camera (`camera` of the other kind
/// replaces it by one that sees the same at its focal distance, render::cameraOfKind()), else a
/// Separator holding a new camera that frames the scene's bounding box for a viewport of
/// `aspect`, then the scene. Then, on the scene's own camera or the new one: `direction` turns
/// it to look along that direction at its focal point (for a framing camera it is the direction
/// framed from), `up` rolls it so that `up` is up in the image, `azimuth` and `elevation` orbit
/// it about its focal point (ParaView's and the viewer's orbit), `zoom` magnifies (a narrower
/// opening angle, or a smaller orthographic height). Framing takes the scene's bounding box,
/// which loads (or generates) its volumes, telling `progress`: callers that time loading count
/// this call in.
/// @throws DataError for a bad option, or a scene with neither geometry nor camera;
/// sg::Cancelled when `progress` cancelled a load.
sg::Node::Ptr withCamera(const sg::Node::Ptr& scene, const Framing& framing, float aspect,
                         const sg::WorkProgress& progress = {});

} // namespace texsplat::apps
