#pragma once

#include <QMetaType>
#include <QString>
#include <cstdint>

namespace stellwerk::mcanhandhelds {

// Something a handheld did or that happened to it, one line of `stellwerk-cli handhelds`.
struct HandheldEvent {
    enum class Kind : std::uint8_t {
        LoggedIn,     // login stage 7 answered: it has its node
        UpgradeDone,  // its first poll: it has read its stack and locomotives
        LocoTaken,    // value: Loc-ID
        LocoRefused,  // somebody else holds it; value: Loc-ID
        LocoReleased, // value: Loc-ID
        Speed,        // value: 0..127, forward
        Function,     // function: index (f0 = 0), on
        Stop,         // its STOP key
        Go,           // its GO key
        Silent,       // no poll for the silence time: the master polls it
        Back,         // heard again while silent
        Lost,         // dropped after the master's polls went unanswered
        FlashMode,    // it sits in its boot loader
        Watching, // Stellwerk only watches from now on; value: why (mcanhandhelds::Watching), function: the
                  // other master's node when another master answered
        Renamed,  // it now calls itself `name`
    };

    Kind kind = Kind::LoggedIn;
    std::uint32_t uid = 0;
    QString name;
    std::uint32_t locId = 0;
    int value = 0;
    int function = 0;
    bool forward = true;
    bool on = false;
};

} // namespace stellwerk::mcanhandhelds

Q_DECLARE_METATYPE(stellwerk::mcanhandhelds::HandheldEvent)
