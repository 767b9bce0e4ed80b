// TCP (field notes, "Framing"): 13-byte frames in a byte stream, split and joined arbitrarily; a station
// that goes away is reconnected with back-off; frames written meanwhile wait (up to a limit) or are refused.

#include "transport/TcpTransport.h"

#include "TestSupport.h"
#include "transport/NetworkFraming.h"

#include <QTcpServer>
#include <QTcpSocket>

namespace stellwerk::transport::test {
namespace {

using State = Transport::State;

// The station's side: a server on 127.0.0.1 that records what arrives and can stop and start again.
class FakeStation {
public:
    FakeStation() {
        QObject::connect(&server_, &QTcpServer::newConnection, &server_, [this] { accept(); });
        listen(0);
    }

    void listen(std::uint16_t port) {
        ASSERT_TRUE(server_.listen(QHostAddress::LocalHost, port)) << server_.errorString().toStdString();
        port_ = server_.serverPort();
    }
    // Closes the connection and stops listening, as a station that is switched off.
    void stop() {
        server_.close();
        if (client_)
            client_->abort();
        client_.reset();
    }
    std::uint16_t port() const { return port_; }
    bool waitForClient() {
        return waitFor([this] { return client_ != nullptr; });
    }
    QByteArray& received() { return received_; }
    bool waitForBytes(qsizetype count) {
        return waitFor([&] { return received_.size() >= count; });
    }

    void write(const QByteArray& bytes) {
        client_->write(bytes);
        client_->flush();
    }
    // Writes `bytes` in pieces of `size` bytes, each flushed to the socket and given to the event loop.
    void writeInPieces(const QByteArray& bytes, qsizetype size) {
        client_->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        for (qsizetype at = 0; at < bytes.size(); at += size) {
            write(bytes.mid(at, size));
            QCoreApplication::processEvents();
        }
    }
    void closeClient() { client_->disconnectFromHost(); }

private:
    void accept() {
        client_.reset(server_.nextPendingConnection());
        client_->setParent(nullptr);
        QObject::connect(client_.get(), &QTcpSocket::readyRead, client_.get(),
                         [this] { received_.append(client_->readAll()); });
    }

    QTcpServer server_;
    std::unique_ptr<QTcpSocket> client_;
    QByteArray received_;
    std::uint16_t port_ = 0;
};

class TcpTransportTest : public ::testing::Test {
protected:
    void SetUp() override {
        settings.host = QStringLiteral("127.0.0.1");
        settings.port = station.port();
        settings.reconnect = fastReconnect();
        transport = std::make_unique<TcpTransport>(settings);
        recorder = std::make_unique<Recorder>(*transport);
    }

    void connectToStation() {
        transport->open();
        ASSERT_TRUE(waitForState(*transport, State::Connected));
        ASSERT_TRUE(station.waitForClient());
    }

