#pragma once

#include "mcan/Id.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <variant>
#include <vector>

namespace stellwerk::mcan {

// Where a session frame comes from and which object it is about: the id's priority, object handle and
// sender node. Its cmd is fixed by the message type.
struct Address {
    std::uint8_t prio = prio::Data;
    std::uint16_t handle = 0;
    std::uint8_t node = 0;
};

// Up to eight bytes kept as sent, for fields the documents do not explain.
struct Bytes {
    std::uint8_t size = 0;
    std::array<std::uint8_t, 8> data{};
};

// ---- Login (Anmeldung, document 6.2; notes B§2.1 and B§3.1), node 126 ---------------------------------

// Stages 0..3 from the slave: one byte of its UID in the id, no data (so that two slaves that send the
// same id at once cannot spoil each other's data).
struct LoginRequest {
    static constexpr std::string_view name = "mcan.login-request";
    std::uint8_t stage = 0;
    std::uint8_t uidByte = 0;
    std::uint8_t mid = 0;
};

// The master's answer to stages 0..3: the UID byte echoed; stage 0 hands out the MID and carries the
// master's UID and type, stages 1..3 vendor and version bytes whose meaning is unclear.
struct LoginReply {
    static constexpr std::string_view name = "mcan.login-reply";
    std::uint8_t stage = 0;
    std::uint8_t uidByte = 0;
    std::uint8_t mid = 0;
    std::array<std::uint8_t, 8> data{};
};

// Stages 4..7 from the slave, sent back to back: its whole UID (stage 4), vendor, hardware and software.
struct LoginDetails {
    static constexpr std::string_view name = "mcan.login-details";
    std::uint8_t stage = 4;
    std::uint8_t mid = 0;
    std::array<std::uint8_t, 8> data{};
};

// The master's answer to stage 7: the slave's node (the master's is one less) and its start handle.
// `flashMode` must stay false: it sends an MS1 into its boot loader, which only a firmware flash ends.
struct LoginGrant {
    static constexpr std::string_view name = "mcan.login-grant";
    std::uint8_t mid = 0;
    std::uint32_t slaveUid = 0;
    std::uint16_t startHandle = 0;
    std::uint8_t node = 0;
    bool multiSlave = true;
    std::uint8_t flags = 0; // Data[7]; bit 0 = flash mode
};

// ---- Session frames after the login (document 6.3 to 7.7; notes B§2.2) ---------------------------------

// 6.1: priority 000, node 0, eight zero bytes; sent only by an MS1 master. Meaning unclear.
struct BusBusy {
    static constexpr std::string_view name = "mcan.bus-busy";
    std::uint8_t dlc = 8;
};

// 6.4: the slave asks for its slave-description (SD) handle, on its start handle: `40 node`.
struct SdHandleRequest {
    static constexpr std::string_view name = "mcan.sd-handle-request";
    Address at;
    std::uint8_t slaveNode = 0;
};

// 6.4: `40 node 00 00 SDh SDl 00 01`.
struct SdHandleAnswer {
    static constexpr std::string_view name = "mcan.sd-handle-answer";
    Address at;
    std::uint8_t slaveNode = 0;
    std::uint16_t sdHandle = 0;
};

// 6.4.1: the master asks how many locomotives the slave's stack holds, on the SD handle: `41 00 00 00`.
struct StackSizeRequest {
    static constexpr std::string_view name = "mcan.stack-size-request";
    Address at;
};

// 6.4.1: `41 00 00 00 hi lo` (0x000A on an MS1).
struct StackSizeAnswer {
    static constexpr std::string_view name = "mcan.stack-size-answer";
    Address at;
    std::uint16_t size = 0;
};

// 6.4.2 / 6.7.4: four characters of a name from `offset` (0, 4, 8, 12) asked for: the slave's name on the
// SD handle (the master asks), a locomotive's on its handle (the slave asks). `02 00 00 offset`.
struct NameRequest {
    static constexpr std::string_view name = "mcan.name-request";
    Address at;
    std::uint8_t offset = 0;
};

// 6.4.2 / 6.7.4 / 7.5: `02 00 00 offset c0 c1 c2 c3`, NUL-terminated, the last one may be shorter. Also
// the master's rename of a slave. `marker` is Data[1] (6.7.4 prints 02 for a first answer, the trace 00).
struct NameSegment {
    static constexpr std::string_view name = "mcan.name-segment";
    Address at;
    std::uint8_t offset = 0;
    std::uint8_t count = 4; // characters carried: 1..4
    std::array<char, 4> chars{};
    std::uint8_t marker = 0;
};

// 6.5: the slave asks for the system-status (SY) handle, on its start handle: `03 00`.
struct SyHandleRequest {
    static constexpr std::string_view name = "mcan.sy-handle-request";
    Address at;
};

// 6.5: `03 00 00 00 SYh SYl 00 01` in the trace (`40 node 00 00 ...` in the document's table).
struct SyHandleAnswer {
    static constexpr std::string_view name = "mcan.sy-handle-answer";
    Address at;
    std::uint16_t syHandle = 0;
    std::uint8_t lead = 0x03;   // Data[0]: 03 (trace) or 40 (table)
    std::uint8_t second = 0x00; // Data[1]: 00 or the slave's node
};

// 6.6: status index `index` (1, 2, ...) asked for its type (`index 01`) or its value (`index 00`), on
// the SY handle.
struct StatusQuery {
    static constexpr std::string_view name = "mcan.status-query";
    Address at;
    std::uint8_t index = 1;
    bool type = true; // false: the value
};

// 6.6: `index 01 type`: 01 stop/go, 02 short circuit, 03 (MS1 master only, unknown), 04 mfx registration.
struct StatusType {
    static constexpr std::string_view name = "mcan.status-type";
    Address at;
    std::uint8_t index = 1;
    std::uint8_t type = 1;
};

// 6.6: the bare echo `index 01`: the list has no index `index`.
struct StatusListEnd {
    static constexpr std::string_view name = "mcan.status-list-end";
    Address at;
    std::uint8_t index = 1;
};

// 6.6 / 7.4: `index 00 value`: the master's answer or change (priority 100), or the slave's stop key
// (priority 010). Stop/go: 1 = stop; short circuit: 1 = short.
struct StatusValue {
    static constexpr std::string_view name = "mcan.status-value";
    Address at;
    std::uint8_t index = 1;
    std::uint8_t value = 0;
};

// 6.7: a loco-stack list (0x80; 0x81 and 0x82 only in the trace), asked for the entry after `previous`
// (0 for the first), on the start handle. The master's bare echo (DLC 4) ends the list.
struct LocoListQuery {
    static constexpr std::string_view name = "mcan.loco-list-query";
    Address at;
    std::uint8_t list = 0x80;
    std::uint16_t previous = 0;
};

struct LocoListAnswer {
    static constexpr std::string_view name = "mcan.loco-list-answer";
    Address at;
    std::uint8_t list = 0x80;
    std::uint16_t previous = 0;
    std::uint16_t next = 0;
};

struct LocoListEnd {
    static constexpr std::string_view name = "mcan.loco-list-end";
    Address at;
    std::uint8_t list = 0x80;
    std::uint16_t previous = 0;
};

// 7.7.2 / 7.7.1: the master adds a locomotive to a slave's stack or deletes one, on the SY handle.
struct StackAdd {
    static constexpr std::string_view name = "mcan.stack-add";
    Address at;
    std::uint16_t locoHandle = 0;
};

struct StackDelete {
    static constexpr std::string_view name = "mcan.stack-delete";
    Address at;
    std::uint16_t locoHandle = 0;
};

// 6.7.1, 6.7.2, 6.7.6: a locomotive's properties on its handle, cmd 001: `40 what variant 00`, what =
// 03 type, 01 rail format (variant 0 and 1), 04 unexplained.
struct LocoQuery {
    static constexpr std::string_view name = "mcan.loco-query";
    Address at;
    std::uint8_t what = 0x03;
    std::uint8_t variant = 0;
};

// The answer: the query echoed and what follows (type in Data[5]: 00 none, 01 electric, 02 diesel,
// 03 steam; rail format in Data[5] for variant 0: 01 mfx, 02 DCC, 03 Motorola/Selectrix).
struct LocoAnswer {
    static constexpr std::string_view name = "mcan.loco-answer";
    Address at;
    std::uint8_t what = 0x03;
    std::uint8_t variant = 0;
    Bytes tail; // Data[4..]: 2 bytes (type, 40 04) or 4 (rail format)
};

// 6.7.3: function `function` (1 = speed and direction, 2 = f0, n = f(n-2)) asked for its description
// (`fkt 01`) or its value (`fkt 00`), on the locomotive's handle.
struct FunctionQuery {
    static constexpr std::string_view name = "mcan.function-query";
    Address at;
    std::uint8_t function = 1;
    bool description = true; // false: the value
};

// 6.7.3: `fkt 01 kind icon`: kind 01 latching, 02 momentary (00 speed in the text); icon 0x00 none.
struct FunctionDescription {
    static constexpr std::string_view name = "mcan.function-description";
    Address at;
    std::uint8_t function = 1;
    std::uint8_t kind = 1;
    std::uint8_t icon = 0;
};

// The bare echo `fkt 01`: the locomotive has no function `function`.
struct FunctionListEnd {
    static constexpr std::string_view name = "mcan.function-list-end";
    Address at;
    std::uint8_t function = 1;
};

// 6.7.3 / 7.3: `fkt 00 value`: an answer, or a change by the slave (priority 010 or 110, no
// acknowledgement) or by the master (011). Function 1: speed 0..127, bit 7 = reverse.
struct FunctionValue {
    static constexpr std::string_view name = "mcan.function-value";
    Address at;
    std::uint8_t function = 1;
    std::uint8_t value = 0;
};

// 6.7.3, last table: `01 02 n 00` and its answer `01 02 n 00 v`; meaning unknown.
struct FunctionExtraQuery {
    static constexpr std::string_view name = "mcan.function-extra-query";
    Address at;
    std::uint8_t n = 0;
};

struct FunctionExtraAnswer {
    static constexpr std::string_view name = "mcan.function-extra-answer";
    Address at;
    std::uint8_t n = 0;
    std::uint8_t value = 0;
};

// 6.7.5: after a restart the slave asks whom a locomotive is assigned to: `03 00` (priority 110).
struct AssignmentQuery {
    static constexpr std::string_view name = "mcan.assignment-query";
    Address at;
};

// The Fahrreglerstatus, `03 control state 00 extra` (priority 110 as the answer to the assignment query,
// 101 to take or release, 7.6): state 0x0008 = taken by the slave / may be taken, 0x0000 = released /
// free, 0xFFFF = held by the master. control (Data[1]) 0 = take, 1 = leave or choose again (guessed).
struct Throttle {
    static constexpr std::string_view name = "mcan.throttle";
    Address at;
    std::uint8_t control = 0;
    std::uint16_t state = 0;
    std::uint8_t extra = 1; // Data[5], usually 01
};

// 7.2.1: the slave's cyclic poll, every 250 ms after the upgrade: `00 00 00 masterNode`.
struct Poll {
    static constexpr std::string_view name = "mcan.poll";
    Address at;
    std::uint8_t masterNode = 0;
};

// 7.2.1: the master's answer `00 00 00 node` + a UID (the trace: its own node and UID; the text: `03` and
// the slave's UID). Also the master's frame before the stage-7 reply (trace #15, the slave's node and UID).
struct PollAnswer {
    static constexpr std::string_view name = "mcan.poll-answer";
    Address at;
    std::uint8_t lead = 0;
    std::uint8_t aboutNode = 0;
    std::uint32_t uid = 0;
};

// 7.2.2: the master polls a slave it has not heard from for 7.5 s: `00 00 00 node` (DLC 4).
struct MasterPoll {
    static constexpr std::string_view name = "mcan.master-poll";
    Address at;
    std::uint8_t aboutNode = 0;
};

// 7.2.2: the slave's answer to a master poll: `03 00 00 00 UID`.
struct PollReply {
    static constexpr std::string_view name = "mcan.poll-reply";
    Address at;
    std::uint32_t uid = 0;
};

// ---- Flashing (document 9), node 127. Stellwerk decodes these and never starts a flash. ------------------

// 9.2: an MS1 told to flash (stage-7 flag) says it is ready: UID, request 101.
struct FlashReady {
    static constexpr std::string_view name = "mcan.flash-ready";
    std::uint32_t uid = 0;
};

// 9.4 / 9.5: the master asks the slave's vendor (stage 1), SW/HW (2) or build (3); the slave answers
// with its UID and four bytes.
struct FlashQuery {
    static constexpr std::string_view name = "mcan.flash-query";
    std::uint8_t handle = 2;
    std::uint8_t stage = 1;
    std::uint32_t uid = 0;
};

struct FlashAnswer {
    static constexpr std::string_view name = "mcan.flash-answer";
    std::uint8_t handle = 2;
    std::uint8_t stage = 1;
    std::uint32_t uid = 0;
    std::uint32_t value = 0;
};

// 9.6: handle 0 aborts ("stops sending further frames"); a handle releases the flash.
struct FlashStart {
    static constexpr std::string_view name = "mcan.flash-start";
    std::uint8_t handle = 0; // 0: abort
    std::uint32_t uid = 0;
};

// 9.7: the slave asks for `count` bytes from `offset`; the master sends them four at a time.
struct FlashDataRequest {
    static constexpr std::string_view name = "mcan.flash-data-request";
    std::uint8_t handle = 2;
    std::uint32_t offset = 0;
    std::uint32_t count = 0;
};

struct FlashData {
    static constexpr std::string_view name = "mcan.flash-data";
    std::uint8_t handle = 2;
    std::uint32_t offset = 0;
    std::uint8_t count = 4; // 4, or 2 in a block's last frame
    std::array<std::uint8_t, 4> bytes{};
};

// 9.8: the master's end of the data.
struct FlashEnd {
    static constexpr std::string_view name = "mcan.flash-end";
    std::uint8_t handle = 2;
    std::uint32_t uid = 0;
};

// Any M-CAN frame the documents leave unexplained, or whose length or bytes no known form has: shown with
// its fields and never acted on. `why` is static text.
struct Unknown {
    static constexpr std::string_view name = "mcan.unknown";
    std::uint32_t id = 0;
    Bytes payload;
    std::string_view why;
};

using Message =
    std::variant<LoginRequest, LoginReply, LoginDetails, LoginGrant, BusBusy, SdHandleRequest, SdHandleAnswer,
                 StackSizeRequest, StackSizeAnswer, NameRequest, NameSegment, SyHandleRequest, SyHandleAnswer,
                 StatusQuery, StatusType, StatusListEnd, StatusValue, LocoListQuery, LocoListAnswer,
                 LocoListEnd, StackAdd, StackDelete, LocoQuery, LocoAnswer, FunctionQuery,
                 FunctionDescription, FunctionListEnd, FunctionValue, FunctionExtraQuery, FunctionExtraAnswer,
                 AssignmentQuery, Throttle, Poll, PollAnswer, MasterPoll, PollReply, FlashReady, FlashQuery,
                 FlashAnswer, FlashStart, FlashDataRequest, FlashData, FlashEnd, Unknown>;

// The message's name, e.g. "mcan.poll".
std::string_view nameOf(const Message& message);

// Every message name, in declaration order (login first, mcan.unknown last), for choosing one in a filter.
std::vector<std::string_view> messageNames();

} // namespace stellwerk::mcan
