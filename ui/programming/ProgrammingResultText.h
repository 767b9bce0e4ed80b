#pragma once

#include "model/Programmer.h"

#include <QCoreApplication>
#include <QString>

namespace stellwerk::ui {

// What a programming result means, in the user's language: the value read or written, or why there is
// none. Its texts belong to the Programming page (same translation context as ProgrammingPanel).
class ProgrammingResultText {
    Q_DECLARE_TR_FUNCTIONS(stellwerk::ui::ProgrammingPanel)

public:
    // "CV 29 = 6 (0x06)", "CV 1.3 written: 5, read back and verified.", ...
    static QString cv(const model::ProgrammingResult& result);
    // Why a command failed: refused, no answer, not sent, busy, or the problem found before sending.
    static QString failure(const model::ProgrammingResult& result);
    // The problem the programmer found in the request before anything was sent.
    static QString problem(const model::ProgrammingResult& result);
};

} // namespace stellwerk::ui
