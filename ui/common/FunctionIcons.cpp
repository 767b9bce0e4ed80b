#include "common/FunctionIcons.h"

#include "common/ToolIcons.h"

#include <QColor>
#include <array>
#include <utility>

namespace stellwerk::ui {
namespace {

constexpr int IconNumberMask = 0x7F;

// CS2 icon numbers (the station's FktIcon files) and the kind we draw for them. The numbering follows
// real lokomotive.cs2 files (see ../shared/corpus) and public CS2 implementations; 50 + n are the plain
// numbered keys "Fn", which stay Numbered like every number not listed here.
constexpr std::array<std::pair<int, FunctionKind>, 44> Kinds{{
    {1, FunctionKind::Light},          {3, FunctionKind::Light},           {4, FunctionKind::Light},
    {47, FunctionKind::Light},         {86, FunctionKind::Light},          {87, FunctionKind::Light},
    {90, FunctionKind::Light},         {105, FunctionKind::Light},         {2, FunctionKind::InteriorLight},
    {32, FunctionKind::InteriorLight}, {33, FunctionKind::InteriorLight},  {34, FunctionKind::InteriorLight},
    {35, FunctionKind::InteriorLight}, {110, FunctionKind::InteriorLight}, {41, FunctionKind::CabLight},
    {42, FunctionKind::CabLight},      {48, FunctionKind::CabLight},       {5, FunctionKind::Sound},
    {21, FunctionKind::Sound},         {22, FunctionKind::Sound},          {23, FunctionKind::Sound},
    {24, FunctionKind::Sound},         {108, FunctionKind::Sound},         {10, FunctionKind::Horn},
    {11, FunctionKind::Whistle},       {12, FunctionKind::Whistle},        {13, FunctionKind::Bell},
    {7, FunctionKind::Smoke},          {91, FunctionKind::Smoke},          {92, FunctionKind::Smoke},
    {9, FunctionKind::Coupler},        {43, FunctionKind::Coupler},        {82, FunctionKind::Coupler},
    {83, FunctionKind::Coupler},       {8, FunctionKind::Shunting},        {20, FunctionKind::BrakeSound},
    {112, FunctionKind::BrakeSound},   {6, FunctionKind::Pantograph},      {84, FunctionKind::Pantograph},
    {85, FunctionKind::Pantograph},    {18, FunctionKind::Inertia},        {25, FunctionKind::Announcement},
    {45, FunctionKind::Announcement},  {104, FunctionKind::Announcement},
}};

} // namespace

FunctionKind FunctionIcons::kindOf(int cs2Icon) {
    const int number = cs2Icon & IconNumberMask;
    for (const auto& [icon, kind] : Kinds)
        if (icon == number)
            return kind;
    return FunctionKind::Numbered;
}

QString FunctionIcons::resourcePath(FunctionKind kind) {
    const char* file = nullptr;
    switch (kind) {
    case FunctionKind::Numbered:
        return {};
    case FunctionKind::Light:
        file = "light";
        break;
    case FunctionKind::InteriorLight:
        file = "interior-light";
        break;
    case FunctionKind::CabLight:
        file = "cab-light";
        break;
    case FunctionKind::Sound:
        file = "sound";
        break;
    case FunctionKind::Horn:
        file = "horn";
        break;
    case FunctionKind::Whistle:
        file = "whistle";
        break;
    case FunctionKind::Bell:
        file = "bell";
        break;
    case FunctionKind::Smoke:
        file = "smoke";
        break;
    case FunctionKind::Coupler:
        file = "coupler";
        break;
    case FunctionKind::Shunting:
        file = "shunting";
        break;
    case FunctionKind::BrakeSound:
        file = "brake-sound";
        break;
    case FunctionKind::Pantograph:
        file = "pantograph";
        break;
    case FunctionKind::Inertia:
        file = "inertia";
        break;
    case FunctionKind::Announcement:
        file = "announcement";
        break;
    }
    return QStringLiteral(":/function-icons/%1.svg").arg(QLatin1String(file));
}

QString FunctionIcons::name(FunctionKind kind) {
    switch (kind) {
    case FunctionKind::Numbered:
        return tr("Function");
    case FunctionKind::Light:
        return tr("Light");
    case FunctionKind::InteriorLight:
        return tr("Interior light");
    case FunctionKind::CabLight:
        return tr("Cab light");
    case FunctionKind::Sound:
        return tr("Sound");
    case FunctionKind::Horn:
        return tr("Horn");
    case FunctionKind::Whistle:
        return tr("Whistle");
    case FunctionKind::Bell:
        return tr("Bell");
    case FunctionKind::Smoke:
        return tr("Smoke");
    case FunctionKind::Coupler:
        return tr("Coupler");
    case FunctionKind::Shunting:
        return tr("Shunting speed");
    case FunctionKind::BrakeSound:
        return tr("Brake sound");
    case FunctionKind::Pantograph:
        return tr("Pantograph");
    case FunctionKind::Inertia:
        return tr("Acceleration delay off");
    case FunctionKind::Announcement:
        return tr("Announcement");
    }
    return tr("Function");
}

QIcon FunctionIcons::icon(FunctionKind kind, const QColor& color, int size) {
    const QString path = resourcePath(kind);
    // The drawings are black; they are painted over in the palette's colour.
    return path.isEmpty() ? QIcon() : ToolIcons::tinted(path, color, size);
}

} // namespace stellwerk::ui
