#pragma once

namespace texsplat::image {

/// @brief A rectangle of pixels: columns [x, x + width), rows [y, y + height), with (0, 0) the
/// top-left pixel of the image (rows are counted top row first, as in the image files).
struct ImageRegion {
    int x = 0;      ///< first column
    int y = 0;      ///< first row (0 is the top row)
    int width = 0;  ///< number of columns
    int height = 0; ///< number of rows
};

} // namespace texsplat::image
