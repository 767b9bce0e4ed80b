#!/usr/bin/env python3
"""Writes the committed seed inputs of the fuzz targets (fuzz/seeds/<target>/) from the examples the
unit tests use: protocol-document frames, small .cs2 files, streams and status-data packets.
scripts/fuzz.sh adds the real files of ../shared/corpus at run time (they are not copied here)."""
import os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def crc16(data, crc=0xFFFF):
    for byte in data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) if crc & 0x8000 else crc << 1
            crc &= 0xFFFF
    return crc


def frame(command, response, hash_, data, prio=0):
    can_id = (prio << 25) | (command << 17) | (int(response) << 16) | hash_
    return struct.pack(">IB", can_id, len(data)) + bytes(data) + bytes(8 - len(data))


def write(target, name, data):
    folder = os.path.join(HERE, "seeds", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode("latin-1"))


DOCUMENT_FRAMES = {  # the protocol document's examples (tests/core/cs2/DocumentChapter*Test.cpp)
    "system-stop": frame(0x00, False, 0x4711, [0, 0, 0, 0, 0]),
    "system-go": frame(0x00, False, 0x4711, [0, 0, 0, 0, 1]),
    "loco-speed": frame(0x04, False, 0x4711, [0, 0, 0xC0, 0x03, 0x01, 0x20]),
    "loco-direction": frame(0x05, False, 0x4711, [0, 0, 0x40, 0x05, 0x01]),
    "loco-function": frame(0x06, False, 0x4711, [0, 0, 0x40, 0x05, 0x00, 0x01]),
    "accessory": frame(0x0B, False, 0x4711, [0, 0, 0x30, 0x00, 0x01, 0x01]),
    "s88-event": frame(0x11, True, 0x4711, [0, 1, 0, 5, 0, 1, 0, 0x64]),
    "ping": frame(0x18, False, 0x4711, []),
    "ping-answer": frame(0x18, True, 0x4711, [0x43, 0x53, 0x32, 0x08, 0x0B, 0x01, 0x00, 0x03]),
    "config-request": frame(0x20, False, 0x4711, list(b"loks\0\0\0\0")),
    "stream-header": frame(0x21, False, 0x4711, [0, 0, 0, 0x5F, 0x21, 0x70]),
    "status-request": frame(0x1D, False, 0x4711, [0x43, 0x53, 0x32, 0x08, 0]),
    "system-status": frame(0x00, False, 0x4711, [0, 0, 0, 0, 0x0B, 1]),
    "mfx-bind": frame(0x02, False, 0x4711, [0xFF, 0xFF, 0xFF, 0xF0, 0x40, 0x05]),
    "config-read": frame(0x07, False, 0x4711, [0, 0, 0xC0, 0x03, 0, 1, 1]),
    "automation-request": frame(0x30, False, 0x4711, [0, 0, 0x41, 0x31, 1, 0]),
    "automation-status-unknown": frame(0x30, True, 0x4711, [0x53, 0x57, 0x42, 0x33, 7, 0]),
    "automation-block-loco": frame(0x30, True, 0x4711, [0, 5, 0x41, 0x32, 0, 0, 0x40, 0x05]),
}
for name, data in DOCUMENT_FRAMES.items():
    write("frame_decode", name, data)
frames = list(DOCUMENT_FRAMES.values())
write("network_stream", "whole", b"\x00" + b"".join(frames[:4]))
write("network_stream", "cut-5-13-1", bytes([5, 13, 1, 0]) + b"".join(frames[:6]) + frames[6][:7])
write("network_stream", "malformed-dlc", bytes([13, 0]) + frames[0][:4] + b"\x10" + frames[0][5:] + frames[1])

