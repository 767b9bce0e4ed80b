#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace stellwerk::cs2config {

// One problem found in a file, said so that a person can act on it: where, what, and what was done.
struct Diagnostic {
    enum class Severity { Warning, Error };

    Severity severity = Severity::Warning;
    int line = 0; // 1-based; 0 = the file as a whole
    std::string message;
    std::string action;
};

// The problems of one file, bounded so that a hostile file cannot fill the memory with reports.
class Diagnostics {
public:
    static constexpr std::size_t defaultLimit = 500;

    explicit Diagnostics(std::string fileName = {}, std::size_t limit = defaultLimit);

    void warning(int line, std::string message, std::string action);
    void error(int line, std::string message, std::string action);
    void add(Diagnostic diagnostic);

    const std::string& fileName() const { return fileName_; }
    void setFileName(std::string fileName) { fileName_ = std::move(fileName); }
    const std::vector<Diagnostic>& items() const { return items_; }
    std::size_t suppressed() const { return suppressed_; }
    std::size_t count() const { return items_.size() + suppressed_; }
    bool empty() const { return count() == 0; }
    bool hasErrors() const { return errors_ > 0; }
    std::size_t errorCount() const { return errors_; }

    // "lokomotive.cs2:7: warning: unreadable line ' komotive]'; kept unchanged and ignored"
    std::string format(const Diagnostic& diagnostic) const;
    // Every item on its own line in line order, plus a line for the suppressed ones.
    std::string formatAll() const;

private:
    std::string fileName_;
    std::size_t limit_;
    std::vector<Diagnostic> items_;
    std::size_t suppressed_ = 0;
    std::size_t errors_ = 0;
};

} // namespace stellwerk::cs2config
