#include "cs2config/TrackElementType.h"

namespace stellwerk::cs2config {

namespace {

using C = TrackCategory;
using A = ArticleLink;

// The document's list (8.3.5) in its order, then the types firmware writes beyond it. A `pfeil`
// links to another page (the document's note "Verweis auf andere Gleisbildseite").
constexpr TrackElementType types[] = {
    // clang-format off
    {"leer", C::Empty, A::None, true},
    {"gerade", C::Track, A::None, true},
    {"kreuzung", C::Track, A::None, true},
    {"unterfuehrung", C::Track, A::None, true},
    {"prellbock", C::Track, A::None, true},
    {"bogen", C::Track, A::None, true},
    {"doppelbogen", C::Track, A::None, true},
    {"tunnel", C::Track, A::None, true},
    {"linksweiche", C::Turnout, A::Accessory, true},
    {"rechtsweiche", C::Turnout, A::Accessory, true},
    {"dreiwegweiche", C::Turnout, A::Accessory, true},
    {"yweiche", C::Turnout, A::Accessory, true},
    {"dkweiche", C::Turnout, A::Accessory, true},
    {"dkweiche_2", C::Turnout, A::Accessory, true},
    {"signal", C::Signal, A::Accessory, true},
    {"s88kontakt", C::Feedback, A::FeedbackContact, true},
    {"s88bogen", C::Feedback, A::FeedbackContact, true},
    {"pfeil", C::PageLink, A::Page, true},
    {"fahrstrasse", C::RouteButton, A::Route, true},
    {"text", C::Text, A::None, true},
    {"signal_hp02", C::Signal, A::Accessory, true},
    {"signal_hp012", C::Signal, A::Accessory, true},
    {"signal_hp01s", C::Signal, A::Accessory, true},
    {"signal_p_hp012s", C::Signal, A::Accessory, true},
    {"signal_f_hp012s", C::Signal, A::Accessory, true},
    {"signal_p_hp012", C::Signal, A::Accessory, true},
    {"signal_f_hp01", C::Signal, A::Accessory, true},
    {"signal_f_hp02", C::Signal, A::Accessory, true},
    {"signal_f_hp012", C::Signal, A::Accessory, true},
    {"signal_sh01", C::Signal, A::Accessory, true},
    {"k84_einfach", C::Output, A::Accessory, true},
    {"k84_doppelt", C::Output, A::Accessory, true},
    {"entkuppler", C::Uncoupler, A::Accessory, true},
    {"entkuppler_1", C::Uncoupler, A::Accessory, true},
    {"std_rot", C::Output, A::Accessory, true},
    {"std_gruen", C::Output, A::Accessory, true},
    {"std_rot_gruen_0", C::Output, A::Accessory, true},
    {"std_rot_gruen_1", C::Output, A::Accessory, true},
    {"schiebebuehne_0", C::TransferTable, A::Accessory, true},
    {"schiebebuehne_1", C::TransferTable, A::Accessory, true},
    {"schiebebuehne_2", C::TransferTable, A::Accessory, true},
    {"schiebebuehne_3", C::TransferTable, A::Accessory, true},
    {"drehscheibe_alt_0", C::Turntable, A::Accessory, true},
    {"drehscheibe_alt_1", C::Turntable, A::Accessory, true},
    {"drehscheibe_alt_2", C::Turntable, A::Accessory, true},
    {"drehscheibe_alt_3", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_0", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_1", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_2", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_3", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_4", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_5", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_6", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_7", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_8", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_9", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_10", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_11", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_12", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_13", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_14", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_15", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_16", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_17", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_18", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_19", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_20", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_21", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_22", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_23", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_24", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_25", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_26", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_27", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_28", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_29", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_30", C::Turntable, A::Accessory, true},
    {"drehscheibe_dig_31", C::Turntable, A::Accessory, true},
    // Written by CS2/CS3 firmware, not in the document (seen in real pages and in readers of them).
    {"s88doppelbogen", C::Feedback, A::FeedbackContact, false},
    {"signal_hp012s", C::Signal, A::Accessory, false},
    {"drehscheibe", C::Turntable, A::Accessory, false},
    {"hosentraeger", C::Turnout, A::Accessory, false},
    {"dkw3_li", C::Turnout, A::Accessory, false},
    {"dkw3_li_2", C::Turnout, A::Accessory, false},
    {"dkw3_re", C::Turnout, A::Accessory, false},
    {"dkw3_re_2", C::Turnout, A::Accessory, false},
    {"lampe", C::Output, A::Accessory, false},
    {"lampe_rt", C::Output, A::Accessory, false},
    {"lampe_gn", C::Output, A::Accessory, false},
    {"lampe_ge", C::Output, A::Accessory, false},
    {"lampe_bl", C::Output, A::Accessory, false},
    {"bahnschranke", C::Output, A::Accessory, false},
    // clang-format on
};

} // namespace

std::span<const TrackElementType> trackElementTypes() {
    return types;
}

const TrackElementType* findTrackElementType(std::string_view name) {
    for (const TrackElementType& type : types)
        if (type.name == name)
            return &type;
    return nullptr;
}

std::string_view trackCategoryName(TrackCategory category) {
    switch (category) {
    case C::Empty:
        return "empty";
    case C::Track:
        return "track";
    case C::Turnout:
        return "turnout";
    case C::Signal:
        return "signal";
    case C::Feedback:
        return "feedback";
    case C::RouteButton:
        return "route button";
    case C::PageLink:
        return "page link";
    case C::Text:
        return "text";
    case C::Uncoupler:
        return "uncoupler";
    case C::Output:
        return "output";
    case C::Turntable:
        return "turntable";
    case C::TransferTable:
        return "transfer table";
    case C::Unknown:
        break;
    }
    return "unknown";
}

std::string_view articleLinkName(ArticleLink link) {
    switch (link) {
    case A::Accessory:
        return "accessory";
    case A::FeedbackContact:
        return "feedback contact";
    case A::Route:
        return "route";
    case A::Page:
        return "page";
    case A::None:
        break;
    }
    return "none";
}

} // namespace stellwerk::cs2config