for name, line in {
    "document": "00004711 5 00 00 00 00 00",
    "document-comment": "00084711 6 00 00 C0 03 01 20 ; loco speed",
    "candump": "00004711#0000000000",
    "candump-time": "(1700000000.000000) can0 00084711#0000C0030120",
    "bracketed": "can0  00004711   [5]  00 00 00 00 00",
    "can-monitor": "can0 00004711 [8] 7b(00) 00 00 00 00 00 00 00",
    "network": "00004711050000000000000000",
    "network-spaced": "00 00 47 11 05 00 00 00 00 00 00 00 00",
    "latin1-byte": "\xe4\n",  # issue 11: decode --json copied it raw
    "network-dlc16": "00004711100000000000000000",  # issue 11: DLC 16 was accepted
}.items():
    write("frame_text", name, line)

# cli_arguments: a choice byte picks the message name (index into messageNames()), then lines.
for name, data in {
    "speed": b"\x13locId=0xC003\nspeed=288\nmfx:5\n",
    "stop": b"\x01\ndcc:3\nforward\n",
    "accessory": b"\x19locId=0x3000\nposition=1\ncurrent=1\nmm2:5\ngreen\n",
    "words": b"\x00\n0x4005\n16389\nsx1:4\ntoggle\n1000\n31\non\nhp1\n0x43533201\n",
}.items():
    write("cli_arguments", name, data)

# cs2_document: first byte odd = a .sr2 file name.
for name, text in {
    "locomotive": "\x00[lokomotive]\nversion\n .minor=3\nlokomotive\n .name=BR 01\n .uid=0x4006\n .adresse=0x6\n"
                  " .typ=mm2_prg\n .funktionen\n ..nr=0\n ..typ=1\n",
    "cs3-escapes": "\x00[lokomotive]\nlokomotive\n .name=BR#20218\n .dectyp=#cc\n",
    "cs3-stray": "\x00[lokomotive]\n.dectyp=#cc\n",  # issue 11: #cc became a raw byte in cs2 json
    "accessories": "\x00[magnetartikel]\nversion\n .minor=1\nartikel\n .id=1\n .typ=standardweiche\n .stellung=1\n",
    "accessories-stray": "\x00[magnetartikel]\n.artikel\nartikel\n .id=1\n",  # issue 11: cs2 format lost it
    "routes": "\x00[fahrstrassen]\nfahrstrasse\n .id=1\n .name=FS 1\n .item\n ..magnetartikel=1\n ..stellung=1\n",
    "routes-stray": "\x00[fahrstrassen]\n.fahrstrasse\nfahrstrasse\n .id=2\n",
    "track-plan": "\x00[gleisbild]\nversion\n .major=1\ngroesse\nseite\n .id=1\n .name=Bahnhof\n",
    "track-page": "\x00[gleisbildseite]\npage=1\nelement\n .id=0x102\n .typ=gerade\n .drehung=1\n",
    "status": "\x01[lokomotive]\nlokomotive\n .name=BR 01\n .richtung=1\n",
    "crlf": "\x00[magnetartikel]\r\nartikel\r\n .id=2\r\n",
    "latin1": "\x00[lokomotive]\nlokomotive\n .name=Gro\xdfe\n",
}.items():
    write("cs2_document", name, text)


