#pragma once

#include "nodes/volume/Progress.h"
#include "scenegraph/Error.h"
#include "scenegraph/FieldContainer.h"
#include "scenegraph/WorkProgress.h"

#include <string>

namespace texsplat::nodes::detail {

/// @brief How the nodes' error messages name a node: "VolumeData 'cloud'", or "VolumeData"
/// when it has no name.
inline std::string nodeContext(const sg::FieldContainer& node) {
    return node.name().empty() ? node.typeName() : node.typeName() + " '" + node.name() + "'";
}

/// @brief Runs `load` and rethrows any texsplat::Error it throws as the same class, with
/// "<node context>: " in front, so the message says which node failed as well as where the
/// loader failed ("VolumeData 'cloud': cloud.raw: cannot open file ...").
template <class Load> auto withNodeContext(const sg::FieldContainer& node, Load&& load) {
    try {
        return load();
    } catch (const ParseError& error) {
        throw ParseError(nodeContext(node) + ": " + error.what());
    } catch (const IoError& error) {
        throw IoError(nodeContext(node) + ": " + error.what());
    } catch (const DataError& error) {
        throw DataError(nodeContext(node) + ": " + error.what());
    } catch (const ResourceError& error) {
        throw ResourceError(nodeContext(node) + ": " + error.what());
    } catch (const GlError& error) {
        throw GlError(nodeContext(node) + ": " + error.what());
    } catch (const volume::LoadCancelled& error) {
        throw volume::LoadCancelled(nodeContext(node) + ": " + error.what());
    } catch (const sg::Cancelled& error) {
        throw sg::Cancelled(nodeContext(node) + ": " + error.what());
    } catch (const Error& error) {
        throw Error(nodeContext(node) + ": " + error.what());
    }
}

} // namespace texsplat::nodes::detail
