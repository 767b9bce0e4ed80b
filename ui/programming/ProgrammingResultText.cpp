#include "programming/ProgrammingResultText.h"

namespace stellwerk::ui {
namespace {

using Outcome = model::ProgrammingResult::Outcome;
using Problem = model::ProgrammingResult::Problem;
using Task = model::ProgrammingResult::Task;

} // namespace

QString ProgrammingResultText::cv(const model::ProgrammingResult& result) {
    const QString cv = result.target.decoder.protocol() == cs2::Protocol::Mfx
                           ? tr("CV %1.%2").arg(result.target.cv).arg(result.target.index)
                           : tr("CV %1").arg(result.target.cv);
    const int value = result.value.value_or(0);
    if (result.task == Task::ReadCv)
        return tr("%1 = %2 (0x%3)").arg(cv).arg(value).arg(value, 2, 16, QLatin1Char('0'));
    return result.verified
               ? tr("%1 written: %2, read back and verified.").arg(cv).arg(value)
               : tr("%1 written: %2. Not verified: the decoder cannot be read back.").arg(cv).arg(value);
}

QString ProgrammingResultText::failure(const model::ProgrammingResult& result) {
    switch (result.outcome) {
    case Outcome::Refused:
        if (result.task == Task::ReadCv)
            return tr("No value: the decoder did not answer the read (is it on the programming track?).");
        if (result.task == Task::WriteCv)
            return tr("Refused: the station could not write the CV.");
        return tr("Refused by the station.");
    case Outcome::NoAnswer:
        return tr("No answer from the station.");
    case Outcome::NotSent:
        return tr("Not sent: the station is not connected.");
    case Outcome::Busy:
        return tr("Wait: the station is still busy with the last programming command.");
    case Outcome::Invalid:
        return problem(result);
    case Outcome::NotFound:
    case Outcome::Done:
        break;
    }
    return QString();
}

QString ProgrammingResultText::problem(const model::ProgrammingResult& result) {
    switch (result.problem) {
    case Problem::NotProgrammable:
        return tr("Only MM2, DCC, mfx and SX1 decoders can be programmed.");
    case Problem::Mm2CannotBeRead:
        return tr("MM2 decoders cannot be read: the station can only write their CVs.");
    case Problem::CvOutOfRange:
        return tr("The CV must be between %1 and %2 for this protocol.")
            .arg(result.minimum)
            .arg(result.maximum);
    case Problem::IndexOutOfRange:
        return tr("The mfx index must be between %1 and %2.").arg(result.minimum).arg(result.maximum);
    case Problem::IndexNotMfx:
        return tr("Only mfx CVs have an index.");
    case Problem::ProgrammingTrackOnly:
        return tr("SX1 decoders are programmed on the programming track only.");
    case Problem::ModeNotDcc:
        return tr("Programming modes are for DCC decoders only.");
    case Problem::ReservedMode:
        return tr("This DCC programming mode is reserved.");
    case Problem::BitValueForm:
        return tr("Bit programming needs a bit position and value.");
    case Problem::NoSid:
        return tr("Choose a SID from 1.");
    case Problem::None:
        break;
    }
    return QString();
}

} // namespace stellwerk::ui