    FakeStation station;
    TcpSettings settings;
    std::unique_ptr<TcpTransport> transport;
    std::unique_ptr<Recorder> recorder;
};

TEST_F(TcpTransportTest, ConnectsToTheStation) {
    connectToStation();
    EXPECT_EQ(recorder->states, (std::vector{State::Connecting, State::Connected}));
    EXPECT_EQ(transport->description(), QStringLiteral("tcp://127.0.0.1:%1").arg(settings.port));
    EXPECT_EQ(transport->counters().reconnects, 0u);
}

TEST_F(TcpTransportTest, FrameSplitIntoOneByteSegmentsIsReassembled) {
    connectToStation();
    station.writeInPieces(encodeFrames(numberedFrames(3)), 1);
    ASSERT_TRUE(recorder->waitForFrames(3));
    EXPECT_EQ(recorder->frames(), numberedFrames(3));
    EXPECT_EQ(transport->counters().malformed, 0u);
}

TEST_F(TcpTransportTest, FramesSplitAcrossOddSegmentsAreReassembled) {
    connectToStation();
    station.writeInPieces(encodeFrames(numberedFrames(30)), 7);
    ASSERT_TRUE(recorder->waitForFrames(30));
    EXPECT_EQ(recorder->frames(), numberedFrames(30));
}

TEST_F(TcpTransportTest, SeveralFramesInOneWriteArriveInBatches) {
    connectToStation();
    station.write(encodeFrames(numberedFrames(100)));
    ASSERT_TRUE(recorder->waitForFrames(100));
    EXPECT_EQ(recorder->frames(), numberedFrames(100));
    EXPECT_LT(recorder->batches.size(), 10u) << "one signal per read, not per frame";
    EXPECT_EQ(transport->counters().framesIn, 100u);
}

TEST_F(TcpTransportTest, SentFramesReachTheStationAs13ByteFrames) {
    connectToStation();
    EXPECT_TRUE(transport->send(numbered(1)));
    EXPECT_EQ(transport->sendBatch(numberedFrames(4, 2)), 4u);
    ASSERT_TRUE(station.waitForBytes(5 * 13));
    EXPECT_EQ(station.received(), encodeFrames(numberedFrames(5, 1)));
    EXPECT_EQ(transport->counters().framesOut, 5u);
}

// The 13-byte form has no room for the frame format: a standard frame is refused with a problem that says
// why, and the frames before it in the batch still go out; nothing of it reaches the station.
TEST_F(TcpTransportTest, StandardFrameIsRefusedWithAClearProblem) {
    connectToStation();
    const std::uint8_t payload[] = {1};
    std::vector frames = numberedFrames(2, 1);
    frames.push_back(can::CanFrame::standard(0x123, payload));
    frames.push_back(numbered(3));
    EXPECT_EQ(transport->sendBatch(frames), 2u);
    EXPECT_FALSE(transport->send(can::CanFrame::standard(0x123, payload)));
    EXPECT_EQ(transport->counters().dropped, 3u);
    EXPECT_TRUE(transport->send(numbered(3))) << "the transport goes on";
    ASSERT_TRUE(station.waitForBytes(3 * 13));
    EXPECT_EQ(station.received(), encodeFrames(numberedFrames(3, 1))) << "nothing of the refused frames";
    ASSERT_FALSE(recorder->problems.empty());
    EXPECT_TRUE(
        recorder->problems.back().contains(QLatin1String("standard (11-bit) CAN frame with id 0x123")))
        << recorder->problems.back().toStdString();
}

TEST_F(TcpTransportTest, FrameWithDlcAboveEightIsCountedAndLeftOut) {
    connectToStation();
    QByteArray bytes = encodeFrames(numberedFrames(3));
    bytes[13 + 4] = char(12);
    station.write(bytes);
    ASSERT_TRUE(recorder->waitForFrames(2));
    EXPECT_EQ(recorder->frames(), (std::vector{numbered(0), numbered(2)}));
    EXPECT_EQ(transport->counters().malformed, 1u);
}

TEST_F(TcpTransportTest, ConnectionEndingInsideAFrameCountsItMalformed) {
    connectToStation();
    station.write(encodeFrames(numberedFrames(2)).left(20));
    station.closeClient();
    ASSERT_TRUE(waitForState(*transport, State::Reconnecting));
    EXPECT_EQ(recorder->frames(), numberedFrames(1));
    EXPECT_EQ(transport->counters().malformed, 1u);
}

// Issue 11: nothing said while the station was away reaches it when it is back.
TEST_F(TcpTransportTest, StationThatRestartsIsReconnectedAndGetsNothingSentMeanwhile) {
    connectToStation();
    station.stop();
    ASSERT_TRUE(waitForState(*transport, State::Reconnecting));
    ASSERT_FALSE(recorder->problems.empty());
    EXPECT_TRUE(recorder->problems[0].startsWith(transport->description()))
        << recorder->problems[0].toStdString();
    EXPECT_EQ(transport->sendBatch(numberedFrames(3)), 0u);
    EXPECT_EQ(transport->queuedFrames(), 0u);
    EXPECT_EQ(transport->counters().dropped, 3u);

    station.listen(settings.port);
    ASSERT_TRUE(waitForState(*transport, State::Connected));
    EXPECT_EQ(transport->counters().reconnects, 1u);
    EXPECT_TRUE(transport->send(numbered(4)));
    ASSERT_TRUE(station.waitForBytes(13));
    EXPECT_EQ(station.received(), encodeFrames(std::vector{numbered(4)}));

    station.write(encodeFrames(numberedFrames(2, 7)));
    ASSERT_TRUE(recorder->waitForFrames(2));
    EXPECT_EQ(recorder->frames(), numberedFrames(2, 7));
}

TEST_F(TcpTransportTest, FramesBeyondTheQueueLimitAreRefusedWhileTheStationIsAway) {
    station.stop();
    transport->setQueueLimit(5);
    transport->open();
    ASSERT_TRUE(waitForState(*transport, State::Reconnecting));
    EXPECT_EQ(transport->sendBatch(numberedFrames(5)), 5u);
    EXPECT_FALSE(transport->send(numbered(5)));
    EXPECT_EQ(transport->sendBatch(numberedFrames(2, 6)), 0u);
    EXPECT_EQ(transport->counters().dropped, 3u);

    station.listen(settings.port);
    ASSERT_TRUE(station.waitForBytes(5 * 13));
    EXPECT_EQ(station.received(), encodeFrames(numberedFrames(5)));
    EXPECT_EQ(transport->counters().reconnects, 0u) << "the first connection is not a reconnection";
}

TEST_F(TcpTransportTest, UnreachableStationIsRetriedWithGrowingDelays) {
    station.stop();
    transport->open();
    ASSERT_TRUE(waitFor([&] { return recorder->problems.size() >= 4; }));
    const std::vector<const char*> delays{"20 ms", "40 ms", "80 ms", "80 ms"};
    for (std::size_t i = 0; i < delays.size(); ++i)
        EXPECT_TRUE(recorder->problems[i].endsWith(QLatin1String(delays[i])))
            << recorder->problems[i].toStdString();
    EXPECT_EQ(transport->state(), State::Reconnecting);
}

TEST_F(TcpTransportTest, ConnectionFailedGivesTheReasonWithoutTheRetryPlan) {
    QStringList reasons;
    QObject::connect(transport.get(), &Transport::connectionFailed,
                     [&](const QString& reason) { reasons.append(reason); });
    station.stop();
    transport->open();
    ASSERT_TRUE(waitFor([&] { return !reasons.isEmpty() && !recorder->problems.empty(); }));
    EXPECT_TRUE(reasons[0].startsWith(transport->description() + QStringLiteral(": ")))
        << reasons[0].toStdString();
    EXPECT_FALSE(reasons[0].contains(QStringLiteral("trying again"))) << reasons[0].toStdString();
    EXPECT_EQ(recorder->problems[0], reasons[0] + QStringLiteral("; trying again in 20 ms"));
}

TEST_F(TcpTransportTest, CloseDiscardsWaitingFramesAsDroppedAndStopsRetrying) {
    station.stop();
    transport->open();
    ASSERT_TRUE(waitForState(*transport, State::Reconnecting));
    transport->sendBatch(numberedFrames(3));
    transport->close();
    EXPECT_EQ(transport->state(), State::Closed);
    EXPECT_EQ(transport->counters().dropped, 3u);
    EXPECT_FALSE(transport->send(numbered(9)));
    station.listen(settings.port);
    QTest::qWait(100);
    EXPECT_EQ(transport->state(), State::Closed);
    EXPECT_TRUE(station.received().isEmpty());
}

// A peer that accepts but never reads: once the socket holds more than a little, frames wait in the
// transport's bounded queue, where a given-up command is withdrawn, instead of piling up in memory.
TEST(TcpTransportToAPeerThatNeverReads, KeepsFramesInItsBoundedQueueWhereTheyCanBeWithdrawn) {
    QTcpServer deaf; // the kernel accepts the connection; nobody ever takes it or reads
    ASSERT_TRUE(deaf.listen(QHostAddress::LocalHost, 0));
    deaf.pauseAccepting(); // else the server would take it and read into its own buffer
    TcpTransport transport(TcpSettings{QStringLiteral("127.0.0.1"), deaf.serverPort(), fastReconnect()});
    transport.setQueueLimit(500);
    transport.open();
    ASSERT_TRUE(waitForState(transport, State::Connected));
    std::size_t accepted = 0;
    QElapsedTimer clock;
    clock.start();
    while (transport.queuedFrames() < 100 && clock.elapsed() < 10000) {
        accepted += transport.sendBatch(numberedFrames(100), 1);
        QCoreApplication::processEvents();
    }
    ASSERT_GE(transport.queuedFrames(), 100u) << "the wire never became busy after " << accepted << " frames";
    EXPECT_LE(transport.queuedFrames(), 500u);
    EXPECT_EQ(transport.sendBatch(numberedFrames(600), 2), 500u - transport.queuedFrames());
    EXPECT_EQ(transport.queuedFrames(), 500u) << "the queue is bounded";
    const auto dropped = transport.counters().dropped;
    const std::size_t withdrawn = transport.withdraw(1) + transport.withdraw(2);
    EXPECT_EQ(withdrawn, 500u);
    EXPECT_EQ(transport.queuedFrames(), 0u);
    EXPECT_EQ(transport.counters().dropped, dropped + 500u);
}

// A reset ends the connection at once (what the peer did not get is thrown away) and connects again.
TEST_F(TcpTransportTest, ResetConnectionReconnects) {
    connectToStation();
    EXPECT_TRUE(transport->resetConnection(QStringLiteral("test")));
    EXPECT_EQ(transport->state(), State::Reconnecting);
    EXPECT_FALSE(transport->send(numbered(1)));
    ASSERT_TRUE(waitForState(*transport, State::Connected));
    EXPECT_EQ(transport->counters().reconnects, 1u);
    ASSERT_TRUE(station.waitForClient());
    EXPECT_TRUE(transport->send(numbered(2)));
    ASSERT_TRUE(station.waitForBytes(13));
    EXPECT_EQ(station.received(), encodeFrames(std::vector{numbered(2)}));
}

TEST_F(TcpTransportTest, ReopenedTransportConnectsAgain) {
    connectToStation();
    transport->close();
    transport->open();
    ASSERT_TRUE(waitForState(*transport, State::Connected));
    EXPECT_TRUE(transport->send(numbered(3)));
    ASSERT_TRUE(station.waitForBytes(13));
    EXPECT_EQ(transport->counters().reconnects, 0u);
}

} // namespace
} // namespace stellwerk::transport::test
