#include "cs2config/LocomotivePicture.h"

#include "cs2config/Text.h"

#include <array>
#include <cstdint>

namespace stellwerk::cs2config::picture {

namespace {

constexpr std::string_view Extension = ".png";
constexpr std::array<unsigned char, 8> PngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr std::string_view IendChunk("\0\0\0\0IEND\xAE\x42\x60\x82", 12);

// The last segment of a path written with '/' or with the CS3's "#2F" escape.
std::string_view lastSegment(std::string_view icon) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < icon.size(); ++i) {
        if (icon[i] == '/')
            start = i + 1;
        else if (icon[i] == '#' && i + 2 < icon.size() && icon[i + 1] == '2' &&
                 (icon[i + 2] == 'F' || icon[i + 2] == 'f'))
            start = i + 3;
    }
    return icon.substr(start);
}

bool safeName(std::string_view name) {
    if (name.empty() || name == "." || name == ".." || name.size() > MaxNameBytes || !isValidUtf8(name))
        return false;
    for (const char c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F || c == '\\' || c == '#' || c == '?')
            return false;
    return true;
}

bool endsWithExtension(std::string_view name) {
    if (name.size() < Extension.size())
        return false;
    const std::string_view tail = name.substr(name.size() - Extension.size());
    for (std::size_t i = 0; i < tail.size(); ++i)
        if ((tail[i] | 0x20) != Extension[i])
            return false;
    return true;
}

std::uint32_t bigEndian(std::string_view bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i)
        value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

} // namespace

std::optional<std::string> fileName(std::string_view icon) {
    const std::string_view name = lastSegment(icon);
    if (!safeName(name))
        return std::nullopt;
    if (!endsWithExtension(name))
        return std::string(name) + std::string(Extension);
    if (name.size() == Extension.size()) // ".png": an extension without a name
        return std::nullopt;
    return std::string(name);
}

std::optional<std::string> problem(std::string_view bytes, Size* size) {
    if (bytes.size() > MaxBytes)
        return std::to_string(bytes.size()) + " bytes, more than the " + std::to_string(MaxBytes) +
               " a locomotive picture may have";
    // Signature, then the IHDR chunk: length 13, "IHDR", width, height (PNG specification 5.2, 11.2.2).
    for (std::size_t i = 0; i < PngSignature.size() && i < bytes.size(); ++i)
        if (static_cast<unsigned char>(bytes[i]) != PngSignature[i])
            return std::string("not a PNG picture");
    if (bytes.size() < 8 + 8 + 13 + 4 + IendChunk.size())
        return std::string("not a PNG picture (too short)");
    if (bigEndian(bytes, 8) != 13 || bytes.substr(12, 4) != "IHDR")
        return std::string("a damaged PNG picture (no IHDR header)");
    const std::uint32_t width = bigEndian(bytes, 16);
    const std::uint32_t height = bigEndian(bytes, 20);
    if (width == 0 || height == 0)
        return std::string("a damaged PNG picture (no pixels)");
    if (width > MaxSide || height > MaxSide)
        return std::to_string(width) + " x " + std::to_string(height) + " pixels, larger than " +
               std::to_string(MaxSide) + " x " + std::to_string(MaxSide);
    // A transfer cut short keeps a sound header: the IEND chunk (length 0, type, CRC) must close it.
    if (!bytes.ends_with(IendChunk))
        return std::string("a cut-off PNG picture (no IEND at its end)");
    if (size)
        *size = {static_cast<int>(width), static_cast<int>(height)};
    return std::nullopt;
}

} // namespace stellwerk::cs2config::picture
