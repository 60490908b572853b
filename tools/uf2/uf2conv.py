#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""uf2conv.py — wraps a flat binary image into UF2 blocks for a USB
mass-storage boot loader (the RP2040 boot ROM's drive).

Each 512-byte block carries 256 bytes of payload at a target address, the
block number and count, and the family ID (flag 0x2000).

usage: uf2conv.py IN.bin OUT.uf2 [--base 0x10000000] [--family 0xE48BFF56]
"""
import struct
import sys

MAGIC_START0 = 0x0A324655
MAGIC_START1 = 0x9E5D5157
MAGIC_END = 0x0AB16F30
FLAG_FAMILY_ID = 0x00002000
PAYLOAD = 256
RP2040_FAMILY = 0xE48BFF56


def to_uf2(data, base, family):
    if len(data) % PAYLOAD:
        data += bytes(PAYLOAD - len(data) % PAYLOAD)
    count = len(data) // PAYLOAD
    out = bytearray()
    for i in range(count):
        chunk = data[i * PAYLOAD:(i + 1) * PAYLOAD]
        head = struct.pack("<8I", MAGIC_START0, MAGIC_START1, FLAG_FAMILY_ID,
                           base + i * PAYLOAD, PAYLOAD, i, count, family)
        out += head + chunk + bytes(476 - PAYLOAD) + struct.pack("<I", MAGIC_END)
    return bytes(out)


def main(argv):
    args = argv[1:]
    base, family = 0x10000000, RP2040_FAMILY
    pos = []
    i = 0
    while i < len(args):
        if args[i] in ("--base", "--family") and i + 1 < len(args):
            try:
                v = int(args[i + 1], 0)
            except ValueError:
                sys.stderr.write("uf2conv.py: bad number '%s'\n" % args[i + 1])
                return 2
            if args[i] == "--base":
                base = v
            else:
                family = v
            i += 2
        else:
            pos.append(args[i])
            i += 1
    if len(pos) != 2:
        sys.stderr.write("usage: uf2conv.py IN.bin OUT.uf2 [--base ADDR] [--family ID]\n")
        return 2
    try:
        with open(pos[0], "rb") as f:
            data = f.read()
    except OSError as e:
        sys.stderr.write("uf2conv.py: %s: %s\n" % (pos[0], e.strerror))
        return 2
    if not data:
        sys.stderr.write("uf2conv.py: %s: empty image\n" % pos[0])
        return 2
    with open(pos[1], "wb") as f:
        f.write(to_uf2(data, base, family))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
