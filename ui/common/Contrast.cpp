#include "common/Contrast.h"

#include <algorithm>
#include <cmath>

namespace stellwerk::ui {
namespace {

constexpr double MostFaded = 0.5; // a greyed colour keeps at least half of its own
constexpr int FadeSteps = 50;

double channel(double value) {
    return value <= 0.03928 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4);
}

double luminance(const QColor& colour) {
    return 0.2126 * channel(colour.redF()) + 0.7152 * channel(colour.greenF()) +
           0.0722 * channel(colour.blueF());
}

} // namespace

double Contrast::ratio(const QColor& a, const QColor& b) {
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QColor Contrast::mix(const QColor& a, const QColor& b, double weight) {
    const auto blend = [weight](double x, double y) { return x * weight + y * (1.0 - weight); };
    return QColor::fromRgbF(float(blend(a.redF(), b.redF())), float(blend(a.greenF(), b.greenF())),
                            float(blend(a.blueF(), b.blueF())));
}

double Contrast::keptFor(const QColor& foreground, const QColor& background, double wanted) {
    for (int step = FadeSteps; step > 0; --step) {
        const double kept = 1.0 - MostFaded * step / FadeSteps;
        if (ratio(mix(foreground, background, kept), background) >= wanted)
            return kept;
    }
    return 1.0;
}

QColor Contrast::faded(const QColor& foreground, const QColor& background, double wanted) {
    return mix(foreground, background, keptFor(foreground, background, wanted));
}

} // namespace stellwerk::ui
