// The simulated CS2 on a bus with MS1 handhelds: a real CS2 reads M-CAN frames as M-CAN (it is an MS1
// master, notes B§6.1), never as CS2 commands, although read as CS2 identifiers many of them look like one.

#include "SeedTrace.h"
#include "SimTestSupport.h"
#include "mcan/Id.h"

namespace stellwerk::sim::test {
namespace {

TEST(McanFrames, NoFrameOfTheChapter11TraceIsTakenForACs2Command) {
    StationProbe probe;
    const std::vector<CanFrame> trace = seeds::chapter11Trace(seeds::McanSeed002);
    ASSERT_EQ(trace.size(), 99u) << seeds::seedPath(seeds::McanSeed002);
    for (const CanFrame& f : trace) {
        if (mcan::isMcanId(f.id)) {
            EXPECT_TRUE(probe.send(f).empty()) << can::formatDocument(f);
        }
    }
}

// A session frame read as a CS2 frame has its command in the handle's bits 14..7: on a handle from 0x80 on
// it would be a CS2 command (discovery, a speed query ...). A master may hand out any handle.
TEST(McanFrames, NoSessionFrameOnAnyHandleIsTakenForACs2Command) {
    StationProbe probe;
    for (std::uint32_t handle = 0; handle < 0x10000; handle += 0x80)
        for (const std::uint8_t command : {0, 1, 2, 3, 4, 5, 7})
            for (std::uint8_t dlc = 0; dlc <= 8; ++dlc) {
                CanFrame f;
                f.id = mcan::sessionId({mcan::prio::Data, std::uint16_t(handle), command, 43});
                f.dlc = dlc;
                f.data = {0x40, 0x03, 0x00, 0x00, 0x00, 0x03, 0x00, 0x01};
                probe.station.receive(f);
            }
    EXPECT_TRUE(probe.batches.empty());
}

} // namespace
} // namespace stellwerk::sim::test
