#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// Writes JSON for `stellwerk-cli cs2 json` and tests: objects and arrays with commas placed for
// the caller, strings escaped, compact or indented by two spaces.
class JsonWriter {
public:
    explicit JsonWriter(bool indented = true) : indented_(indented) {}

    JsonWriter& beginObject(std::string_view key = {});
    JsonWriter& endObject();
    JsonWriter& beginArray(std::string_view key = {});
    JsonWriter& endArray();

    JsonWriter& value(std::string_view key, std::string_view text);
    JsonWriter& value(std::string_view key, const char* text) { return value(key, std::string_view(text)); }
    JsonWriter& value(std::string_view key, std::int64_t number);
    JsonWriter& value(std::string_view key, int number) { return value(key, std::int64_t{number}); }
    JsonWriter& value(std::string_view key, bool flag);
    JsonWriter& null(std::string_view key);
    // Array elements: call with an empty key.

    const std::string& text() const { return out_; }

    static std::string quoted(std::string_view text);

private:
    void prefix(std::string_view key);
    void newline();

    bool indented_;
    std::string out_;
    std::vector<bool> first_; // per open container: no member written yet
};

} // namespace stellwerk::cs2config
