#include "Bindings.h"

#include "nodes/Camera.h"
#include "nodes/annotation/ImageAnnotations.h"
#include "nodes/image/ImageIo.h"
#include "nodes/render/SceneFraming.h"
#include "nodes/render/SceneRenderer.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/actions/SearchAction.h"
#include "scenegraph/engines/SceneTime.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"

#include <nanobind/ndarray.h>
#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace texsplat::python {
namespace {

// A scene read or made in Python: its root, the name messages give it (the file), and its time.
struct Scene {
    Scene(sg::Node::Ptr sceneRoot, std::string sceneName)
        : root(std::move(sceneRoot)), name(std::move(sceneName)),
          time(std::make_unique<sg::SceneTime>(*root)) {}

    sg::Node::Ptr root;
    std::string name;
    std::unique_ptr<sg::SceneTime> time;
};

// A rendered image, the scene as drawn (its camera) and what it was drawn over, for the
// annotations save() draws.
struct Image {
    image::Image pixels;
    sg::Node::Ptr drawn;
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
};

// The memory limit of one call (`memory_limit`): as `--memory-limit`, the memory available now
// unless given; the previous limit comes back when the call ends.
class MemoryLimitScope {
public:
    explicit MemoryLimitScope(nb::handle limit) {
        std::uint64_t bytes = 0;
        if (limit.is_none()) {
            bytes = availableMemoryBytes();
        } else if (nb::isinstance<nb::int_>(limit) && !nb::isinstance<nb::bool_>(limit)) {
            const long long value = nb::cast<long long>(limit);
            if (value < 1) {
                throw DataError("memory_limit: expected a byte count > 0, got " +
                                std::to_string(value));
            }
            bytes = static_cast<std::uint64_t>(value);
        } else if (nb::isinstance<nb::str>(limit)) {
            try {
                bytes = parseByteCount(nb::cast<std::string>(limit));
            } catch (const DataError& error) {
                throw DataError(std::string("memory_limit: ") + error.what());
            }
        } else {
            throw nb::type_error("memory_limit: expected a byte count (an int, or a string such "
                                 "as '512M' or '8G') or None");
        }
        mPrevious = setMemoryLimit(bytes);
    }
    ~MemoryLimitScope() { setMemoryLimit(mPrevious); }
    MemoryLimitScope(const MemoryLimitScope&) = delete;
    MemoryLimitScope& operator=(const MemoryLimitScope&) = delete;

private:
    std::uint64_t mPrevious = 0;
};

// The fields of a scene's own camera, put back after a render that turned it, so that rendering
// a scene again with the same view gives the same image.
class CameraRestore {
public:
    explicit CameraRestore(sg::Node& scene) : mCamera(render::findCamera(scene)) {
        if (mCamera != nullptr) {
            mSaved = std::static_pointer_cast<nodes::Camera>(mCamera->type().create());
            for (std::size_t i = 0; i < mCamera->fields().size(); ++i) {
                mSaved->fields()[i]->copyValueFrom(*mCamera->fields()[i]);
                mSaved->fields()[i]->setDefault(mCamera->fields()[i]->isDefault());
            }
        }
    }
    ~CameraRestore() {
        if (mCamera != nullptr) {
            for (std::size_t i = 0; i < mCamera->fields().size(); ++i) {
                sg::Field& field = *mCamera->fields()[i];
                if (field.valueText() != mSaved->fields()[i]->valueText()) {
                    field.copyValueFrom(*mSaved->fields()[i]);
                }
                field.setDefault(mSaved->fields()[i]->isDefault());
            }
        }
    }
    CameraRestore(const CameraRestore&) = delete;
    CameraRestore& operator=(const CameraRestore&) = delete;

private:
    nodes::Camera* mCamera;
    std::shared_ptr<nodes::Camera> mSaved;
};

// Whether `auto` was found to mean the CPU backend (GL is a software rasterizer or missing):
// later renders then skip trying a GL context.
std::atomic<bool> sAutoIsCpu{false};

render::BackendRequest backendRequest(const std::string& backend) {
    const render::BackendRequest request = render::parseBackendRequest(backend);
    return request == render::BackendRequest::Auto && sAutoIsCpu ? render::BackendRequest::Cpu
                                                                  : request;
}

// The premultiplied clear colour `background` names, as `--background` does: "black" (None),
// "white", "transparent", or (r, g, b) or (r, g, b, a) from 0 to 1 (as colour maps give colours).
glm::vec4 backgroundOf(nb::handle background) {
    if (background.is_none()) {
        return {0.0f, 0.0f, 0.0f, 1.0f};
    }
    if (nb::isinstance<nb::str>(background)) {
        const std::string name = nb::cast<std::string>(background);
        if (name == "black") {
            return {0.0f, 0.0f, 0.0f, 1.0f};
        }
        if (name == "white") {
            return glm::vec4(1.0f);
        }
        if (name == "transparent") {
            return glm::vec4(0.0f);
        }
    } else if (nb::isinstance<nb::sequence>(background) &&
               (nb::len(background) == 3 || nb::len(background) == 4)) {
        glm::vec4 rgba(1.0f);
        bool inRange = true;
        int channel = 0;
        for (nb::handle value : background) {
            rgba[channel] = PyNumber_Check(value.ptr()) ? nb::cast<float>(nb::float_(value)) : -1.0f;
            inRange = inRange && rgba[channel] >= 0.0f && rgba[channel] <= 1.0f;
            ++channel;
        }
        if (inRange) {
            return {glm::vec3(rgba) * rgba.a, rgba.a};
        }
    }
    throw DataError("background: expected black, white, transparent or r,g,b (0 to 1), "
                    "got " + std::string(nb::repr(background).c_str()));
}

// What `progress` asks for: a callable, True (tqdm bars: texsplat.TqdmProgress), False or None.
nb::object progressOf(nb::handle progress) {
    if (progress.is(nb::bool_(true))) {
        return nb::module_::import_("texsplat").attr("TqdmProgress")();
    }
    if (progress.is(nb::bool_(false))) {
        return nb::none();
    }
    return nb::borrow(progress);
}

Image renderScene(Scene& scene, std::pair<int, int> size, const std::string& backend,
                  std::optional<double> time, nb::handle background, float azimuth,
                  float elevation, float zoom, int threads, nb::handle memoryLimit,
                  nb::handle progress) {
    render::SceneRenderOptions options;
    options.width = size.first;
    options.height = size.second;
    options.background = backgroundOf(background);
    options.backend = backendRequest(backend);
    options.threads = threads;
    options.advice = "render a smaller size, with a splat budget (max_splats), or with "
                     "backend='cpu'";
    render::ViewChange change;
    change.azimuth = azimuth;
    change.elevation = elevation;
    change.zoom = zoom;
    const MemoryLimitScope limit(memoryLimit);
    PythonProgress work(progressOf(progress));
    return work.run([&] {
        render::SceneRenderer renderer(options);
        if (backend == "auto" && renderer.backend().backend == render::Backend::Cpu) {
            sAutoIsCpu = true;
        }
        renderer.setWorkProgress(work.workProgress());
        if (time) {
            scene.time->setTime(*time);
        }
        render::Framing framing;
        framing.name = scene.name;
        framing.progress = work.workProgress();
        const CameraRestore restore(*scene.root);
        const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
        sg::Node::Ptr drawn = withMemoryStage("reading the scene's volumes", 0,
                                              "use a volume of lower resolution", [&] {
                                                  return render::viewedScene(scene.root, aspect,
                                                                             framing, change);
                                              });
        image::Image pixels = renderer.render(*drawn);
        return Image{std::move(pixels), std::move(drawn), options.background};
    });
}

nb::ndarray<nb::numpy, float, nb::shape<-1, -1, 4>> pixelArray(nb::handle self) {
    Image& image = nb::cast<Image&>(self);
    return {reinterpret_cast<float*>(image.pixels.data()),
            {static_cast<std::size_t>(image.pixels.height()),
             static_cast<std::size_t>(image.pixels.width()), 4},
            self};
}

void saveImage(const Image& image, const std::filesystem::path& file, bool colorbar,
               const std::string& colorbarPosition, bool outline) {
    annotation::AnnotationRequest request;
    request.background = image.background;
    request.colorbar = colorbar;
    if (colorbar) {
        try {
            request.colorbarPosition = annotation::parseLegendPosition(colorbarPosition);
        } catch (const DataError& error) {
            throw DataError(std::string("colorbar_position: ") + error.what());
        }
    }
    if (outline) {
        request.outline = glm::vec4(1.0f);
    }
    const std::string path = file.string();
    nb::gil_scoped_release release;
    if (!image.drawn) {
        if (request.colorbar || request.outline) {
            throw DataError(path + ": an image read from a file has no scene to draw a colour "
                                   "bar or an outline of");
        }
        image::writeImage(image.pixels, path);
        return;
    }
    annotation::ImageAnnotations(request, *image.drawn).write(image.pixels, path);
}

sg::Node::Ptr nodeNamed(const Scene& scene, const std::string& name) {
    sg::SearchAction search;
    search.setName(name);
    search.setSearchingAll(true);
    search.apply(*scene.root);
    if (search.paths().empty()) {
        throw nb::key_error((scene.name + ": no node named '" + name + "'").c_str());
    }
    return search.paths().front().tail();
}

} // namespace

