#include "mcanhandhelds/SlaveSession.h"

#include "mcanhandhelds/LocoFacts.h"

#include <algorithm>
#include <type_traits>

namespace stellwerk::mcanhandhelds {
namespace {

// An MS1 shows at most eight functions (FKT 2..9) besides speed and direction (FKT 1).
constexpr std::uint8_t LastFunctionKey = 9;
// The icon an MS1 has no picture for (document 6.7.3); the pictures of the others are lost.
constexpr std::uint8_t OtherIcon = 0x0B;

template <class T>
const T* as(const mcan::Message& message) {
    return std::get_if<T>(&message);
}

mcan::Address addressOf(const mcan::Message& message) {
    return std::visit(
        [](const auto& m) {
            if constexpr (requires { m.at; })
                return m.at;
            else
                return mcan::Address{};
        },
        message);
}

// The highest function key the locomotive has a function for, FKT 1 when it has none.
std::uint8_t lastKey(const HandheldLoco& loco) {
    int last = -1;
    for (const HandheldFunction& function : loco.functions)
        last = std::max(last, function.index);
    return std::uint8_t(std::min(last + 2, int(LastFunctionKey)));
}

const HandheldFunction* functionOf(const HandheldLoco& loco, int index) {
    for (const HandheldFunction& function : loco.functions)
        if (function.index == index)
            return &function;
    return nullptr;
}

} // namespace

SlaveSession::SlaveSession(Handheld handheld, std::uint32_t masterUid, SessionHost& host)
    : handheld_(std::move(handheld)), masterUid_(masterUid), host_(host) {
    const std::vector<std::uint32_t> stack = std::exchange(handheld_.stack, {});
    for (const std::uint32_t locId : stack)
        addLoco(locId);
}

std::optional<std::uint32_t> SlaveSession::locoOf(std::uint16_t handle) const {
    for (const auto& [h, locId] : locoHandles_)
        if (h == handle)
            return locId;
    return std::nullopt;
}

std::optional<std::uint16_t> SlaveSession::handleOf(std::uint32_t locId) const {
    for (const auto& [handle, id] : locoHandles_)
        if (id == locId)
            return handle;
    return std::nullopt;
}

std::uint16_t SlaveSession::addLoco(std::uint32_t locId) {
    const std::uint16_t handle = nextHandle_++;
    locoHandles_.emplace_back(handle, locId);
    handheld_.stack.push_back(locId);
    return handle;
}

std::vector<mcan::Message> SlaveSession::answer(const mcan::Message& message, bool& understood) {
    understood = true;
    const mcan::Address at = addressOf(message);
    if (at.node != slaveNode()) {
        understood = false;
        return {};
    }
    switch (at.handle) {
    case StartHandle:
        return answerStart(message, understood);
    case SdHandle:
        return answerSlaveDescription(message, understood);
    case SyHandle:
        return answerSystemStatus(message, understood);
    default:
        break;
    }
    if (const std::optional<std::uint32_t> locId = locoOf(at.handle))
        return answerLoco(message, at.handle, *locId, understood);
    if (const auto* poll = as<mcan::Poll>(message); poll && at.handle == PollHandle) {
        if (handheld_.state != HandheldState::Online) {
            handheld_.state = HandheldState::Online; // the first poll ends the upgrade (notes B§3.2, 7)
            host_.changed(*this);
        }
        return {mcan::PollAnswer{from(PollHandle, mcan::prio::Master), 0, masterNode(), masterUid_}};
    }
    if (as<mcan::PollReply>(message) && at.handle == PollHandle)
        return {}; // the master's liveness already counts it as heard
    understood = false;
    return {};
}

std::vector<mcan::Message> SlaveSession::answerStart(const mcan::Message& message, bool& understood) {
    if (const auto* request = as<mcan::SdHandleRequest>(message)) {
        // The SD handle, and at once the master's own questions: stack size and name (trace #18-#22, #28).
        return {mcan::SdHandleAnswer{from(StartHandle), request->slaveNode, SdHandle},
                mcan::StackSizeRequest{from(SdHandle)},
                mcan::NameRequest{from(SdHandle), 0},
                mcan::NameRequest{from(SdHandle), 4},
                mcan::NameRequest{from(SdHandle), 8},
                mcan::NameRequest{from(SdHandle), 12}};
    }
    if (as<mcan::SyHandleRequest>(message))
        return {mcan::SyHandleAnswer{from(StartHandle), SyHandle, 0x03, 0x00}};
    if (const auto* query = as<mcan::LocoListQuery>(message))
        return nextInStack(*query);
    understood = false;
    return {};
}

std::vector<mcan::Message> SlaveSession::answerSlaveDescription(const mcan::Message& message,
                                                                bool& understood) {
    if (const auto* answer = as<mcan::StackSizeAnswer>(message)) {
        handheld_.stackSize = answer->size;
        host_.changed(*this);
        return {};
    }
    if (const auto* segment = as<mcan::NameSegment>(message)) {
        learnName(*segment);
        return {};
    }
    understood = false;
    return {};
}

void SlaveSession::learnName(const mcan::NameSegment& segment) {
    if (segment.offset == 0)
        nameRead_.clear();
    if (segment.offset != nameRead_.size() || segment.offset > 12)
        return; // out of order: what was read stays
    for (std::uint8_t i = 0; i < segment.count; ++i) {
        if (segment.chars[i] == '\0') {
            nameRead_.push_back('\0'); // the end: later segments add nothing
            break;
        }
        nameRead_.push_back(segment.chars[i]);
    }
    const std::string name = nameRead_.substr(0, nameRead_.find('\0'));
    const QString shown = QString::fromLatin1(name.data(), qsizetype(name.size()));
    if (shown != handheld_.name) {
        handheld_.name = shown;
        host_.changed(*this);
    }
}

std::vector<mcan::Message> SlaveSession::answerSystemStatus(const mcan::Message& message, bool& understood) {
    // The status list of the ECoS: 1 stop/go, 2 short circuit, 3 mfx registration (notes B§3.2, 4).
    static constexpr std::uint8_t Types[] = {0x01, 0x02, 0x04};
    if (const auto* query = as<mcan::StatusQuery>(message)) {
        const bool listed = query->index >= 1 && query->index <= std::size(Types);
        if (query->type)
            return listed ? std::vector<mcan::Message>{mcan::StatusType{from(SyHandle), query->index,
                                                                        Types[query->index - 1]}}
                          : std::vector<mcan::Message>{mcan::StatusListEnd{from(SyHandle), query->index}};
        const bool on = (query->index == 1 && host_.stopped()) || (query->index == 2 && host_.shortCircuit());
        const std::uint8_t value = on ? 1 : 0;
        return {mcan::StatusValue{from(SyHandle, mcan::prio::Status), query->index, value}};
    }
    if (const auto* change = as<mcan::StatusValue>(message); change && change->index == 1) {
        host_.stopKey(*this, change->value != 0); // the master tells every handheld (7.4)
        return {};
    }
    understood = false;
    return {};
}

std::vector<mcan::Message> SlaveSession::answerLoco(const mcan::Message& message, std::uint16_t handle,
                                                    std::uint32_t locId, bool& understood) {
    if (const auto* query = as<mcan::LocoQuery>(message))
        return answerLocoProperty(*query, locId);
    if (const auto* query = as<mcan::FunctionQuery>(message))
        return answerFunction(*query, locId);
    if (const auto* query = as<mcan::FunctionExtraQuery>(message))
        return {mcan::FunctionExtraAnswer{from(handle), query->n, 0}};
    if (as<mcan::AssignmentQuery>(message))
        return {
            mcan::Throttle{from(handle), 0, std::uint16_t(host_.heldByOther(*this, locId) ? 0xFFFF : 0), 1}};
    if (const auto* request = as<mcan::Throttle>(message))
        return answerThrottle(*request, locId);
    if (const auto* request = as<mcan::NameRequest>(message);
        request && request->offset <= 12 && request->offset % 4 == 0)
        return answerName(*request, locId);
    if (const auto* change = as<mcan::FunctionValue>(message);
        change && change->function <= LastFunctionKey) {
        std::erase_if(shown_, [&](const auto& shown) { return shown.first == change->function; });
        shown_.emplace_back(change->function, change->value);
        host_.drive(*this, locId, change->function, change->value);
        return {};
    }
    understood = false;
    return {};
}

std::vector<mcan::Message> SlaveSession::answerLocoProperty(const mcan::LocoQuery& query,
                                                            std::uint32_t locId) const {
    const HandheldLoco* loco = host_.loco(locId);
    mcan::LocoAnswer answer{from(query.at.handle), query.what, query.variant, {}};
    if (query.what == 0x03)
        answer.tail = {2, {0x00, std::uint8_t(loco ? loco->kind : LocoKind::None)}};
    else if (query.what == 0x01 && query.variant == 0)
        answer.tail = {4, {0x00, std::uint8_t(loco ? loco->format : RailFormat::Unknown), 0x00, 0x00}};
    else if (query.what == 0x01)
        answer.tail = {4, {}};
    else
        answer.tail = {2, {}};
    return {answer};
}

std::uint8_t SlaveSession::functionValue(std::uint8_t function, std::uint32_t locId) const {
    const LocoDrive drive = host_.drive(locId);
    if (function == 1)
        return speedByte(handheldSpeed(drive.speed), drive.forward);
    return (drive.functions >> (function - 2)) & 1;
}

std::vector<mcan::Message> SlaveSession::answerFunction(const mcan::FunctionQuery& query,
                                                        std::uint32_t locId) const {
    const HandheldLoco* loco = host_.loco(locId);
    const mcan::Address at = from(query.at.handle);
    const bool exists =
        query.function == 1 || (loco && query.function >= 2 && query.function <= lastKey(*loco));
    if (!query.description)
        return {mcan::FunctionValue{at, query.function,
                                    exists ? functionValue(query.function, locId) : std::uint8_t(0)}};
    if (!exists)
        return {mcan::FunctionListEnd{at, query.function}};
    if (query.function == 1)
        return {mcan::FunctionDescription{at, 1, 1, 1}}; // as the ECoS describes speed (trace #61)
    const HandheldFunction* function = functionOf(*loco, query.function - 2);
    if (!function)
        return {mcan::FunctionDescription{at, query.function, 1, 0x00}}; // a gap: no icon
    return {
        mcan::FunctionDescription{at, query.function, std::uint8_t(function->momentary ? 2 : 1), OtherIcon}};
}

std::vector<mcan::Message> SlaveSession::answerThrottle(const mcan::Throttle& request, std::uint32_t locId) {
    const mcan::Address at = from(request.at.handle, mcan::prio::Throttle);
    if (request.control == 0 && request.state == 0x0008) { // take (7.6)
        if (!host_.take(*this, locId)) {
            handheld_.locoRefused = true;
            host_.changed(*this);
            return {mcan::Throttle{at, 0, 0xFFFF, 1}};
        }
        handheld_.loco = locId;
        handheld_.locoRefused = false;
        rememberShown(locId);
        const LocoDrive drive = host_.drive(locId);
        handheld_.speed = handheldSpeed(drive.speed);
        handheld_.forward = drive.forward;
        handheld_.functions = drive.functions;
        host_.changed(*this);
        return {mcan::Throttle{at, request.control, request.state, request.extra}};
    }
    // Leave it, or choose it again (control 1), or give it back (state 0): released, and "held" when someone
    // else has it.
    host_.release(*this, locId);
    if (handheld_.loco == locId)
        handheld_.loco.reset();
    handheld_.locoRefused = false;
    host_.changed(*this);
    std::vector<mcan::Message> answers{mcan::Throttle{at, 0, 0x0000, 1}};
    if (host_.heldByOther(*this, locId))
        answers.push_back(mcan::Throttle{at, 0, 0xFFFF, 1});
    return answers;
}

std::vector<mcan::Message> SlaveSession::answerName(const mcan::NameRequest& request,
                                                    std::uint32_t locId) const {
    if (request.offset > 12 || request.offset % 4 != 0)
        return {};
    const HandheldLoco* loco = host_.loco(locId);
    const std::array<char, 16> name = nameSegments(loco ? loco->name : std::string());
    mcan::NameSegment segment{from(request.at.handle), request.offset, 4, {}, 0};
    std::copy_n(name.begin() + request.offset, 4, segment.chars.begin());
    return {segment};
}

std::vector<mcan::Message> SlaveSession::nextInStack(const mcan::LocoListQuery& query) const {
    const mcan::Address at = from(StartHandle);
    if (query.list != 0x80)
        return {mcan::LocoListEnd{at, query.list, query.previous}}; // 0x81, 0x82: empty, as the ECoS answers
    auto next = locoHandles_.begin();
    if (query.previous != 0) {
        next = std::find_if(locoHandles_.begin(), locoHandles_.end(),
                            [&](const auto& entry) { return entry.first == query.previous; });
        if (next != locoHandles_.end())
            ++next;
    }
    if (next == locoHandles_.end())
        return {mcan::LocoListEnd{at, query.list, query.previous}};
    return {mcan::LocoListAnswer{at, query.list, query.previous, next->first}};
}

std::vector<mcan::Message> SlaveSession::status(bool stopped, bool shortCircuit) const {
    return {mcan::StatusValue{from(SyHandle, mcan::prio::Status), 1, std::uint8_t(stopped ? 1 : 0)},
            mcan::StatusValue{from(SyHandle, mcan::prio::Status), 2, std::uint8_t(shortCircuit ? 1 : 0)}};
}

// The handheld shows the values it read during the upgrade: from now on, only changes are told.
void SlaveSession::rememberShown(std::uint32_t locId) {
    shown_.clear();
    const HandheldLoco* loco = host_.loco(locId);
    for (std::uint8_t function = 1; function <= (loco ? lastKey(*loco) : 1); ++function)
        shown_.emplace_back(function, functionValue(function, locId));
}

std::vector<mcan::Message> SlaveSession::driveChanged(std::uint32_t locId, const LocoDrive& drive) {
    const std::optional<std::uint16_t> handle = handleOf(locId);
    if (!handle || handheld_.loco != locId)
        return {}; // only what the handheld shows (7.3)
    handheld_.speed = handheldSpeed(drive.speed);
    handheld_.forward = drive.forward;
    handheld_.functions = drive.functions;
    const HandheldLoco* loco = host_.loco(locId);
    const std::uint8_t last = loco ? lastKey(*loco) : 1;
    std::vector<mcan::Message> frames;
    for (std::uint8_t function = 1; function <= last; ++function) {
        const std::uint8_t value = functionValue(function, locId);
        const auto shown =
            std::find_if(shown_.begin(), shown_.end(), [&](const auto& s) { return s.first == function; });
        if (shown != shown_.end() && shown->second == value)
            continue;
        if (shown != shown_.end())
            shown->second = value;
        else
            shown_.emplace_back(function, value);
        frames.push_back(mcan::FunctionValue{from(*handle, mcan::prio::Master), function, value});
    }
    return frames;
}

std::vector<mcan::Message> SlaveSession::holderChanged(std::uint32_t locId, bool heldByOther) {
    const std::optional<std::uint16_t> handle = handleOf(locId);
    if (!handle)
        return {};
    if (heldByOther && handheld_.loco == locId) {
        handheld_.loco.reset();
        handheld_.locoRefused = true;
    }
    return {
        mcan::Throttle{from(*handle, mcan::prio::Throttle), 0, std::uint16_t(heldByOther ? 0xFFFF : 0), 1}};
}

std::vector<mcan::Message> SlaveSession::setStack(const std::vector<std::uint32_t>& stack) {
    std::vector<mcan::Message> frames;
    for (auto entry = locoHandles_.begin(); entry != locoHandles_.end();) {
        if (std::find(stack.begin(), stack.end(), entry->second) != stack.end()) {
            ++entry;
            continue;
        }
        frames.push_back(mcan::StackDelete{from(SyHandle), entry->first});
        if (handheld_.loco == entry->second) {
            host_.release(*this, entry->second);
            handheld_.loco.reset();
        }
        entry = locoHandles_.erase(entry);
    }
    handheld_.stack.clear();
    for (const auto& entry : locoHandles_)
        handheld_.stack.push_back(entry.second);
    for (const std::uint32_t locId : stack)
        if (!handleOf(locId))
            frames.push_back(mcan::StackAdd{from(SyHandle), addLoco(locId)});
    return frames;
}

std::vector<mcan::Message> SlaveSession::rename(const std::string& name) const {
    const std::array<char, 16> segments = nameSegments(name);
    std::vector<mcan::Message> frames;
    for (std::uint8_t offset = 0; offset < 16; offset += 4) {
        mcan::NameSegment segment{from(SdHandle), offset, 4, {}, 0};
        std::copy_n(segments.begin() + offset, 4, segment.chars.begin());
        frames.push_back(segment);
    }
    return frames;
}

mcan::Message SlaveSession::announce() const {
    return mcan::PollAnswer{from(PollHandle, mcan::prio::Master), 0, slaveNode(), handheld_.uid};
}

mcan::Message SlaveSession::masterPoll() const {
    return mcan::MasterPoll{from(PollHandle, mcan::prio::Master), masterNode()};
}

void SlaveSession::releaseAll() {
    if (handheld_.loco)
        host_.release(*this, *handheld_.loco);
    handheld_.loco.reset();
}

} // namespace stellwerk::mcanhandhelds
