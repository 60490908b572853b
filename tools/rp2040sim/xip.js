// SPDX-License-Identifier: MIT
'use strict';
/* xip.js — the RP2040's boot path and XIP cache for the rp2040js emulator,
 * which by itself loads the image without its boot2 and charges a flash load
 * like an SRAM one.
 *
 * Boot: as the boot ROM does, the first 256 bytes of flash (boot2) are
 * checked against the CRC32 in their last 4 bytes (polynomial 0x04C11DB7,
 * initial value 0xFFFFFFFF, not reflected, no final XOR) — an image that
 * fails is one the boot ROM would not start — then copied to SRAM at
 * 0x20041f00 and run there (SP 0x20042000, LR 0). boot2 programs the XIP SSI
 * and enters the application; the SSI registers it leaves decide the cost of
 * a cache miss (below).
 *
 * Cache: 16 KB, two-way set associative, 8-byte lines (1024 sets; address
 * bits 12:3 select the set), least recently used way replaced. Aliases:
 * 0x10xxxxxx cached, 0x11 cached without allocating on a miss, 0x12 and 0x13
 * not cached (every access is a flash read). A hit costs nothing beyond the
 * emulator's own cycle count; a miss stalls the core that made the access
 * by one line fill over the SSI in the mode boot2 left:
 *   SCK cycles = instruction bits / lanes(instruction) + (address + mode)
 *                bits / lanes(address) + wait cycles + 64 data bits / lanes
 *   stall (clk_sys) = SCK cycles * BAUDR + XIP_OVERHEAD
 * lanes from CTRLR0.SPI_FRF (1, 2, 4) and SPI_CTRLR0.TRANS_TYPE (whether
 * instruction and address use them). 03h serial at clk_sys/4: (8 + 24 + 64)
 * * 4 + 4 = 388 cycles; EBh quad continuous read (no instruction, 24-bit
 * address + 8 mode bits, 4 wait cycles) at clk_sys/2: (8 + 4 + 16) * 2 + 4
 * = 60 cycles. Accesses outside a core's instruction (DMA) update the cache
 * and are not charged. Once configured, a write to the SSI (the firmware
 * changing the flash's divider for a faster clk_sys) configures it again:
 * a miss costs what the registers say from then on.
 */

const FLASH_BASE = 0x10000000, FLASH_END = 0x14000000;
const BOOT2_SRAM = 0x20041f00;
const LINE_SHIFT = 3, SETS = 1024;
const XIP_OVERHEAD = 4;   /* clk_sys cycles of SSI start-up and bus handover per line fill */

function crc32BootRom(bytes) {
  let crc = 0xffffffff;
  for (const b of bytes) {
    crc ^= b << 24;
    for (let i = 0; i < 8; i++) crc = (crc & 0x80000000) ? ((crc << 1) ^ 0x04c11db7) : (crc << 1);
    crc >>>= 0;
  }
  return crc >>> 0;
}

/* the boot2 of the image in flash: null when the boot ROM would accept it,
 * else why not */
function boot2Problem(flash) {
  const stored = (flash[252] | flash[253] << 8 | flash[254] << 16 | flash[255] << 24) >>> 0;
  const crc = crc32BootRom(flash.subarray(0, 252));
  return crc === stored ? null : `boot2 CRC32 ${crc.toString(16)} does not match the stored ${stored.toString(16)}: the boot ROM would not start this image`;
}

/* clk_sys cycles of one 8-byte line fill with the SSI as configured */
function lineFillCycles(ssi) {
  const frf = (ssi.crtlr0 >>> 21) & 3;
  const lanes = frf === 2 ? 4 : frf === 1 ? 2 : 1;
  const tt = ssi.spictlr0 & 3;
  const instBits = [0, 4, 8, 16][(ssi.spictlr0 >>> 8) & 3];
  const addrBits = ((ssi.spictlr0 >>> 2) & 15) * 4;
  const wait = (ssi.spictlr0 >>> 11) & 31;
  const div = ssi.baudr & 0xfffe || 2;
  const sck = instBits / (tt === 2 ? lanes : 1) + addrBits / (tt >= 1 ? lanes : 1) + wait + 64 / lanes;
  return { cycles: Math.ceil(sck * div) + XIP_OVERHEAD, lanes, div, instBits, addrBits, wait,
           cmd: (ssi.spictlr0 >>> 24) & 0xff };
}

class XipCache {
  constructor(mcu) {
    this.mcu = mcu;
    this.tags = new Int32Array(SETS * 2).fill(-1);
    this.lru = new Uint8Array(SETS);      /* the way to replace next */
    this.misses = 0;
    this.stall = 0;                       /* cycles owed by the executing core */
    this.stallTotal = 0;
    this.charging = false;                /* true while a core executes */
    this.fill = null;                     /* set by configure() */
    const rd32 = mcu.readUint32.bind(mcu), rd16 = mcu.readUint16.bind(mcu), rd8 = mcu.readUint8.bind(mcu);
    const x = this;
    mcu.readUint32 = (a) => { a >>>= 0; if (a >= FLASH_BASE && a < FLASH_END) x.access(a); return rd32(a); };
    mcu.readUint16 = (a) => { a >>>= 0; if (a >= FLASH_BASE && a < FLASH_END) x.access(a); return rd16(a); };
    mcu.readUint8 = (a) => { a >>>= 0; if (a >= FLASH_BASE && a < FLASH_END) x.access(a); return rd8(a); };
    const ssi = mcu.peripherals[0x18000], ssiWrite = ssi.writeUint32.bind(ssi);
    ssi.writeUint32 = (off, v) => { ssiWrite(off, v); if (x.fill) x.configure(); };
  }

  configure() { this.fill = lineFillCycles(this.mcu.peripherals[0x18000]); }

  access(a) {
    if (!this.fill) return;               /* boot2 still running from SRAM */
    const alias = (a >>> 24) & 3, off = a & 0xffffff;
    const line = off >>> LINE_SHIFT, set = line & (SETS - 1), tag = line >>> 10;
    if (alias < 2) {
      const i = set * 2;
      if (this.tags[i] === tag) { this.lru[set] = 1; return; }
      if (this.tags[i + 1] === tag) { this.lru[set] = 0; return; }
      if (alias === 0) {
        const w = this.lru[set];
        this.tags[i + w] = tag;
        this.lru[set] = w ^ 1;
      }
    }
    this.misses++;
    if (this.charging) { this.stall += this.fill.cycles; this.stallTotal += this.fill.cycles; }
  }

  take() { const s = this.stall; this.stall = 0; return s; }
}

/* Prepares core 0 to run boot2 from SRAM as the boot ROM would; the caller
 * runs it and calls xip.configure() when the core reaches flash. */
function bootThroughBoot2(mcu) {
  const problem = boot2Problem(mcu.flash);
  if (problem) return problem;
  mcu.sram.set(mcu.flash.subarray(0, 256), BOOT2_SRAM - 0x20000000);
  const c = mcu.core;
  c.SP = 0x20042000;
  c.LR = 0;
  c.PC = BOOT2_SRAM;
  return null;
}

module.exports = { XipCache, bootThroughBoot2, boot2Problem, lineFillCycles, crc32BootRom };
