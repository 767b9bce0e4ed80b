#include "ro/Codec.h"

#include "ro/RegisterFile.h"

#include <cstdio>

namespace stellwerk::ro {
namespace {

// Request bytes (004 §3.2, 1-based as the document counts): 1 COMMAND, 2-3 ADRESSE, 4 JOB-ID, 5-8 DATA.
constexpr std::size_t HeaderSize = 4;
constexpr std::size_t MaxSize = 8;

std::string hexByte(unsigned value) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", value & 0xFF);
    return text;
}

std::string hexValue(std::uint32_t value) {
    char text[12];
    std::snprintf(text, sizeof text, "0x%X", value);
    return text;
}

DecodeError refuse(std::string reason, unsigned byte = 0) {
    return DecodeError{std::move(reason), byte};
}

bool fitsWidth(std::uint32_t value, Width width) {
    return width == Width::None || value <= maxValue(width);
}

std::optional<Request> requestOf(std::uint8_t command) {
    const unsigned width = command & 0x0F;
    const unsigned kind = command & 0xF0;
    if (width < 1 || width > 4 || (kind != 0x10 && kind != 0x20))
        return std::nullopt;
    Request request;
    request.kind = Request::Kind(kind);
    request.width = Width(width);
    return request;
}

Expected<Request, DecodeError> readData(Request request, std::span<const std::uint8_t> payload) {
    if (!request.isWrite())
        return request; // §3.2.5: a read carries no DATA; any padding is ignored
    const std::size_t needed = HeaderSize + byteCount(request.width);
    if (payload.size() < needed)
        return refuse(std::string(request.name()) + " needs " + std::to_string(needed) + " bytes, got " +
                          std::to_string(payload.size()),
                      unsigned(payload.size()) + 1);
    request.value = readLittleEndian(payload.subspan(HeaderSize));
    if (!fitsWidth(request.value, request.width))
        return refuse("DATA " + hexValue(request.value) + " does not fit a " +
                          std::string(widthName(request.width)) + " write",
                      5);
    return request;
}

Expected<Answer, DecodeError> decodeOk(std::span<const std::uint8_t> payload) {
    if (payload.size() < 3)
        return refuse("OK answer needs at least 3 bytes (answer, width, job id), got " +
                          std::to_string(payload.size()),
                      unsigned(payload.size()) + 1);
    if (payload[1] > 4)
        return refuse("width code " + hexByte(payload[1]) + " is not 0-4 (004 §3.5.1)", 2);
    OkAnswer ok{Width(payload[1]), payload[2],
                readLittleEndian(payload.subspan(3, std::min<std::size_t>(payload.size() - 3, 4)))};
    if (!fitsWidth(ok.value, ok.width))
        return refuse("data does not fit a " + std::string(widthName(ok.width)) + " answer", 4);
    return Answer(ok);
}

Expected<Answer, DecodeError> decodeDuplicate(std::span<const std::uint8_t> payload) {
    if (payload.size() < 2)
        return refuse("0xFD answer without job id (004 §3.5.2.1)", 2);
    if (payload.size() > 6)
        return refuse("0xFD answer carries at most 4 data bytes, got " + std::to_string(payload.size() - 2),
                      7);
    const std::uint8_t dataBytes = std::uint8_t(payload.size() - 2);
    return Answer(DuplicateJobAnswer{payload[1], dataBytes, readLittleEndian(payload.subspan(2))});
}

} // namespace

Payload encode(const Request& request, ReadRequestSize readSize) {
    Payload payload;
    payload.size = request.isWrite() ? MaxSize : std::uint8_t(readSize);
    payload.bytes[0] = request.command();
    writeLittleEndian(std::span(payload.bytes).subspan(1, 2), request.address);
    payload.bytes[3] = request.job;
    if (request.isWrite())
        writeLittleEndian(std::span(payload.bytes).subspan(HeaderSize, 4), request.value);
    return payload;
}

Expected<Request, DecodeError> decodeRequest(std::span<const std::uint8_t> payload) {
    if (payload.empty())
        return refuse("empty payload");
    if (payload.size() > MaxSize)
        return refuse("a request has at most 8 bytes, got " + std::to_string(payload.size()));
    auto request = requestOf(payload[0]);
    if (!request)
        return refuse(
            "COMMAND " + hexByte(payload[0]) + " is none of 0x11-0x14, 0x21-0x24 (004 §3.2.1, §3.2.2)", 1);
    if (payload.size() < HeaderSize)
        return refuse("a request needs at least 4 bytes (command, address, job id), got " +
                          std::to_string(payload.size()),
                      unsigned(payload.size()) + 1);
    request->address = std::uint16_t(readLittleEndian(payload.subspan(1, 2)));
    request->job = payload[3];
    return readData(*request, payload);
}

Payload encode(const Answer& answer) {
    Payload payload;
    if (const auto* ok = std::get_if<OkAnswer>(&answer)) {
        payload.size = 7;
        payload.bytes = {answer_code::Ok, std::uint8_t(ok->width), ok->job};
        writeLittleEndian(std::span(payload.bytes).subspan(3, 4), ok->value);
    } else if (const auto* duplicate = std::get_if<DuplicateJobAnswer>(&answer)) {
        const std::uint8_t dataBytes = std::min<std::uint8_t>(duplicate->dataBytes, 4);
        payload.size = std::uint8_t(2 + dataBytes);
        payload.bytes = {answer_code::DuplicateJob, duplicate->job};
        writeLittleEndian(std::span(payload.bytes).subspan(2, dataBytes), duplicate->value);
    } else {
        payload.size = 1;
        payload.bytes = {answer_code::InvalidCommand};
    }
    return payload;
}

Expected<Answer, DecodeError> decodeAnswer(std::span<const std::uint8_t> payload) {
    if (payload.empty())
        return refuse("empty payload");
    if (payload.size() > MaxSize)
        return refuse("an answer has at most 8 bytes, got " + std::to_string(payload.size()));
    switch (payload[0]) {
    case answer_code::Ok:
        return decodeOk(payload);
    case answer_code::DuplicateJob:
        return decodeDuplicate(payload);
    case answer_code::InvalidCommand:
        return Answer(InvalidCommandAnswer{});
    default:
        return refuse("answer code " + hexByte(payload[0]) + " is none of 0x01, 0xFD, 0xFE (004 §3.5)", 1);
    }
}

} // namespace stellwerk::ro
