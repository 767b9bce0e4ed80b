#include "cs2config/Diagnostics.h"

#include <algorithm>

namespace stellwerk::cs2config {

Diagnostics::Diagnostics(std::string fileName, std::size_t limit)
    : fileName_(std::move(fileName)), limit_(limit) {}

void Diagnostics::warning(int line, std::string message, std::string action) {
    add({Diagnostic::Severity::Warning, line, std::move(message), std::move(action)});
}

void Diagnostics::error(int line, std::string message, std::string action) {
    add({Diagnostic::Severity::Error, line, std::move(message), std::move(action)});
}

void Diagnostics::add(Diagnostic diagnostic) {
    if (diagnostic.severity == Diagnostic::Severity::Error)
        ++errors_;
    if (items_.size() >= limit_) {
        ++suppressed_;
        return;
    }
    items_.push_back(std::move(diagnostic));
}

std::string Diagnostics::format(const Diagnostic& diagnostic) const {
    std::string text = fileName_.empty() ? std::string("<input>") : fileName_;
    if (diagnostic.line > 0)
        text += ':' + std::to_string(diagnostic.line);
    text += diagnostic.severity == Diagnostic::Severity::Error ? ": error: " : ": warning: ";
    text += diagnostic.message;
    if (!diagnostic.action.empty())
        text += "; " + diagnostic.action;
    return text;
}

std::string Diagnostics::formatAll() const {
    // In line order, as a person reads the file; problems of the same line keep the order found.
    std::vector<const Diagnostic*> ordered;
    for (const Diagnostic& diagnostic : items_)
        ordered.push_back(&diagnostic);
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const Diagnostic* a, const Diagnostic* b) { return a->line < b->line; });
    std::string text;
    for (const Diagnostic* diagnostic : ordered)
        text += format(*diagnostic) + '\n';
    if (suppressed_ > 0)
        text += (fileName_.empty() ? std::string("<input>") : fileName_) + ": " +
                std::to_string(suppressed_) + " more problems not listed\n";
    return text;
}

} // namespace stellwerk::cs2config
