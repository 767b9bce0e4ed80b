// A locomotive's `.icon` value and the bytes a station serves as its picture (cs2config::picture).
// Invariants: a file name is safe to join to a folder and a URL (one segment, valid UTF-8, no control
// character, backslash, '#' or '?', ends in ".png", bounded); bytes accepted as a picture are at most
// MaxBytes, end in the IEND chunk and their header's size is within MaxSide.
#include "FuzzSupport.h"
#include "cs2config/LocomotivePicture.h"

using namespace stellwerk;
namespace picture = stellwerk::cs2config::picture;

namespace {

void checkName(std::string_view icon) {
    const std::optional<std::string> name = picture::fileName(icon);
    if (!name)
        return;
    fuzz::check(cs2config::isValidUtf8(*name), "a picture name is not UTF-8", *name);
    fuzz::check(name->size() >= 5 && name->size() <= picture::MaxNameBytes + 4, "a picture name's length",
                *name);
    fuzz::check(*name != ".png" && name->find_first_of("/\\#?") == std::string::npos,
                "a picture name leaves its folder or URL", *name);
    for (const char c : *name)
        fuzz::check(static_cast<unsigned char>(c) >= 0x20 && c != 0x7F, "a control byte in a picture name",
                    *name);
    std::string tail = name->substr(name->size() - 4);
    for (char& c : tail)
        c = static_cast<char>(c | 0x20);
    fuzz::check(tail == ".png", "a picture name without .png", *name);
}

void checkBytes(std::string_view bytes) {
    picture::Size size;
    if (picture::problem(bytes, &size))
        return;
    fuzz::check(bytes.size() <= picture::MaxBytes, "a picture over the byte limit accepted");
    fuzz::check(bytes.ends_with(std::string_view("\0\0\0\0IEND\xAE\x42\x60\x82", 12)),
                "a picture cut off before its IEND chunk accepted");
    fuzz::check(size.width >= 1 && size.width <= picture::MaxSide && size.height >= 1 &&
                    size.height <= picture::MaxSide,
                "a picture size outside the limits accepted");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > picture::MaxBytes + 16)
        return -1;
    fuzz::FuzzInput input(data, size);
    const std::string_view text = input.restText();
    checkName(text);
    checkBytes(text);
    return 0;
}
