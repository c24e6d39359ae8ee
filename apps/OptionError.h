#pragma once

#include "scenegraph/Error.h"

#include <string>

namespace texsplat::apps {

/// @brief Runs `parse` (a parser or check of one command-line option's value) and returns what
/// it returns; a DataError it throws is thrown again with the option's name in front
/// ("--spacing: ..."), as main prints it.
template <class Parse> auto withOption(const char* option, Parse&& parse) {
    try {
        return parse();
    } catch (const DataError& error) {
        throw DataError(std::string(option) + ": " + error.what());
    }
}

} // namespace texsplat::apps
