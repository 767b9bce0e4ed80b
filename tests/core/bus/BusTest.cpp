// An open bus: each protocol's subscribers get that protocol's frames in order, foreign frames are
// counted and seen but reach no CS2 session, and a subscriber that leaves gets nothing more.

#include "bus/Bus.h"

#include "transport/LoopbackTransport.h"

#include <QSignalSpy>
#include <QTest>
#include <gtest/gtest.h>
#include <memory>

namespace stellwerk::bus {
namespace {

using busreading::BusProfile;
using busreading::Protocol;

can::CanFrame cs2Frame(std::uint8_t last) {
    const std::uint8_t data[] = {0, 0, 0, 0, last};
    return can::CanFrame::extendedFrame(0x00004711, data);
}

can::CanFrame standardFrame(std::uint16_t id) {
    const std::uint8_t data[] = {1, 2};
    return can::CanFrame::standard(id, data);
}

// A bus on the app's end of a loopback pair, the other end standing for everything else on the wire.
struct Wire {
    explicit Wire(BusProfile profile = BusProfile::centralStation()) : bus(app, std::move(profile), "can0") {
        transport::LoopbackTransport::join(app, others);
        app.open();
        others.open();
    }
    transport::LoopbackTransport app{QStringLiteral("app")};
    transport::LoopbackTransport others{QStringLiteral("others")};
    Bus bus;
};

// What one subscriber was handed.
struct Deliveries {
    void subscribe(Bus& bus, Protocol protocol, QObject* subscriber) {
        bus.subscribe(protocol, subscriber, [this](const std::vector<can::CanFrame>& f) {
            ++batches;
            frames.insert(frames.end(), f.begin(), f.end());
        });
    }
    int batches = 0;
    std::vector<can::CanFrame> frames;
};

TEST(Bus, EachProtocolGetsItsOwnFramesInOrderAndEveryFrameIsCounted) {
    Wire wire;
    QObject cs2Session;
    QObject foreignCounter;
    Deliveries cs2;
    Deliveries foreign;
    cs2.subscribe(wire.bus, Protocol::Cs2, &cs2Session);
    foreign.subscribe(wire.bus, Protocol::Foreign, &foreignCounter);
    wire.others.sendBatch(std::vector{cs2Frame(1), standardFrame(0x123), cs2Frame(2), standardFrame(0x7FF)});
    ASSERT_TRUE(QTest::qWaitFor([&] { return cs2.frames.size() == 2; }));
    EXPECT_EQ(cs2.frames, (std::vector{cs2Frame(1), cs2Frame(2)}));
    EXPECT_EQ(foreign.frames, (std::vector{standardFrame(0x123), standardFrame(0x7FF)}));
    EXPECT_EQ(cs2.batches, 1) << "one batch read, one delivery per protocol";
    EXPECT_EQ(wire.bus.received(Protocol::Cs2), 2u);
    EXPECT_EQ(wire.bus.received(Protocol::Foreign), 2u);
}

TEST(Bus, FramesNoSessionTakesAreCountedAndSeenNotDropped) {
    Wire wire(BusProfile{}); // a bus of modules whose protocols are not built yet
    QObject session;
    Deliveries cs2;
    cs2.subscribe(wire.bus, Protocol::Cs2, &session);
    QSignalSpy seen(&wire.bus, &Bus::framesSeen);
    wire.others.sendBatch(std::vector{cs2Frame(1), standardFrame(0x010)});
    ASSERT_TRUE(QTest::qWaitFor([&] { return wire.bus.received(Protocol::Foreign) == 2; }));
    EXPECT_TRUE(cs2.frames.empty()) << "no CS2 is expected on this bus";
    ASSERT_EQ(seen.count(), 1);
    EXPECT_EQ(seen.at(0).at(0).value<std::vector<can::CanFrame>>().size(), 2u);
    EXPECT_FALSE(seen.at(0).at(1).toBool()) << "received";
}

TEST(Bus, WhatTheAppWritesIsSeenAsOutgoing) {
    Wire wire;
    QSignalSpy seen(&wire.bus, &Bus::framesSeen);
    wire.app.send(cs2Frame(9));
    ASSERT_TRUE(QTest::qWaitFor([&] { return seen.count() == 1; }));
    EXPECT_EQ(seen.at(0).at(0).value<std::vector<can::CanFrame>>(), std::vector{cs2Frame(9)});
    EXPECT_TRUE(seen.at(0).at(1).toBool());
    EXPECT_EQ(wire.bus.received(Protocol::Cs2), 0u) << "our own frames are not received ones";
}

TEST(Bus, ASubscriberThatIsGoneGetsNothingMore) {
    Wire wire;
    auto session = std::make_unique<QObject>();
    QObject other;
    Deliveries gone;
    Deliveries stays;
    gone.subscribe(wire.bus, Protocol::Cs2, session.get());
    stays.subscribe(wire.bus, Protocol::Cs2, &other);
    session.reset();
    wire.others.send(cs2Frame(1));
    ASSERT_TRUE(QTest::qWaitFor([&] { return stays.frames.size() == 1; }));
    EXPECT_TRUE(gone.frames.empty());

    wire.bus.unsubscribe(&other);
    wire.others.send(cs2Frame(2));
    ASSERT_TRUE(QTest::qWaitFor([&] { return wire.bus.received(Protocol::Cs2) == 2; }));
    EXPECT_EQ(stays.frames.size(), 1u);
}

// A session that ends on what it read (the first subscriber unsubscribes the second one) must not be
// called once it left, even for the batch being delivered.
TEST(Bus, ASubscriberRemovedDuringADeliveryIsNotCalled) {
    Wire wire;
    QObject first;
    QObject second;
    Deliveries late;
    wire.bus.subscribe(Protocol::Cs2, &first,
                       [&](const std::vector<can::CanFrame>&) { wire.bus.unsubscribe(&second); });
    late.subscribe(wire.bus, Protocol::Cs2, &second);
    wire.others.send(cs2Frame(1));
    ASSERT_TRUE(QTest::qWaitFor([&] { return wire.bus.received(Protocol::Cs2) == 1; }));
    QTest::qWait(20);
    EXPECT_TRUE(late.frames.empty());
}

} // namespace
} // namespace stellwerk::bus
