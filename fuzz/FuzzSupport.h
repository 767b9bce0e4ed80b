// What every fuzz target shares: the libFuzzer entry point's declaration, a check that aborts with a
// message (a finding), a reader for the fuzzer's bytes, and the JSON and text properties the targets
// assert about Stellwerk's output.
#pragma once

#include "cs2config/Text.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace stellwerk::fuzz {

// A broken invariant: says which and stops, so that libFuzzer stores the input as a crash.
[[noreturn]] inline void fail(const char* what, std::string_view detail = {}) {
    std::fprintf(stderr, "FUZZ INVARIANT BROKEN: %s\n%.*s\n", what, int(detail.size()), detail.data());
    std::abort();
}

inline void check(bool holds, const char* what, std::string_view detail = {}) {
    if (!holds)
        fail(what, detail);
}

// Takes the fuzzer's bytes apart: single bytes for choices first, the rest as the payload.
class FuzzInput {
public:
    FuzzInput(const std::uint8_t* data, std::size_t size) : bytes_(data, size) {}
    std::uint8_t byte() {
        if (bytes_.empty())
            return 0;
        const std::uint8_t value = bytes_.front();
        bytes_ = bytes_.subspan(1);
        return value;
    }
    std::span<const std::uint8_t> take(std::size_t count) {
        const auto part = bytes_.first(std::min(count, bytes_.size()));
        bytes_ = bytes_.subspan(part.size());
        return part;
    }
    std::span<const std::uint8_t> rest() const { return bytes_; }
    std::string_view restText() const {
        return {reinterpret_cast<const char*>(bytes_.data()), bytes_.size()};
    }
    bool empty() const { return bytes_.empty(); }

private:
    std::span<const std::uint8_t> bytes_;
};

// A frame report's text and JSON, made once: the targets check both and compare them with a description.
struct ReportStrings {
    std::string text;
    std::string json;

    template <class Report>
    static ReportStrings of(const Report& report) {
        return {report.text(), report.json()};
    }
};

// True when `text` is one JSON document in valid UTF-8 whose only raw control bytes are the line ends
// of its indentation (`allowNewlines`): what any JSON consumer can read.
inline bool isJsonDocument(std::string_view text, bool allowNewlines) {
    if (!cs2config::isValidUtf8(text))
        return false;
    for (char c : text)
        if (static_cast<unsigned char>(c) < 0x20 && !(allowNewlines && (c == '\n' || c == ' ')))
            return false;
    QJsonParseError error{};
    QJsonDocument::fromJson(QByteArray(text.data(), qsizetype(text.size())), &error);
    return error.error == QJsonParseError::NoError;
}

// True when `text` is printable ASCII only (0x20..0x7E): what the codecs' frame reports promise.
inline bool isPrintableAscii(std::string_view text) {
    for (const char c : text)
        if (c < 0x20 || c > 0x7E)
            return false;
    return true;
}

// True when `text` can go to a terminal as it is: valid UTF-8 without control characters (C0, DEL, C1).
inline bool isPrintableText(std::string_view text) {
    if (!cs2config::isValidUtf8(text))
        return false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x20 || byte == 0x7F)
            return false;
        // C1 controls U+0080..U+009F are C2 80..C2 9F in UTF-8.
        if (byte == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) < 0xA0)
            return false;
    }
    return true;
}

} // namespace stellwerk::fuzz
