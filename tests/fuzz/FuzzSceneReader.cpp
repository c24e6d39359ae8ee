// libFuzzer target for SceneReader: any input either reads or throws texsplat::Error (never
// crashes, hangs or trips a sanitizer), and whatever reads must write and read back to the same
// text: write(read(write(graph))) == write(graph).

#include "scenegraph/Error.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"
#include "tests/scenegraph/SceneTestSupport.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool registered = [] {
        texsplat::sg::test::registerSceneTestTypes();
        return true;
    }();
    (void)registered;
    using texsplat::sg::SceneReader;
    using texsplat::sg::WriteAction;
    std::shared_ptr<texsplat::sg::Node> root;
    try {
        root = SceneReader::readString(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.iv");
    } catch (const texsplat::Error&) {
        return 0;
    }
    const std::string written = WriteAction::writeString(*root);
    std::string rewritten;
    try {
        rewritten = WriteAction::writeString(*SceneReader::readString(written, "written.iv"));
    } catch (const texsplat::Error& error) {
        std::fprintf(stderr, "written scene does not read back: %s\n%s\n", error.what(),
                     written.c_str());
        std::abort();
    }
    if (rewritten != written) {
        std::fprintf(stderr, "round trip changed the scene:\n%s\n---\n%s\n", written.c_str(),
                     rewritten.c_str());
        std::abort();
    }
    return 0;
}
