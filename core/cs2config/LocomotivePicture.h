#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace stellwerk::cs2config {

// Where a locomotive's picture is and whether bytes that claim to be one can be shown. The `.icon` value
// names the picture: a CS2 writes the bare name ("BR 218"), a CS3 a path on its own disk
// ("/usr/local/cs3/lokicons/mSD3_Logo", in its files with "#2F" for '/'). The picture is the PNG file of
// that name in the station's /icons/ folder (over HTTP) or in the layout's icons folder.
namespace picture {

// What Stellwerk accepts as a picture: no station writes bigger ones.
inline constexpr std::size_t MaxBytes = 256 * 1024;
inline constexpr int MaxSide = 1024;
inline constexpr std::size_t MaxNameBytes = 128;

// The picture's file name ("BR 218.png", "mSD3_Logo.png"), or nullopt when the value names none or a
// name that could leave the icons folder or the URL: empty, ".", "..", a backslash, a control
// character, invalid UTF-8, or longer than MaxNameBytes.
std::optional<std::string> fileName(std::string_view icon);

// The size of a PNG picture, read from its header.
struct Size {
    int width = 0;
    int height = 0;
};

// Why these bytes are not a picture to show ("not a PNG picture", "4000 x 80 pixels, larger than
// 1024 x 1024", "a cut-off PNG picture"), or nullopt when the header is sound and the IEND chunk ends
// the bytes; `size` receives the header's size. The pixels themselves are the image decoder's business.
std::optional<std::string> problem(std::string_view bytes, Size* size = nullptr);

} // namespace picture

} // namespace stellwerk::cs2config
