#pragma once

#include "base/Expected.h"
#include "orc/Messages.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stellwerk::orc {

using KeyValue = std::pair<std::string, std::string>;

// An ORC message from its name and key=value pairs, as a person types it (`stellwerk-cli encode
// orc.decoder.switch target=0x3005 position=1`). Keys every message takes: prio=1..3 (default: notes A1.4),
// type=0..3 or system|loco|can-decoder|can-encoder, sender=bus id; answer=true|false where the document lets
// a message go both ways. The error names the key and what is wrong with it, or an unknown name or key.
Expected<Message, std::string> buildMessage(std::string_view name, const std::vector<KeyValue>& keyValues);

// The keys a message takes besides prio, type and sender, for help texts: "target position answer".
std::string_view keysOf(std::string_view name);

} // namespace stellwerk::orc
