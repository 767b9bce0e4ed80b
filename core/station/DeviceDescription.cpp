#include "station/DeviceDescription.h"

#include <QString>
#include <cmath>

namespace stellwerk::station {
namespace {

// The text without control characters (C0, DEL, C1): a device on the bus must not be able to send
// terminal escapes or line breaks into what the CLI and the UI show.
QString printable(const QString& text) {
    QString out;
    out.reserve(text.size());
    for (const QChar c : text)
        if (c.category() != QChar::Other_Control)
            out += c;
    return out;
}

// Reads fixed fields and NUL-terminated strings from a status-data block, with bounds checks.
class BlockReader {
public:
    explicit BlockReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    bool has(std::size_t count) const { return pos_ + count <= bytes_.size(); }
    std::uint8_t u8() { return bytes_[pos_++]; }
    std::uint16_t u16() {
        const auto value = std::uint16_t(bytes_[pos_] << 8 | bytes_[pos_ + 1]);
        pos_ += 2;
        return value;
    }
    std::uint32_t u32() { return std::uint32_t(u16()) << 16 | u16(); }
    // A fixed-size ASCII field (the article number): up to the first NUL, printable characters only.
    std::string fixed(std::size_t count) {
        std::string text;
        for (std::size_t i = 0; i < count && bytes_[pos_ + i] != 0; ++i)
            if (bytes_[pos_ + i] > 0x20 && bytes_[pos_ + i] < 0x7F)
                text += char(bytes_[pos_ + i]);
        pos_ += count;
        return text;
    }
    // UTF-8, or Latin-1 when the bytes are not valid UTF-8, without control characters; empty at the
    // end of the block.
    std::string text() {
        std::size_t end = pos_;
        while (end < bytes_.size() && bytes_[end] != 0)
            ++end;
        const auto* data = reinterpret_cast<const char*>(bytes_.data() + pos_);
        const auto size = qsizetype(end - pos_);
        pos_ = std::min(end + 1, bytes_.size());
        QString utf8 = QString::fromUtf8(data, size);
        if (utf8.contains(QChar::ReplacementCharacter))
            utf8 = QString::fromLatin1(data, size);
        return printable(utf8).toStdString();
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_ = 0;
};

double labelValue(const std::string& label) {
    return QString::fromStdString(label).trimmed().toDouble();
}

int labelDecimals(const std::string& label) {
    const auto dot = label.find('.');
    return dot == std::string::npos ? 0 : int(label.size() - dot - 1);
}

} // namespace

double ReadingChannel::scaled(std::uint16_t raw) const {
    const double start = labelValue(startLabel);
    const double end = labelValue(endLabel);
    const double span = double(rangeEnds[3]) - double(zero);
    if (span == 0)
        return start;
    return start + (double(raw) - double(zero)) * (end - start) / span;
}

int ReadingChannel::decimals() const {
    return std::max(labelDecimals(startLabel), labelDecimals(endLabel));
}

std::optional<DeviceSummary> parseDeviceSummary(std::span<const std::uint8_t> bytes) {
    BlockReader in(bytes);
    if (!in.has(16))
        return std::nullopt;
    DeviceSummary summary;
    summary.readingCount = in.u8();
    summary.configCount = in.u8();
    in.u16();
    summary.serial = in.u32();
    summary.article = in.fixed(8);
    summary.name = in.text();
    summary.nickname = in.text();
    return summary;
}

std::optional<ReadingChannel> parseReadingChannel(std::uint8_t index, std::span<const std::uint8_t> bytes) {
    BlockReader in(bytes);
    if (!in.has(16))
        return std::nullopt;
    ReadingChannel reading;
    reading.index = index;
    reading.channel = in.u8();
    reading.power = std::int8_t(in.u8());
    for (auto& colour : reading.colours)
        colour = in.u8();
    reading.zero = in.u16();
    for (auto& end : reading.rangeEnds)
        end = in.u16();
    reading.name = in.text();
    reading.startLabel = in.text();
    reading.endLabel = in.text();
    reading.unit = in.text();
    return reading;
}

std::optional<ConfigChannel> parseConfigChannel(std::uint8_t index, std::span<const std::uint8_t> bytes) {
    BlockReader in(bytes);
    if (!in.has(8))
        return std::nullopt;
    ConfigChannel config;
    config.index = index;
    config.channel = in.u8();
    const std::uint8_t kind = in.u8();
    if (kind == 1) {
        config.kind = ConfigChannel::Kind::List;
        const std::uint8_t count = in.u8();
        config.current = in.u8();
        in.u32();
        config.title = in.text();
        for (std::uint8_t i = 0; i < count; ++i)
            config.options.push_back(in.text());
    } else if (kind == 2) {
        config.kind = ConfigChannel::Kind::Number;
        config.minimum = in.u16();
        config.maximum = in.u16();
        config.value = in.u16();
        config.title = in.text();
        config.startLabel = in.text();
        config.endLabel = in.text();
        config.unit = in.text();
    }
    return config;
}

} // namespace stellwerk::station
