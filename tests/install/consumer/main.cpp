// A tiny application built against the *installed* texsplat package: it reads a scene with the
// library's node types, writes it back, and evaluates the paper's kernel. It prints
// "texsplat consumer: ok" only when all of that worked.
#include "nodes/NodeTypes.h"
#include "nodes/kernel/CubicKernel.h"
#include "scenegraph/Node.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/WriteAction.h"

#include <cmath>
#include <cstdio>
#include <string>

int main() {
    using namespace texsplat;
    nodes::registerNodeTypes();
    const auto root = sg::SceneReader::readString(
        "#Inventor V2.1 ascii\nSeparator { Transform { translation 1 2 3 } }\n", "consumer.iv");
    const std::string written = sg::WriteAction::writeString(*root);
    if (written.find("translation 1 2 3") == std::string::npos) {
        std::fprintf(stderr, "texsplat consumer: the scene did not round-trip:\n%s", written.c_str());
        return 1;
    }
    const kernel::CubicKernel kernel = kernel::CubicKernel::paper();
    if (!(std::abs(kernel.support() - 1.556228) < 1e-9) || !(kernel.footprint(0.0) > 0.0)) {
        std::fprintf(stderr, "texsplat consumer: unexpected kernel\n");
        return 1;
    }
    std::printf("texsplat consumer: ok (footprint at 0: %.6f)\n", kernel.footprint(0.0));
    return 0;
}
