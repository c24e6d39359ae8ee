#include "scenegraph/gl/LightScale.h"

#include <cstdio>

namespace texsplat::gl {

std::string withLightScale(const char* source) {
    std::string text(source);
    char declaration[64];
    // %a writes the float exactly (0x1p-64), which GLSL 3.30 cannot read: 17 digits round back.
    std::snprintf(declaration, sizeof declaration, "const float lightScale = %.17g;\n",
                  double(kLightScale));
    text.insert(text.find('\n') + 1, declaration);
    return text;
}

} // namespace texsplat::gl
