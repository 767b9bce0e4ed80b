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
