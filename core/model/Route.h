#pragma once

#include "cs2config/RouteFile.h"

#include <QString>
#include <cstdint>
#include <vector>

namespace stellwerk::model {

// A route of fahrstrassen.cs2 as the UI lists it, and whether it is running now.
class Route {
public:
    Route() = default;
    explicit Route(const cs2config::Route& record)
        : id_(record.id), name_(QString::fromStdString(record.name)), steps_(record.steps) {}

    std::int64_t id() const { return id_; }
    const QString& name() const { return name_; }
    const std::vector<cs2config::RouteStep>& steps() const { return steps_; }

    bool running() const { return running_; }
    void setRunning(bool running) { running_ = running; }

private:
    std::int64_t id_ = 0;
    QString name_;
    std::vector<cs2config::RouteStep> steps_;
    bool running_ = false;
};

} // namespace stellwerk::model
