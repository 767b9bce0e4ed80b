#include "trackplan/PaintThreads.h"

#include <QCoreApplication>
#include <QPointer>
#include <QSemaphore>
#include <QThreadPool>
#include <algorithm>
#include <thread>

namespace stellwerk::ui {
namespace {

constexpr std::size_t MaximumThreads = 4;

// Owned by the application, so that the threads end with it, while Qt's per-thread data (each thread's
// fonts) can still be cleaned up; without an application the pool lives until the program ends.
QThreadPool& helpers() {
    static QPointer<QThreadPool> pool;
    if (!pool) {
        pool = new QThreadPool(QCoreApplication::instance());
        pool->setMaxThreadCount(std::max(int(PaintThreads::count()) - 1, 1));
        pool->setExpiryTimeout(-1); // kept: a new thread starts with new memory
    }
    return *pool;
}

} // namespace

std::size_t PaintThreads::count() {
    return std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, MaximumThreads);
}

void PaintThreads::run(std::size_t parts, const std::function<void(std::size_t part)>& work) {
    QThreadPool& pool = helpers();
    QSemaphore done;
    int started = 0;
    for (std::size_t part = 1; part < parts; ++part, ++started)
        pool.start([&work, &done, part] {
            work(part);
            done.release();
        });
    if (parts > 0)
        work(0);
    done.acquire(started);
}

} // namespace stellwerk::ui
