#include "nodes/detail/JsonNesting.h"

#include "scenegraph/Error.h"

#include <cstddef>

namespace texsplat::nodes::detail {

void checkJsonNesting(std::string_view json, const std::string& where) {
    int depth = 0;
    bool inString = false;
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < json.size(); ++i, ++column) {
        const char c = json[i];
        if (inString) {
            if (c == '\\') {
                ++i; // the escaped character cannot end the string
                ++column;
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonNesting) {
                throw ParseError(where + ":" + std::to_string(line) + ":" +
                                 std::to_string(column) +
                                 ": JSON objects and arrays nested deeper than the limit of " +
                                 std::to_string(kMaxJsonNesting) + " levels");
            }
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        } else if (c == '\n') {
            ++line;
            column = 0;
        }
    }
}

} // namespace texsplat::nodes::detail