void bindRendering(nb::module_& module) {
    nb::class_<Image>(module, "Image",
                      "A rendered image: premultiplied float RGBA, rows from the top.")
        .def_prop_ro("width", [](const Image& image) { return image.pixels.width(); })
        .def_prop_ro("height", [](const Image& image) { return image.pixels.height(); })
        .def_prop_ro("array", &pixelArray, nb::rv_policy::reference_internal,
                     "The pixels as a (height, width, 4) float32 array (no copy): premultiplied "
                     "RGBA (display values, as colour maps give them), what an EXR file of the "
                     "image holds.")
        .def(
            "__array__",
            [](nb::handle self, nb::handle dtype, nb::handle) {
                nb::object array = nb::cast(pixelArray(self), nb::rv_policy::reference_internal,
                                            self);
                return dtype.is_none() ? array : array.attr("astype")(dtype);
            },
            nb::arg("dtype").none() = nb::none(), nb::arg("copy").none() = nb::none())
        .def("save", &saveImage, nb::arg("path"), nb::arg("colorbar") = false,
             nb::arg("colorbar_position") = "right", nb::arg("outline") = false,
             "Writes the image as `texsplat render -o PATH` writes it: .png (8-bit, the colour "
             "values as they are) or .exr (float RGBA), by the extension; `colorbar` adds the "
             "colour bars beside it (--colorbar), at `colorbar_position` (right, left, top, "
             "bottom); `outline` the volumes' edges in white, all over the picture (--outline "
             "draws those behind the volume under it). The file appears whole or not at all.")
        .def(
            "_repr_png_",
            [](const Image& image) {
                const std::string png = image::pngBytes(image.pixels);
                return nb::bytes(png.data(), png.size());
            },
            "The PNG a notebook shows.")
        .def("__repr__", [](const Image& image) {
            return "<texsplat.Image " + image.pixels.sizeString() + ">";
        });

    nb::class_<Scene>(module, "Scene",
                      "A scene graph read from an Inventor file or made in Python, and its "
                      "animation time.")
        .def(nb::init<sg::Node::Ptr, std::string>(), nb::arg("root"), nb::arg("name") = "scene",
             "A scene of the graph under `root`; `name` names it in messages.")
        .def_prop_ro("root", [](const Scene& scene) { return scene.root; })
        .def_prop_ro("name", [](const Scene& scene) { return scene.name; })
        .def_prop_ro("time", [](const Scene& scene) { return scene.time->time(); },
                     "The time (seconds) the scene's engines show.")
        .def("__getitem__", &nodeNamed, nb::arg("name"), "The first node DEF'd `name`.")
        .def(
            "write",
            [](const Scene& scene, const std::filesystem::path& path) {
                nb::gil_scoped_release release;
                sg::WriteAction::writeFile(*scene.root, path.string());
            },
            nb::arg("path"), "Writes the scene as an Inventor file (atomically).")
        .def("__str__",
             [](const Scene& scene) { return sg::WriteAction::writeString(*scene.root); })
        .def("render", &renderScene, nb::arg("size") = std::pair<int, int>(512, 512),
             nb::kw_only(), nb::arg("backend") = "auto", nb::arg("time").none() = nb::none(),
             nb::arg("background").none() = nb::none(), nb::arg("azimuth") = 0.0f,
             nb::arg("elevation") = 0.0f, nb::arg("zoom") = 1.0f, nb::arg("threads") = 0,
             nb::arg("memory_limit").none() = nb::none(), nb::arg("progress").none() = nb::none(),
             "The scene rendered as `texsplat render SCENE --size WxH` renders it, to the same "
             "bits: framed by a camera around its bounding box when it has none (looking along "
             "-z), turned by `azimuth` and `elevation` (degrees) and magnified by `zoom`, at "
             "animation `time` (seconds; None: the scene's current time, 0 at first), drawn by "
             "`backend` ('auto', 'cpu', 'gl') over `background` ('black', 'white', "
             "'transparent' or (r, g, b[, a]) from 0 to 1), the CPU backend on `threads` "
             "threads (0: all). `memory_limit` is --memory-limit (bytes, or '512M', '8G'; None: the memory "
             "available). `progress` gets (step, fraction) during long steps (True: tqdm bars) "
             "and cancels by returning False. Ctrl-C cancels (KeyboardInterrupt).");

    module.def(
        "read_scene",
        [](const std::filesystem::path& source) {
            const std::string text = source.string();
            if (text.rfind("#Inventor", 0) == 0) {
                return Scene(sg::SceneReader::readString(text), "<string>");
            }
            sg::Node::Ptr root;
            {
                nb::gil_scoped_release release;
                root = sg::SceneReader::readFile(text);
            }
            return Scene(root, text);
        },
        nb::arg("source"),
        "Reads an Inventor scene file (`texsplat render`'s), or scene text: a string that starts "
        "with its header, `#Inventor V2.1 ascii` (parse_scene() names it).");
    module.def(
        "read_image",
        [](const std::filesystem::path& path) {
            nb::gil_scoped_release release;
            return Image{image::readImage(path.string()), nullptr};
        },
        nb::arg("path"),
        "Reads a .png or .exr image as texsplat compare reads it (PNG to premultiplied floats, "
        "each value over 255).");
    module.def(
        "parse_scene",
        [](const std::string& text, const std::string& name) {
            return Scene(sg::SceneReader::readString(text, name), name);
        },
        nb::arg("text"), nb::arg("name") = "<string>",
        "Reads a scene from Inventor text; `name` names it in messages.");
}

} // namespace texsplat::python
