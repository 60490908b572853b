// SPDX-License-Identifier: MIT
'use strict';
/* profile.js — rp2040sim --profile FILE: where an image's time and memory
 * reads go, per symbol of its ELF (functions and data objects).
 *
 * Counted from the application's start (after boot2) to the end of the run,
 * for both cores, only while a core executes an instruction (a DMA transfer's
 * reads are not counted):
 *   reads   the core's reads of the symbol's bytes: instruction fetches (one
 *           per 16-bit halfword, two for a 32-bit instruction), literal pool
 *           loads and data loads; in SRAM and in flash alike (the 0x10
 *           alias; the others are the same bytes, folded onto it)
 *   cycles  the cycles of the instructions whose address lies in a function,
 *           XIP cache stalls included (self cost: not its callees')
 * The file is JSON: {image, frames, frame_cycles, cycles, symbols: [{name,
 * type (func or object), addr, size, reads, cycles}]} with every symbol of
 * non-zero size that was read or executed; frames is the run's frame count,
 * frame_cycles the sum of their cycles (--json's "cycles": from a frame's
 * begin line to its last pixel), cycles both cores' over the run. tools/rp2040_ram_text.py
 * turns such profiles into the images' SRAM placement.
 */
const fs = require('fs');

const FLASH_BASE = 0x10000000, SRAM_BASE = 0x20000000;

/* the function and object symbols (non-zero size) of an ELF32 LE file */
function elfSymbols(buf) {
  if (buf.length < 52 || buf.readUInt32BE(0) !== 0x7f454c46 || buf[4] !== 1 || buf[5] !== 1) return null;
  const shoff = buf.readUInt32LE(32), shentsize = buf.readUInt16LE(46), shnum = buf.readUInt16LE(48);
  const sh = (i) => {
    const o = shoff + i * shentsize;
    return { type: buf.readUInt32LE(o + 4), offset: buf.readUInt32LE(o + 16), size: buf.readUInt32LE(o + 20),
             link: buf.readUInt32LE(o + 24), entsize: buf.readUInt32LE(o + 36) };
  };
  const out = [];
  for (let i = 0; i < shnum; i++) {
    const s = sh(i);
    if (s.type !== 2) continue;                     /* SHT_SYMTAB */
    const str = sh(s.link);
    for (let o = s.offset; o + 16 <= s.offset + s.size; o += s.entsize || 16) {
      const nameOff = buf.readUInt32LE(o), value = buf.readUInt32LE(o + 4), size = buf.readUInt32LE(o + 8);
      const type = buf[o + 12] & 0xf, shndx = buf.readUInt16LE(o + 14);
      if ((type !== 1 && type !== 2) || !size || !shndx) continue;
      let e = str.offset + nameOff;
      while (buf[e]) e++;
      out.push({ name: buf.toString('latin1', str.offset + nameOff, e), type: type === 2 ? 'func' : 'object',
                 addr: type === 2 ? (value & ~1) >>> 0 : value >>> 0, size });
    }
  }
  return out;
}

class Profile {
  constructor(mcu, flashSize, sramSize) {
    this.flashReads = new Float64Array(flashSize >>> 1);
    this.sramReads = new Float64Array(sramSize >>> 1);
    this.flashCycles = new Float64Array(flashSize >>> 1);
    this.sramCycles = new Float64Array(sramSize >>> 1);
    this.on = false;            /* counting (the application runs) */
    this.executing = false;     /* a core executes an instruction */
    this.cycles = 0;
    const p = this;
    for (const [fn, bytes] of [['readUint32', 4], ['readUint16', 2], ['readUint8', 1]]) {
      const rd = mcu[fn].bind(mcu);
      mcu[fn] = (a) => {
        if (p.executing) p.read(a >>> 0, bytes);
        return rd(a);
      };
    }
  }

  read(a, bytes) {
    const n = bytes === 4 ? 2 : 1;
    if (a >= FLASH_BASE && a < FLASH_BASE + 0x4000000) {
      const i = (a & 0xffffff) >>> 1;
      if (i + n <= this.flashReads.length) for (let k = 0; k < n; k++) this.flashReads[i + k] += 1 / n;
    } else if (a >= SRAM_BASE && a < SRAM_BASE + 2 * this.sramReads.length) {
      const i = (a - SRAM_BASE) >>> 1;
      for (let k = 0; k < n && i + k < this.sramReads.length; k++) this.sramReads[i + k] += 1 / n;
    }
  }

  /* an instruction at pc took cycles (stalls included) */
  exec(pc, cycles) {
    if (!this.on) return;
    this.cycles += cycles;
    pc >>>= 0;
    if (pc >= FLASH_BASE && pc < FLASH_BASE + 0x4000000) {
      const i = (pc & 0xffffff) >>> 1;
      if (i < this.flashCycles.length) this.flashCycles[i] += cycles;
    } else if (pc >= SRAM_BASE) {
      const i = (pc - SRAM_BASE) >>> 1;
      if (i < this.sramCycles.length) this.sramCycles[i] += cycles;
    }
  }

  /* per symbol of the ELF in buf */
  write(file, image, buf, frames, frameCycles) {
    const syms = elfSymbols(buf) || [];
    const sum = (arr, base, s) => {
      let t = 0;
      const lo = (s.addr - base) >>> 1, hi = Math.min(arr.length, lo + ((s.size + 1) >>> 1));
      for (let i = lo; i < hi; i++) t += arr[i];
      return t;
    };
    const out = [];
    for (const s of syms) {
      let reads = 0, cycles = 0;
      if (s.addr >= FLASH_BASE && s.addr < FLASH_BASE + 0x1000000) {
        reads = sum(this.flashReads, FLASH_BASE, s); cycles = sum(this.flashCycles, FLASH_BASE, s);
      } else if (s.addr >= SRAM_BASE && s.addr < SRAM_BASE + 2 * this.sramReads.length) {
        reads = sum(this.sramReads, SRAM_BASE, s); cycles = sum(this.sramCycles, SRAM_BASE, s);
      } else continue;
      if (reads || cycles) out.push(Object.assign(s, { reads: Math.round(reads), cycles: Math.round(cycles) }));
    }
    out.sort((a, b) => b.cycles - a.cycles || b.reads - a.reads || (a.name < b.name ? -1 : 1));
    fs.writeFileSync(file, JSON.stringify({ image, frames, frame_cycles: Math.round(frameCycles), cycles: Math.round(this.cycles),
      symbols: out }, null, 0)
      .replace(/\},\{/g, '},\n{') + '\n');
  }
}

module.exports = { Profile, elfSymbols };
