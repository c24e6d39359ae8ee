#pragma once

#include <string>

namespace texsplat::sg {

/// @brief The scene-file reference of every type in the NodeRegistry, as Markdown: for each
/// node and engine type (sorted by name) its kind, parent, whether it takes children, and a
/// table of its fields with types, defaults and meanings (NodeType::fieldDescription(); engines:
/// inputs and outputs).
///
/// Generated from the types' own field declarations, so it cannot drift from the code;
/// `texsplat info --reference --update docs/scene-files.md` puts it into the documentation.
std::string sceneReferenceMarkdown();

/// @brief Begin marker of the generated section in a Markdown document.
inline constexpr const char* kGeneratedReferenceBegin =
    "<!-- BEGIN GENERATED REFERENCE (texsplat info --reference): do not edit by hand -->";

/// @brief End marker of the generated section.
inline constexpr const char* kGeneratedReferenceEnd = "<!-- END GENERATED REFERENCE -->";

/// @brief `document` with the text between the generated-section markers replaced by
/// `generated`. Throws DataError("documentName: ...") when the markers are missing or out of
/// order.
std::string replaceGeneratedReference(const std::string& document, const std::string& generated,
                                      const std::string& documentName);

} // namespace texsplat::sg
