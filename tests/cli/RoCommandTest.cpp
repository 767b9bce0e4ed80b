// `stellwerk-cli encode ro.*` and `decode --ro-module`: RO requests and answers (seed 004) as payloads and
// frames, with the document's examples.
#include "CommandRuns.h"
#include "DecodeCommand.h"
#include "EncodeCommand.h"

#include <gtest/gtest.h>
#include <sstream>

using stellwerk::cli::test::decode;
using stellwerk::cli::test::encode;

namespace {

// 004 §3.4 "Beispiel für das Beschreiben der ersten 16 Relais".
TEST(CliRo, EncodeSection3_4_RelayExample) {
    const auto run = encode({"ro.write", "width=word", "address=0x0000", "job=0x35", "value=0x2000"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "payload:  13 00 00 35 00 20 00 00\n");
}

// 004 §3.3 "Beispiel für ein Schreibbefehl", as a frame of the simulator's module 1.
TEST(CliRo, EncodeSection3_3_WriteExampleAsAFrame) {
    const auto run =
        encode({"ro.write", "width=byte", "address=0x0012", "job=0x34", "value=0x0F", "id=0x01FE0001"});
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "payload:  12 12 00 34 0F 00 00 00\n"
                       "document: 01FE0001 8 12 12 00 34 0F 00 00 00\n"
                       "candump:  01FE0001#121200340F000000\n");
}

// Derived (notes B4.4): the read of the relay word, 8 bytes by default or 4, and as an 11-bit frame.
TEST(CliRo, EncodeReadsDerived) {
    EXPECT_EQ(encode({"ro.read", "width=word", "address=0", "job=0x36"}).out,
              "payload:  23 00 00 36 00 00 00 00\n");
    EXPECT_EQ(
        encode({"ro.read", "width=word", "address=0", "job=0x36", "size=4", "id=0x700", "standard=true"}).out,
        "payload:  23 00 00 36\ndocument: 700 4 23 00 00 36\ncandump:  700#23000036\n");
}

TEST(CliRo, EncodeRefusesWhatNoModuleCouldRead) {
    auto run = encode({"ro.write", "width=byte", "address=0x12", "job=0x34", "value=0x100"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.err,
              "stellwerk-cli encode: ro.write: value=0x100 is not a number from 0 to 255 (byte write)\n");
    run = encode({"ro.write", "width=nibble", "address=0", "job=1", "value=1"});
    EXPECT_EQ(run.err, "stellwerk-cli encode: ro.write: width= must be bit, byte, word or long\n");
    run = encode({"ro.read", "width=word", "address=0x10000", "job=1"});
    EXPECT_EQ(run.err, "stellwerk-cli encode: ro.read: address=0x10000 is not a number from 0 to 65535\n");
    run = encode({"ro.read", "width=word", "address=0", "job=1", "value=3"});
    EXPECT_EQ(run.err, "stellwerk-cli encode: ro.read: a read carries no value= (004 §3.2.5)\n");
    run = encode({"ro.erase", "address=0"});
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.err, "stellwerk-cli encode: ro.erase: RO messages are ro.write and ro.read\n");
    run = encode({"ro.write", "width=word", "adress=0"});
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.err,
              "stellwerk-cli encode: unknown key adress (width, address, job, value, size, id, standard)\n");
}

TEST(CliRo, DecodeReadsAModulesRequestAndAnswer) {
    const auto run =
        decode({"--ro-module", "req=0x01FE0001,resp=0x01FF0001"},
               "01FE0001#1300003500200000\n01FF0001#01003500000000\n01FF0001#FD35\n00004711#0000000000\n");
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "01FE0001 8 13 00 00 35 00 20 00 00  ro.write-word  direction=request width=word "
                       "address=0x0000 job=0x35 value=0x2000\n"
                       "01FF0001 7 01 00 35 00 00 00 00  ro.ok  direction=answer width=none job=0x35 "
                       "value=0x00000000\n"
                       "01FF0001 2 FD 35  ro.duplicate-job  direction=answer job=0x35\n"
                       "00004711 5 00 00 00 00 00  system.stop uid=0x00000000 subcommand=0x00\n");
}

TEST(CliRo, DecodeElevenBitModuleAsJson) {
    const auto run = decode({"--json", "--ro-module", "req=0x700,resp=0x701,std"}, "701#01033600200000\n");
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.out, "{\"protocol\":\"ro\",\"module\":0,\"id\":\"701\",\"extended\":false,\"dlc\":7,"
                       "\"data\":\"01033600200000\",\"name\":\"ro.ok\",\"direction\":\"answer\",\"fields\":{"
                       "\"width\":\"word\",\"job\":\"0x36\",\"value\":\"0x2000\"}}\n");
}

TEST(CliRo, DecodeWithoutTheModuleCallsTheFrameForeignOrCs2) {
    EXPECT_NE(decode({}, "701#01033600200000\n").out.find("foreign 11-bit frame"), std::string::npos);
}

TEST(CliRo, DecodeMalformedRoFrameFails) {
    const auto run = decode({"--ro-module", "req=0x700,resp=0x701,std"}, "701#30\n");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.out,
              "701 1 30  ro.unknown  direction=answer error=\"answer code 0x30 is none of 0x01, 0xFD, "
              "0xFE (004 §3.5) (byte 1)\"\n");
}

TEST(CliRo, DecodeRefusesABadModuleOption) {
    auto run = decode({"--ro-module", "req=0x700"});
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.err, "stellwerk-cli decode: --ro-module needs req=ID,resp=ID[,std]\n");
    run = decode({"--ro-module", "req=0x800,resp=0x801,std"});
    EXPECT_EQ(run.err, "stellwerk-cli decode: --ro-module: id 0x00000800 does not fit a 11-bit frame\n");
    run = decode({"--ro-module", "req=1,resp=2,ext"});
    EXPECT_EQ(run.err, "stellwerk-cli decode: --ro-module: 'ext' is none of req=ID, resp=ID, std\n");
}

} // namespace
