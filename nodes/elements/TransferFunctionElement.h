#pragma once

namespace texsplat::nodes {

class TransferFunction;

/// @brief State element: the TransferFunction met last, which the splat nodes that follow use
/// to classify their volume.
struct TransferFunctionElement {
    /// @brief The transfer function, or nullptr before any (non-owning: valid during the
    /// traversal).
    const TransferFunction* transferFunction = nullptr;
};

} // namespace texsplat::nodes
