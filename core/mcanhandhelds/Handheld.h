#pragma once

#include <QMetaType>
#include <QString>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace stellwerk::mcanhandhelds {

// Where a handheld is in its conversation with its master (notes B§3).
enum class HandheldState : std::uint8_t {
    LoggingIn, // login stages 0-7
    Upgrading, // the "Aufrüstung": it reads its stack, the status list and its locomotives
    Online,    // polling every 250 ms
    Silent,    // no poll for 7.5 s: the master polls it, at most 30 times
    Offline,   // dropped after the polls went unanswered (or unplugged while another master is master)
    FlashMode, // in its boot loader: only a firmware flash by a CS1/ECoS brings it back
};

// One MS1 as people see it: who it is, where it stands, and what it drives. Made by the master (or the
// watcher, when another master answers the handhelds) and shown by the Handhelds panel and the CLI.
struct Handheld {
    std::uint32_t uid = 0;
    QString name;               // as the handheld calls itself, up to 16 characters
    std::uint8_t slaveNode = 0; // odd; its master's node is one less
    HandheldState state = HandheldState::LoggingIn;
    int loginStage = 0;      // 0..7 while logging in
    int silentPollsLeft = 0; // while Silent: how many master polls are left before it is dropped
    int stackSize = 10;
    std::vector<std::uint32_t> stack;  // Loc-IDs in the handheld's order
    std::optional<std::uint32_t> loco; // the locomotive it drives (taken), when it has one
    QString locoName;                  // its name as the handheld shows it
    bool locoRefused = false;          // it asked for a locomotive somebody else holds
    int speed = 0;                     // 0..127, as the handheld shows it
    bool forward = true;
    std::uint32_t functions = 0;           // bit n: function n
    std::array<std::uint8_t, 4> version{}; // the software bytes of login stage 7
    bool ours = true;                      // logged in at Stellwerk (false: at another master)

    std::uint8_t masterNode() const { return std::uint8_t(slaveNode - 1); }
};

} // namespace stellwerk::mcanhandhelds

Q_DECLARE_METATYPE(stellwerk::mcanhandhelds::Handheld)