def stream_frames(payload, hash_=0x4711, broadcast=False):
    padded = payload + bytes(-len(payload) % 8)
    header = list(struct.pack(">IH", len(payload), crc16(padded))) + ([0x7B] if broadcast else [])
    out = frame(0x21, False, hash_, header)
    for i in range(0, len(padded), 8):
        out += frame(0x21, False, 0x0300 + i // 8 + 1, list(padded[i:i + 8]))
    return out


text = b"[gleisbildseite]\nversion\n .major=1\n"
compressed = struct.pack(">I", len(text)) + zlib.compress(text)
request = frame(0x20, False, 0x4711, list(b"loks\0\0\0\0"))
write("config_stream", "compressed", b"\x00" + request + stream_frames(compressed))
write("config_stream", "broadcast", b"\x00" + stream_frames(compressed, broadcast=True))
write("config_stream", "plain", b"\x00" + stream_frames(b"[lokliste]\nlok\n .name=x\n"))
write("config_stream", "bad-crc", b"\x00" + stream_frames(compressed)[:-1] + b"\x01")
write("config_stream", "roundtrip-loks", b"\x80" + text)
write("config_stream", "roundtrip-lokinfo", b"\x81[lokomotive]\nlok\n .name=BR 01\n")
write("config_stream", "roundtrip-small-plain", b"\x81abcdx ")  # issue 11: read as compressed
write("config_stream", "roundtrip-lokdb", b"\x82\x01\x02\x00\x00\x00\x00\x00\x00")


def status_frames(block):
    padded = block + bytes(-len(block) % 8)
    out = b""
    for i in range(0, len(padded), 8):
        out += frame(0x1D, True, 0x0300 + i // 8 + 1, list(padded[i:i + 8]))
    return out + frame(0x1D, True, 0x4711, [0x43, 0x53, 0x32, 0x08, 0, len(padded) // 8])


summary = struct.pack(">BBHI", 2, 1, 0, 0x12345678) + b"60113\0\0\0" + b"Gleisbox\0" + b"\0"
write("status_data", "summary", status_frames(summary))
write("status_data", "summary-escape", status_frames(struct.pack(">BBHI", 1, 0, 0, 1) + b"\x1b[2J\xff\0\0\0" +
                                                       b"Box\x1b]0;x\x07\0"))  # issue 11: raw article
reading = bytes([1, 0xFD, 0x30, 0xF0, 0xE0, 0xC0, 0, 0]) + struct.pack(">HHHH", 0x100, 0x200, 0x300, 0x400) + \
    b"TRACK\0" + b"0.000\0" + b"2.500\0" + b"A\0"
write("status_data", "reading", status_frames(bytes(16) + reading))
config = bytes([2, 1, 2, 0, 0, 0, 0, 0]) + b"Sprache\0Deutsch\0English\0"
write("status_data", "config-list", status_frames(config))

# Locomotive pictures: .icon values as stations write them, and a PNG header (240 x 80).
write("loco_picture", "cs2-name", b"BR 218")
write("loco_picture", "cs3-path", b"#2Fusr#2Flocal#2Fcs3#2Flokicons#2FmSD3_Logo")
write("loco_picture", "climbing", b"../../etc/passwd")
write("loco_picture", "png-header", b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" +
      struct.pack(">II", 240, 80) + b"\x08\x06\0\0\0" + bytes(4) + bytes(4) + b"IEND\xae\x42\x60\x82")

# mcan_frame: M-CAN frames in bus order (13-byte network form). The chapter-11 trace of the M-CAN document
# (an MS1 logging into an ECoS; ../shared/docs/mcan-notes.md B§4.2, frames #3-34, #45-50, #60-65, #76-83,
# #92-93) and the forms the trace lacks.
def mcan(can_id, data_hex=""):
    data = bytes.fromhex(data_hex)
    return struct.pack(">IB", int(can_id, 16), len(data)) + data + bytes(8 - len(data))


MCAN_LOGIN = [
    ("1C00007E", ""), ("1C0030FE", "000484D300010001"), ("1C08B07E", ""), ("1C08B0FE", "0000009700000103"),
    ("1C11307E", ""), ("1C1130FE", "0113000500000000"), ("1ECDB07E", ""), ("1ECDB0FE", "0000000103000001"),
    ("1C02307E", "000204B300020003"), ("1C02B07E", "0000009701004010"), ("1C03307E", "0100006700004010"),
    ("1C03B07E", "0000401001080010"), ("0C0007AA", "0000002B000204B3"), ("1C03B0FE", "000204B30002AB00"),
]
MCAN_UPGRADE = [
    ("18000A2B", "402B"), ("18000A2A", "402B000000080001"), ("180020AA", "41000000"), ("180020AA", "02000000"),
    ("180020AA", "02000004"), ("180020AA", "02000008"), ("180020AB", "41000000000A"),
    ("180020AB", "020000004B53204D"), ("180020AB", "02000004533100"), ("180020AB", "0200000800"),
    ("180009AB", "0300"), ("180020AA", "0200000C"), ("180020AB", "0200000C00"), ("180009AA", "0300000000030001"),
    ("18000D2B", "0101"), ("18000D2A", "010101"), ("18000D2B", "0100"), ("10000D2A", "010000"),
]
MCAN_LOCO = [
    ("180009AB", "80020000"), ("180009AA", "8002000000090001"), ("180009AB", "80020009"), ("180024AB", "40030000"),
    ("180009AA", "80020009"), ("180024AA", "400300000003"), ("1800252B", "0101"), ("1800252A", "01010101"),
    ("1800252B", "0100"), ("1800252A", "010000"), ("1800252B", "0201"), ("1800252A", "0201"),
    ("180024AB", "02000000"), ("180024AA", "0200000030303320"), ("180024AB", "02000004"),
    ("180024AA", "020000043133312D"), ("180024AB", "02000008"), ("180024AA", "0200000830000000"),
    ("0C0007AB", "0000002A"), ("0C0007AA", "0000002A000484D3"), ("1400242B", "030000080001"),
    ("1400242A", "030000080001"),
]


def mcan_frames(frames):
    return b"".join(mcan(*f) for f in frames)


write("mcan_frame", "trace-login", mcan_frames(MCAN_LOGIN))
write("mcan_frame", "trace-upgrade", mcan_frames(MCAN_LOGIN + MCAN_UPGRADE))
write("mcan_frame", "trace-loco", mcan_frames(MCAN_LOGIN + MCAN_UPGRADE + MCAN_LOCO))
write("mcan_frame", "relogin", mcan_frames(MCAN_LOGIN + MCAN_UPGRADE + MCAN_LOGIN[-1:] + MCAN_UPGRADE[-4:]))
write("mcan_frame", "bus-busy", mcan("00000380", "0000000000000000"))
write("mcan_frame", "stack-add-delete", mcan_frames(MCAN_LOGIN + MCAN_UPGRADE + [
    ("18000E2A", "8000FFFF00090003"), ("1800252B", "0101"), ("18000EAA", "8000000000090001")]))
write("mcan_frame", "flash", mcan_frames([
    ("1C02807F", "00029C03"), ("1C08047F", "00029C03"), ("1C08047F", "00029C0300000097"),
    ("1C08007F", "00029C03"), ("1C0800FF", "0000000000000226"), ("1C08017F", "0000000011223344"),
    ("1C08017F", "000002241122"), ("1C0801FF", "00029C03"), ("1C00007F", "00029C03")]))
write("mcan_frame", "ecan-and-cs2", mcan_frames([
    ("00000201", "00"), ("10000281", "0000"), ("01000106", "03067166"), ("00084711", "0000C0030120"),
    ("00080201", "0000000000")]))
write("mcan_frame", "hostile-name", mcan_frames(MCAN_LOGIN + MCAN_UPGRADE[:2] + [
    ("180020AB", "020000001B5B324A"), ("180020AB", "02000004FF07005C")]))
write("mcan_frame", "dlc-above-eight", struct.pack(">IB", 0x0C0007AB, 12) + bytes(8))

# ro_frame: RO module payloads (seed 004), 9-byte records: header (bit 0 answer id, bit 1 11-bit module,
# bits 4..7 DLC) and 8 data bytes. The document's two requests (§3.3, §3.4), the notes' derived answers
# (B4.4) and refusals.
def ro(answer, standard, data_hex):
    data = bytes.fromhex(data_hex)
    return bytes([(len(data) << 4) | (2 if standard else 0) | (1 if answer else 0)]) + data + bytes(8 - len(data))


write("ro_frame", "section-3-3-write-byte", ro(False, False, "121200340F000000"))
write("ro_frame", "section-3-4-relays", ro(False, False, "1300003500200000") + ro(True, False, "01003500000000"))
write("ro_frame", "derived-read-word", ro(False, True, "23000036") + ro(True, True, "01033600200000"))
write("ro_frame", "derived-duplicate-and-invalid", ro(True, False, "FD35") + ro(True, False, "FE") +
      ro(False, False, "3000003600000000"))
write("ro_frame", "every-command", b"".join(ro(False, False, "%02X000001FF000000" % c)
                                            for c in (0x11, 0x12, 0x13, 0x14, 0x21, 0x22, 0x23, 0x24)))
write("ro_frame", "refused", ro(True, False, "0105340000000000") + ro(True, False, "FD35010203040506") +
      ro(False, False, "12120034FF010000") + bytes([0xF0]) + bytes(8))

# orc_frame: OpenRailCAN frames (13-byte network form): the ORC notes' derived vectors (A4.2, not printed in
# the document), every command group, Stellwerk's bus-id extension, and malformed forms.
ORC_DERIVED = [
    ("09000000", "00"), ("09000000", "012E01"), ("09000042", "0A0102"), ("09020000", "00"),
    ("11100000", "03300501"), ("11020000", "010048"), ("11030000", "01004801F4"), ("17122E01", "102E0105"),
    ("19200000", "003A2E2E01"), ("1D212E01", "003A2E2E010102"),
]
def orc_id(prio, type_, group, answer, bus_id):  # layout L2 (core/orc/OrcId.h)
    return "%08X" % (prio << 27 | type_ << 25 | group << 17 | int(answer) << 16 | bus_id)


ORC_GROUPS = [
    (orc_id(2, 0, 0x81, 0, 0), "020048"), (orc_id(2, 0, 0x81, 0, 0), "0300480000000F"),
    (orc_id(2, 0, 0x81, 1, 0x42), "04004804010000"), (orc_id(2, 0, 0x88, 0, 0), "02"),
    (orc_id(2, 0, 0x89, 0, 0), "01"), (orc_id(2, 0, 0x89, 0, 0), "102E02"),
    (orc_id(2, 3, 0x89, 1, 0x2E02), "102E02FF00FF00"), (orc_id(3, 0, 0x90, 0, 0), "0100000000"),
    (orc_id(3, 2, 0x90, 1, 0x2E01), "013A2E2E010102"), (orc_id(3, 0, 0x90, 0, 0), "023A2E2E012E02"),
    (orc_id(3, 2, 0x90, 1, 0x2E02), "023A2E2E012E02"), (orc_id(3, 0, 0xF0, 0, 0), "00"),
    (orc_id(3, 0, 0xF0, 0, 0), "012E0103"), (orc_id(3, 2, 0xF0, 1, 0x2E01), "012E013A2E2E0102"),
    (orc_id(3, 0, 0xF0, 0, 0), "022E0100100004"), (orc_id(3, 2, 0xF0, 1, 0x2E01), "022E01800020"),
    (orc_id(3, 0, 0xF0, 0, 0), "042E010701020304"), (orc_id(3, 2, 0xF0, 1, 0x2E01), "042E010701020304"),
    (orc_id(3, 0, 0xF0, 0, 0), "052E0107CBF43926"),
]
ORC_MALFORMED = [
    ("09000000", "002E"), ("09010000", "00"), ("01000000", "00"), ("09400000", "00"), ("11100000", "033005"),
    ("11020000", "04004801010200"), (orc_id(3, 0, 0xF0, 0, 0), "042E010001"),
]
write("orc_frame", "derived-a42", mcan_frames(ORC_DERIVED))
write("orc_frame", "every-group", mcan_frames(ORC_GROUPS))
write("orc_frame", "malformed", mcan_frames(ORC_MALFORMED))
write("orc_frame", "beside-cs2-and-mcan", mcan_frames(ORC_DERIVED[:3] + [("00084711", "0000C0030120"), ("0C0007AB", "0000002A")]))
write("orc_frame", "dlc-above-eight", struct.pack(">IB", 0x11100000, 12) + bytes(8))
# Found by a long run: an enkoder Status with five status bytes (DLC 8) shifted a 32-bit value by 32.
write("orc_frame", "encoder-status-five-bytes", mcan_frames([("11122E01", "102E010102030405"), ("11132E01", "102E01FFFFFFFFFF")]))
# Found by a long run: a single-function frame with DLC 8 decoded, and encoded back with DLC 7.
write("orc_frame", "loco-function-dlc8", mcan_frames([("11020000", "0400000000000000"), ("11020000", "0400480101000000")]))



# track_graph: pages as .cs2 text, each [gleisbildseite] a page (numbered 0, 1, ... as the target reads
# them), with [magnetartikel] and [fahrstrassen] sections. The demo layout is ours; the real pages of
# ../shared/corpus are added by scripts/fuzz.sh at run time.
def page(tiles):
    lines = ["[gleisbildseite]", "version", " .major=1"]
    for column, row, typ, rotation, article, text in tiles:
        lines += ["element", " .id=0x%x" % (row << 8 | column), " .typ=" + typ]
        lines += [" .drehung=%d" % rotation] if rotation else []
        lines += [" .artikel=%d" % article] + ([" .text=" + text] if text else [])
    return "\n".join(lines) + "\n"


def line(row, contacts, first=0):  # a buffer stop, contacts with a straight between each, a buffer stop
    tiles, column = [(first, row, "prellbock", 2, -1, "")], first + 1
    for i, contact in enumerate(contacts):
        if i:
            tiles.append((column, row, "gerade", 0, -1, ""))
            column += 1
        tiles.append((column, row, "s88kontakt", 0, contact, ""))
        column += 1
    return tiles + [(column, row, "prellbock", 0, -1, "")]


DEMO = os.path.join(HERE, "..", "resources", "demo-layout", "config")
demo = "".join(open(os.path.join(DEMO, "gleisbilder", name + ".cs2"), encoding="utf-8").read()
               for name in ("Bahnhof", "Strecke", "Bw"))
demo += open(os.path.join(DEMO, "magnetartikel.cs2"), encoding="utf-8").read()
demo += open(os.path.join(DEMO, "fahrstrassen.cs2"), encoding="utf-8").read()
write("track_graph", "demo-layout", demo.encode("utf-8"))
arrows = [(0, 0, "prellbock", 2, -1, ""), (1, 0, "s88kontakt", 0, 5, "Ost"), (2, 0, "pfeil", 0, 1, "Seite1")]
back = [(0, 0, "pfeil", 2, 0, ""), (1, 0, "s88kontakt", 0, 6, ""), (2, 0, "prellbock", 0, -1, "")]
write("track_graph", "overview-detail", (page(arrows) + page(back) + page(line(0, [5, 6]))).encode())
write("track_graph", "overview-disagrees", (page(arrows) + page(back) + page(line(0, [5, 7, 6]))).encode())
write("track_graph", "crossing-underpass", page(
    [(0, 2, "prellbock", 2, -1, ""), (1, 2, "s88kontakt", 0, 1, ""), (2, 2, "kreuzung", 0, -1, ""),
     (3, 2, "s88kontakt", 0, 2, ""), (4, 2, "unterfuehrung", 0, -1, ""), (5, 2, "prellbock", 0, -1, ""),
     (2, 0, "prellbock", 1, -1, ""), (2, 1, "s88kontakt", 1, 3, ""), (2, 3, "s88kontakt", 1, 4, ""),
     (2, 4, "prellbock", 3, -1, ""), (4, 1, "s88bogen", 1, 8, ""), (4, 3, "gerade", 1, -1, "")]).encode())
write("track_graph", "slips-and-three-way", page(
    [(0, 2, "prellbock", 2, -1, ""), (1, 2, "s88kontakt", 0, 1, ""), (2, 2, "dkweiche_2", 0, 18, ""),
     (3, 2, "dreiwegweiche", 3, 20, ""), (2, 1, "s88kontakt", 1, 3, ""), (2, 3, "s88kontakt", 1, 4, ""),
     (3, 1, "bogen", 0, -1, ""), (4, 1, "s88kontakt", 0, 5, ""), (4, 2, "s88kontakt", 0, 6, ""),
     (3, 3, "bogen", 1, -1, ""), (4, 3, "hosentraeger", 0, 22, ""), (5, 2, "yweiche", 1, 24, "")]).encode())
write("track_graph", "loop-and-signals", page(
    [(0, 0, "s88bogen", 0, 1, ""), (1, 0, "signal", 0, 10, "S"), (2, 0, "bogen", 3, -1, ""),
     (2, 1, "s88bogen", 2, 2, ""), (1, 1, "signal_f_hp012", 2, 12, ""), (0, 1, "bogen", 1, -1, "")]).encode())
write("track_graph", "routes", (page(line(0, [1]) + [(3, 0, "fahrstrasse", 0, 1, "")]) +
                                "[fahrstrassen]\nfahrstrasse\n .id=1\n .name=R\n .item\n ..magnetartikel=5\n"
                                " ..stellung=2\n").encode())


# z21_datagram: the first byte chooses requests (0) or replies (1); the rest is one UDP datagram. The
# examples of Roco's Z21 LAN protocol specification (tests/core/z21/DocumentExamplesTest.cpp).
def xbus(*body):
    data = bytes(body)
    checksum = 0
    for byte in data:
        checksum ^= byte
    return struct.pack("<HH", len(data) + 5, 0x40) + data + bytes([checksum])


def lan(header, data=b""):
    return struct.pack("<HH", len(data) + 4, header) + data


Z21_REQUESTS = {
    "serial-code-hwinfo": lan(0x10) + lan(0x18) + lan(0x1A),
    "broadcast-flags": lan(0x50, struct.pack("<I", 0x00010101)) + lan(0x51) + lan(0x85),
    "modes": lan(0x60, b"\x00\x03") + lan(0x61, b"\x00\x03\x01") + lan(0x70, b"\x00\x02") + lan(0x71, b"\x00\x02\x00"),
    "x-version-status-power": xbus(0x21, 0x21) + xbus(0x21, 0x24) + xbus(0x21, 0x80) + xbus(0x21, 0x81) + xbus(0x80),
    "firmware-logoff": xbus(0xF1, 0x0A) + lan(0x30),
    "loco-info-and-drive": xbus(0xE3, 0xF0, 0xC4, 0xD2) + xbus(0xE4, 0x13, 0x00, 0x03, 0x82) + xbus(0xE4, 0x12, 0x00, 0x05, 0x12)
    + xbus(0xE4, 0x10, 0x00, 0x05, 0x8F),
    "loco-function-estop": xbus(0xE4, 0xF8, 0x00, 0x03, 0x40) + xbus(0xE4, 0xF8, 0x00, 0x03, 0x9F) + xbus(0x92, 0x00, 0x03),
    "turnout-figure": xbus(0x43, 0x00, 0x04) + xbus(0x53, 0x00, 0x04, 0x89) + xbus(0x53, 0x00, 0x04, 0x81) + xbus(0x53, 0x01, 0x00, 0xA8),
    "combined-1-3": xbus(0x43, 0x00, 0x04) + xbus(0x43, 0x00, 0x05) + lan(0x81, b"\x00"),
    "wrong-xor": bytes([0x07, 0x00, 0x40, 0x00, 0x21, 0x81, 0x00]),
    "wrong-length-then-logoff": lan(0x10, b"\x00") + bytes([0x09, 0x00, 0x40, 0x00, 0xE4, 0x13, 0x00, 0x03, 0x76]) + lan(0x30),
    "truncated": bytes([0x0A, 0x00, 0x40, 0x00, 0xE4, 0x13, 0x00]),
    "length-below-four": lan(0x10) + bytes([0x02, 0x00, 0x10, 0x00]),
    "unknown-x": xbus(0xE4, 0x20, 0x00, 0x03, 0x10) + xbus(0x23, 0x11, 0x00, 0x1C),
}
for name, data in Z21_REQUESTS.items():
    write("z21_datagram", "request-" + name, b"\x00" + data)

Z21_REPLIES = {
    "serial-code-hwinfo": lan(0x10, struct.pack("<I", 0x12345678)) + lan(0x18, b"\x00")
    + bytes([0x0C, 0x00, 0x1A, 0x00, 0x00, 0x02, 0x00, 0x00, 0x20, 0x01, 0x00, 0x00]),
    "x-version-firmware": xbus(0x63, 0x21, 0x30, 0x12) + bytes([0x09, 0x00, 0x40, 0x00, 0xF3, 0x0A, 0x01, 0x23, 0xDB]),
    "broadcasts": xbus(0x61, 0x00) + xbus(0x61, 0x01) + xbus(0x61, 0x02) + xbus(0x61, 0x08) + xbus(0x61, 0x82)
    + xbus(0x81, 0x00) + xbus(0x62, 0x22, 0x03),
    "system-state": lan(0x84, struct.pack("<hhhhHHBBBB", -5, 20, 300, 35, 18000, 16000, 2, 2, 0, 0x13)),
    "loco-info": xbus(0xEF, 0x00, 0x03, 0x0C, 0x82, 0x11, 0x80, 0x00, 0x00, 0x01) + xbus(0xEF, 0xC4, 0xD2, 0x02, 0x0F, 0x10, 0, 0, 0),
    "turnout-info-modes": xbus(0x43, 0x00, 0x04, 0x02) + lan(0x60, b"\x01\x02\x01") + lan(0x70, b"\x00\x02\x00") + lan(0x51, b"\x01\x01\x00\x00"),
}
for name, data in Z21_REPLIES.items():
    write("z21_datagram", "reply-" + name, b"\x01" + data)

# withrottle_lines: the line cap byte, the cut byte, then the stream. The lines of JMRI's WiThrottle protocol
# page (tests/core/withrottle), both directions, with every line end.
WITHROTTLE_CLIENT = "\n".join([
    "NJohn's Throttle", "HU3f2a9b", "VN2.0", "*+", "*", "MT+L341<;>ED&RGW 341", "MT+S3<;>ED&RGW 341",
    "MTSL341<;>L341", "MTA*<;>qR", "MTAL341<;>qV", "MTA*<;>F112", "MTA*<;>F012", "MTAL341<;>f10", "MTA*<;>R0",
    "MTA*<;>V30", "MTA*<;>X", "MTA*<;>I", "MTAL41<;>s8", "MT-L341<;>d", "MT-*<;>r", "PPA1", "PTA2LT12",
    "PTATLT324", "PRA2IR:AUTO:0001", "RC+<;>S74<;>My consist<:>L341<;>true", "*-", "Q"]) + "\n"
WITHROTTLE_SERVER = "\r\n".join([
    "VN2.0", "RL2]\\[RGS 41}|{41}|{L]\\[Test Loco}|{1234}|{L", "PPA2", "PTT]\\[Turnouts}|{Turnout]\\[Closed}|{2]\\[Thrown}|{4",
    "PTL]\\[LT12}|{Rico Station N}|{1]\\[LT324}|{Rico Station S}|{2", "PRT]\\[Routes}|{Route]\\[Active}|{2]\\[Inactive}|{4",
    "PRL]\\[IR:AUTO:0001}|{Rico Main}|{", "RCC0", "PW12080", "*10", "MT+L41<;>",
    "MTLL41<;>]\\[Headlight]\\[Bell]\\[Whistle]\\[]\\[", "MTAL41<;>F00", "MTAL41<;>V0", "MTAL41<;>R1", "MTAL41<;>s1",
    "MTAL341<;>F10", "MT-L341<;>", "HTDigitrax", "HtDigitrax LnWi 1.0 Unit=7,Wifi Chnl= 1,Command Station= DCS100",
    "HM error - long address < 127 S23", "PTA4LT12"]) + "\r\n"
write("withrottle_lines", "client-lines", bytes([248, 17]) + WITHROTTLE_CLIENT.encode())
write("withrottle_lines", "server-lines", bytes([248, 200]) + WITHROTTLE_SERVER.encode())
write("withrottle_lines", "cr-only-and-overlong", bytes([2, 5]) + b"NPhone\r*+\rMTA*<;>V30\r" + b"x" * 40 + b"\r*\r")
