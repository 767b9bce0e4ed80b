#pragma once

#include <QString>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace stellwerk::mcanhandhelds {

// What the master keeps of a handheld from one session to the next (document 5.4.1: a master remembers an
// MS1 and its locomotives by UID, permanently).
struct SavedHandheld {
    QString name;
    std::vector<std::uint32_t> stack; // Loc-IDs
    friend bool operator==(const SavedHandheld&, const SavedHandheld&) = default;
};

// Where handhelds are remembered, by UID.
class HandheldBook {
public:
    virtual ~HandheldBook() = default;
    virtual std::optional<SavedHandheld> load(std::uint32_t uid) const = 0;
    virtual void save(std::uint32_t uid, const SavedHandheld& handheld) = 0;
};

// A book that lasts as long as the program: for the simulator and for tests.
class MemoryHandheldBook final : public HandheldBook {
public:
    std::optional<SavedHandheld> load(std::uint32_t uid) const override;
    void save(std::uint32_t uid, const SavedHandheld& handheld) override;

private:
    std::map<std::uint32_t, SavedHandheld> saved_;
};

// A book in the program's settings (QSettings of the organisation and application given), group
// "mcanhandhelds/<UID in hex>": kept across runs.
class SettingsHandheldBook final : public HandheldBook {
public:
    SettingsHandheldBook(QString organization, QString application)
        : organization_(std::move(organization)), application_(std::move(application)) {}
    std::optional<SavedHandheld> load(std::uint32_t uid) const override;
    void save(std::uint32_t uid, const SavedHandheld& handheld) override;

private:
    QString organization_;
    QString application_;
};

} // namespace stellwerk::mcanhandhelds
