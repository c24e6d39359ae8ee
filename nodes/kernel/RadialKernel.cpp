#include "nodes/kernel/RadialKernel.h"

#include <cmath>

namespace texsplat::kernel {

double RadialKernel::value(double r) const {
    if (std::isnan(r))
        return r;
    const double distance = std::fabs(r);
    if (distance >= support())
        return 0.0;
    return static_cast<double>(profile(distance));
}

} // namespace texsplat::kernel
