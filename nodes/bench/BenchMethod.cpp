#include "nodes/bench/BenchMethod.h"

#include "nodes/CombinedSplat.h"
#include "nodes/GaussianSplat.h"
#include "nodes/TextureSplat.h"
#include "nodes/VectorSplat.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string_view>

namespace texsplat::bench {
namespace {

struct KindName {
    const char* name;
    BenchMethod::Kind kind;
};

constexpr KindName kKindNames[] = {{"texture", BenchMethod::Kind::TexturePaper},
                                   {"texture-gaussian", BenchMethod::Kind::TextureGaussian},
                                   {"polygon", BenchMethod::Kind::PolygonGaussian},
                                   {"vector", BenchMethod::Kind::Vector},
                                   {"combined", BenchMethod::Kind::Combined}};

[[noreturn]] void unknownMethod(const std::string& name) {
    throw DataError("unknown method '" + name +
                    "' (expected texture, texture-gaussian, polygon, vector or combined, optionally "
                    "with +shade and @FRACTION, e.g. texture+shade@0.1)");
}

} // namespace

BenchMethod BenchMethod::fromName(const std::string& name) {
    const std::size_t at = name.find('@');
    std::string kindName = name.substr(0, at);
    constexpr std::string_view kShade = "+shade";
    const bool shaded = kindName.size() > kShade.size() &&
                        kindName.compare(kindName.size() - kShade.size(), kShade.size(),
                                         kShade) == 0;
    if (shaded) {
        kindName.resize(kindName.size() - kShade.size());
    }
    const auto entry = std::find_if(std::begin(kKindNames), std::end(kKindNames),
                                    [&](const KindName& k) { return kindName == k.name; });
    if (entry == std::end(kKindNames) || (shaded && entry->kind == Kind::Vector)) {
        unknownMethod(name);
    }
    BenchMethod method;
    method.kind = entry->kind;
    method.shaded = shaded;
    if (at != std::string::npos) {
        const std::string fraction = name.substr(at + 1);
        char* end = nullptr;
        method.budget = std::strtod(fraction.c_str(), &end);
        if (fraction.empty() || end != fraction.c_str() + fraction.size() ||
            !(method.budget > 0.0 && method.budget < 1.0)) {
            unknownMethod(name);
        }
    }
    return method;
}

std::vector<BenchMethod> BenchMethod::parseList(const std::string& names) {
    std::vector<BenchMethod> methods;
    std::istringstream stream(names);
    std::string name;
    while (std::getline(stream, name, ',')) {
        methods.push_back(fromName(name));
    }
    if (methods.empty()) {
        throw DataError("empty method list");
    }
    return methods;
}

std::string BenchMethod::name() const {
    std::string text;
    for (const KindName& entry : kKindNames) {
        if (entry.kind == kind) {
            text = entry.name;
        }
    }
    if (shaded) {
        text += "+shade";
    }
    if (budget > 0.0) {
        char fraction[32];
        std::snprintf(fraction, sizeof fraction, "@%g", budget);
        text += fraction;
    }
    return text;
}

sg::Node::Ptr BenchMethod::makeNode(std::size_t fullSplats) const {
    nodes::ScalarSplat::Ptr node;
    if (kind == Kind::PolygonGaussian) {
        node = nodes::GaussianSplat::create();
    } else if (kind == Kind::Vector) {
        node = nodes::VectorSplat::create();
    } else if (kind == Kind::Combined) {
        node = nodes::CombinedSplat::create();
    } else {
        nodes::TextureSplat::Ptr texture = nodes::TextureSplat::create();
        texture->kernel.setValue(kind == Kind::TextureGaussian ? nodes::SplatKernel::Gaussian
                                                               : nodes::SplatKernel::Paper);
        node = texture;
    }
    if (budget > 0.0) {
        const double splats = std::clamp(std::round(budget * static_cast<double>(fullSplats)), 1.0,
                                         static_cast<double>(INT_MAX));
        node->maxSplats.setValue(static_cast<int>(splats));
    }
    return node;
}

} // namespace texsplat::bench
