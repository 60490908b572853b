// SPDX-License-Identifier: MIT
'use strict';
/* emu_panel.js — the emulated ST7789 / ILI9341 / ST7735S / SSD1351 / GC9A01 / ILI9488 controller of hal/sim/emu_panel.c,
 * ported line for line so the emulated Pico and host_sim decode the same bus
 * the same way (same rules, same violation lines; tools/rp2040sim/replay_vectors.js
 * and tests/unit/test_panel_vectors.c replay the same vectors through both). Keep the two in step. */

const fs = require('fs');
const path = require('path');

const MS = 1000000;
const MEM_W = 320;
const MEM_H = 480;
const ST = 0;
const IL = 1;
const S7 = 2;
const SD = 3;
const GC = 4;
const I8 = 5;
const M_ST = 1 << ST;
const M_IL = 1 << IL;
const M_S7 = 1 << S7;
const M_SD = 1 << SD;
const M_GC = 1 << GC;
const M_I8 = 1 << I8;
const M_SIL = M_ST | M_IL | M_I8;
const M_SI = M_ST | M_IL | M_GC | M_I8;
const M_GAM = M_ST | M_IL | M_S7 | M_I8;
const M_ALL = M_ST | M_IL | M_S7 | M_GC | M_I8;
const F_PIXELS = 1;
const F_NOTEMU = 2;
const F_READ = 4;   /* a read command: the bytes after it are its read phase (dummy clocks) */
const F_LOCKB = 8;  /* SSD1351: refused until the command lock is given B1h */
const F_INTER = 16; /* GC9A01: refused until the inter-register enable (FEh, EFh) */

/* The accepted commands: the CMD lines of hal/sim/emu_commands.def, the table
 * hal/sim/emu_panel.c compiles in. */
function readCommands(file) {
  const consts = { M_ALL, M_SI, M_SIL, M_GAM, M_ST, M_IL, M_S7, M_SD, M_GC, M_I8, F_PIXELS, F_NOTEMU, F_READ, F_LOCKB, F_INTER, 0: 0 };
  const cmds = [];
  const text = fs.readFileSync(file, 'utf8');
  for (const m of text.matchAll(/^CMD\((0x[0-9A-F]{2}), *(\w+), *(\d+), *(\d+), *(\w+), *"([^"]*)"\)/gm)) {
    if (!(m[2] in consts) || !(m[5] in consts)) throw new Error(`${file}: bad CMD line: ${m[0]}`);
    cmds.push({ code: Number(m[1]), models: consts[m[2]], min: Number(m[3]), max: Number(m[4]),
      flags: consts[m[5]], name: m[6] });
  }
  if (!cmds.length) throw new Error(`${file}: no CMD lines`);
  return cmds;
}
const CMDS = readCommands(path.join(__dirname, '..', '..', 'hal', 'sim', 'emu_commands.def'));

/* Facts of each controller model the rules depend on (struct model in
 * hal/sim/emu_panel.c): memory size, COLMOD after a hardware reset, whether
 * SWRESET resets COLMOD, the 16-bit value, the wait after SLPOUT (ms),
 * DCS rules or the SSD1351's, the shortest reset pulse (ns), a round glass
 * (the circle inscribed in the memory; black outside it), 18-bit pixels only
 * on the serial interface (three bytes). */
const MODELS = [
  { name: 'ST7789', memW: 240, memH: 320, colmodReset: 0x66, colmodSwreset: 1, colmod16: 0x55, slpoutBusyMs: 5, dcs: 1, resetPulseNs: 10000, round: 0, rgb666: 0 },
  { name: 'ILI9341', memW: 240, memH: 320, colmodReset: 0x66, colmodSwreset: 1, colmod16: 0x55, slpoutBusyMs: 5, dcs: 1, resetPulseNs: 10000, round: 0, rgb666: 0 },
  { name: 'ST7735S', memW: 132, memH: 162, colmodReset: 0x06, colmodSwreset: 0, colmod16: 0x05, slpoutBusyMs: 120, dcs: 1, resetPulseNs: 10000, round: 0, rgb666: 0 },
  { name: 'SSD1351', memW: 128, memH: 128, colmodReset: 0, colmodSwreset: 0, colmod16: 0, slpoutBusyMs: 0, dcs: 0, resetPulseNs: 2000, round: 0, rgb666: 0 },
  { name: 'GC9A01', memW: 240, memH: 240, colmodReset: 0x66, colmodSwreset: 1, colmod16: 0x55, slpoutBusyMs: 5, dcs: 1, resetPulseNs: 10000, round: 1, rgb666: 0 },
  { name: 'ILI9488', memW: 320, memH: 480, colmodReset: 0x66, colmodSwreset: 1, colmod16: 0x66, slpoutBusyMs: 5, dcs: 1, resetPulseNs: 10000, round: 0, rgb666: 1 },
];

/* The modules and the panels they show: the GLASS and PANEL lines of
 * hal/panels.def, the table hal/sim/emu_panel.c compiles in. */
function readPanels(file) {
  const modules = {}, find = {}, controllers = {};
  const text = fs.readFileSync(file, 'utf8');
  for (const m of text.matchAll(/^(GLASS|PANEL)\(([^)]*)\)\s*$/gm)) {
    const a = m[2].split(',').map((x) => x.trim());
    if (m[1] === 'GLASS') {
      const n = a.slice(2).map(Number);
      if (a.length !== 10 || n.some((x) => !Number.isInteger(x)) || !(a[1] in MODEL)) {
        throw new Error(`${file}: bad GLASS line: ${m[0]}`);
      }
      modules[a[0]] = { name: a[0], model: MODEL[a[1]], gw: n[0], gh: n[1], memX: n[2], memY: n[3],
        mirrorX: n[4], bgr: n[5], inverted: n[6], normallyBlack: n[7] };
    } else {
      if (a.length !== 4 || !/^[0-3]$/.test(a[3])) throw new Error(`${file}: bad PANEL line: ${m[0]}`);
      find[a[0]] = [a[2], Number(a[3])];
      if (!(a[1] in controllers)) controllers[a[1]] = find[a[0]];
    }
  }
  for (const [name, [glass]] of Object.entries(find)) {
    if (!modules[glass]) throw new Error(`${file}: panel ${name} shows an unknown glass ${glass}`);
  }
  /* a panel by name, then a module by name (view 0), then a controller's first panel */
  for (const name of Object.keys(modules)) if (!(name in find)) find[name] = [name, 0];
  for (const [c, f] of Object.entries(controllers)) if (!(c in find)) find[c] = f;
  return { MODULES: modules, FIND: find };
}
const MODEL = { ST7789: ST, ILI9341: IL, ST7735S: S7, SSD1351: SD, GC9A01: GC, ILI9488: I8 };
const { MODULES, FIND } = readPanels(path.join(__dirname, '..', '..', 'hal', 'panels.def'));

function hex2(v) { return v.toString(16).toUpperCase().padStart(2, '0'); }

/* The rate the glass is scanned at, per controller: the ST7789's FRCTRL2
 * after reset (0x0F, 60 Hz) and the ILI9341's FRMCTR1 (70 Hz); the others
 * are modelled at 60 Hz. The gate lines of the module's glass are scanned
 * top to bottom over SCAN_ACTIVE of the period, then the vertical blank. */
const SCAN_HZ = { ST7789: 60, ILI9341: 70 };
const SCAN_ACTIVE = 0.95;

class EmuPanel {
  /* name as emu_module_find accepts; throws for an unknown name. */
  constructor(name, view) {
    const f = FIND[name];
    if (!f) throw new Error(`unknown panel '${name}'`);
    this.mod = MODULES[f[0]];
    this.model = MODELS[this.mod.model];
    this.view = view === undefined ? f[1] : view;
    if (!Number.isInteger(this.view) || this.view < 0 || this.view > 3) throw new Error(`bad view ${view}`);
    this.cs = 1; this.dc = 1; this.reset = 1; this.bl = 1;
    this.csTiedLow = 0;
    this.offset = 0;
    this.resetLowNs = 0;
    this.param = new Uint8Array(16);
    this.violation = '';
    this.pixelsWritten = 0;
    this.now = 0;
    this.scanNs = 1e9 / (SCAN_HZ[this.model.name] || 60);
    this.tearLo = Infinity; this.tearHi = -Infinity;
    this.mem = new Uint16Array(MEM_W * MEM_H);
    /* (the first 240x320 cells in the order they had before the memory
     * grew for the ILI9488, so that the other models' noise is unchanged) */
    let s = 0x2545F491;
    for (let pass = 0; pass < 2; pass++) {
      for (let i = 0; i < MEM_W * MEM_H; i++) {
        if ((Math.floor(i / MEM_W) < 320 && i % MEM_W < 240) !== (pass === 0)) continue;
        s = (s ^ (s << 13)) >>> 0;
        s = (s ^ (s >>> 17)) >>> 0;
        s = (s ^ (s << 5)) >>> 0;
        this.mem[i] = s & 0xffff;
      }
    }
    this.slpinOk = 0; this.slpinSince = 0; this.slpinWhy = '';
    this.hwResetDone(0);
  }

  lookup(code) {
    const bit = 1 << this.mod.model;
    for (const c of CMDS) if (c.code === code && (c.models & bit)) return c;
    return null;
  }

  cmdName(code) {
    const c = code < 0 ? null : this.lookup(code);
    return c ? c.name : 'UNKNOWN';
  }

  violate(name, code, at, what) {
    if (this.violation) return;
    this.violation = code >= 0 ? `${name} (0x${hex2(code)}) at byte ${at}: ${what}` : `${name} at byte ${at}: ${what}`;
  }

  vcmd(code, what) { this.violate(this.cmdName(code), code, this.offset, what); }

  /* hw: a hardware reset (else SWRESET) */
  resetRegs(hw) {
    this.teOn = 0;
    this.cur = -1; this.nparam = 0; this.half = 0; this.hi = 0; this.mid = 0;
    this.asleep = 1; this.displayOn = 0; this.inverted = 0; this.idle = 0;
    if (hw || this.model.colmodSwreset) this.colmod = this.model.colmodReset;
    this.madctl = 0; this.windowSet = 0; this.contValid = 0;
    this.remap = 0x40; this.locked = 0; this.protect = 1; this.mode = 0xA6; this.inter = 0;
    this.xs = 0; this.xe = this.model.memW - 1; this.ys = 0; this.ye = this.model.memH - 1; this.cx = 0; this.cy = 0;
  }

  hwResetDone(t) {
    this.resetRegs(true);
    this.busyUntil = t + (this.model.dcs ? 5 * MS : 0); this.busyWhy = 'hardware reset'; this.busySince = t;
    this.slpoutOk = t + 120 * MS; this.slpoutWhy = 'hardware reset'; this.slpoutSince = t;
    this.slpinOk = 0;
  }

  limX() { return (this.madctl & 0x20) ? this.model.memH : this.model.memW; }
  limY() { return (this.madctl & 0x20) ? this.model.memW : this.model.memH; }

  /* a memory write stopped inside a pixel (partial_pixel in emu_panel.c) */
  partialPixel(how) {
    if (this.model.rgb666) this.vcmd(this.cur, `${how} ${this.half} of a pixel's 3 bytes`);
    else if (how[0] === 'e') this.vcmd(this.cur, `${how} half a pixel (odd number of data bytes)`);
    else this.vcmd(this.cur, `${how} half a pixel`);
  }

  endCommand() {
    if (this.cur < 0) return;
    const c = this.lookup(this.cur);
    if (c.flags & F_PIXELS) {
      if (this.half) this.partialPixel('ended with');
    } else if (this.nparam < c.min) {
      this.vcmd(this.cur, `${this.nparam} parameter bytes, needs ${c.min}`);
    }
    this.cur = -1; this.nparam = 0; this.half = 0;
  }

  tooSoon(code, t, until, since, why) {
    if (t >= until) return false;
    this.vcmd(code, `sent ${Math.floor((t - since) / 1000)} us after ${why}, needs ${Math.floor((until - since) / 1000)} us`);
    return true;
  }

  startWrite(code) {
    if (this.asleep) {
      this.vcmd(code, 'memory write while asleep (no SLPOUT since reset or SLPIN)');
    } else if (this.windowSet !== 3) {
      this.vcmd(code, (this.windowSet & 1) ? 'memory write before RASET set the rows'
        : (this.windowSet & 2) ? 'memory write before CASET set the columns'
          : 'memory write before CASET/RASET set a window');
    } else if (this.model.rgb666 && (this.colmod & 7) !== 6) {
      this.vcmd(code, `memory write with COLMOD 0x${hex2(this.colmod)} (the serial interface takes 18-bit only, 0x66)`);
    } else if (!this.model.rgb666 && (this.colmod & 7) !== 5) {
      this.vcmd(code, `memory write with COLMOD 0x${hex2(this.colmod)} (only 16-bit, 0x${hex2(this.model.colmod16)}, emulated)`);
    } else if (this.xe >= this.limX() || this.ye >= this.limY()) {
      this.vcmd(code, `window ${this.xs}..${this.xe} x ${this.ys}..${this.ye} outside the memory (${this.limX()}x${this.limY()})`);
    } else if (code === 0x3C && !this.contValid) {
      this.vcmd(code, 'no RAMWR to continue since the window or MADCTL changed');
    } else if (code === 0x2C) {
      this.cx = this.xs; this.cy = this.ys; this.contValid = 1;
    }
  }

  command(code, t) {
    this.endCommand();
    if (this.violation) return;
    const c = this.lookup(code);
    if (!c) {
      /* "an" before a letter said with a vowel first: "an SSD1351", "a GC9A01" */
      this.vcmd(code, `not ${'AEFHILMNORSX'.includes(this.model.name[0]) ? 'an' : 'a'} ${this.model.name} command`);
      return;
    }
    if (c.flags & F_NOTEMU) { this.vcmd(code, 'not emulated'); return; }
    if (!this.model.dcs) { this.ssdCommand(code, c); return; }
    if (this.tooSoon(code, t, this.busyUntil, this.busySince, this.busyWhy)) return;
    if ((c.flags & F_INTER) && this.inter !== 2) {
      this.vcmd(code, 'refused: a vendor register, locked until the inter-register enable (FEh, then EFh)');
      return;
    }
    this.cur = code; this.nparam = 0;
    if (this.mod.model === GC && (code === 0xFE || code === 0xEF)) {
      this.inter = code === 0xFE ? 1 : this.inter ? 2 : 0;
      return;
    }
    switch (code) {
      case 0x01: {
        const awake = !this.asleep;
        this.resetRegs(false);
        this.busyUntil = t + 5 * MS; this.busyWhy = 'SWRESET'; this.busySince = t;
        if (awake) { this.slpoutOk = t + 120 * MS; this.slpoutWhy = 'SWRESET'; this.slpoutSince = t; }
        this.slpinOk = 0;
        this.cur = code;
        break;
      }
      case 0x10:
        if (this.tooSoon(code, t, this.slpinOk, this.slpinSince, this.slpinWhy)) return;
        if (!this.asleep) { this.asleep = 1; this.slpoutOk = t + 120 * MS; this.slpoutWhy = 'SLPIN'; this.slpoutSince = t; }
        this.busyUntil = t + 5 * MS; this.busyWhy = 'SLPIN'; this.busySince = t;
        break;
      case 0x11:
        if (this.tooSoon(code, t, this.slpoutOk, this.slpoutSince, this.slpoutWhy)) return;
        if (this.asleep) { this.asleep = 0; this.slpinOk = t + 120 * MS; this.slpinWhy = 'SLPOUT'; this.slpinSince = t; }
        this.busyUntil = t + this.model.slpoutBusyMs * MS; this.busyWhy = 'SLPOUT'; this.busySince = t;
        break;
      case 0x20: this.inverted = 0; break;
      case 0x21: this.inverted = 1; break;
      case 0x28: this.displayOn = 0; break;
      case 0x29: this.displayOn = 1; break;
      case 0x34: this.teOn = 0; break;
      case 0x38: this.idle = 0; break;
      case 0x39: this.idle = 1; break;
      case 0x2C: case 0x3C: this.startWrite(code); break;
      default: break;
    }
  }

  execute() {
    const a = this.param;
    if (!this.model.dcs) { this.ssdExecute(); return; }
    switch (this.cur) {
      case 0x2A: case 0x2B: {
        const s = (a[0] << 8) | a[1], e = (a[2] << 8) | a[3];
        const col = this.cur === 0x2A;
        const lim = col ? this.limX() : this.limY();
        if (s > e) this.vcmd(this.cur, `start ${s} after end ${e}`);
        else if (e >= lim) this.vcmd(this.cur, `${col ? 'columns' : 'rows'} ${s}..${e} outside the memory (0..${lim - 1})`);
        else if (col) { this.xs = s; this.xe = e; this.windowSet |= 1; }
        else { this.ys = s; this.ye = e; this.windowSet |= 2; }
        this.contValid = 0;
        break;
      }
      case 0x36: this.madctl = a[0]; this.contValid = 0; break;
      case 0x35: this.teOn = 1; break;   /* TE in the vertical blank (parameter 0) */
      case 0x37:   /* the scroll start line: 0 shows the memory unscrolled */
        if (a[0] || a[1]) this.vcmd(this.cur, 'not emulated (a scroll start other than 0)');
        break;
      case 0x3A: this.colmod = a[0]; break;
      default: break;
    }
  }

  /* A write into memory row r at this.now: the scan shows it from the
   * first pass that reads row r after now (pass n reads glass row g at
   * n T + g SCAN_ACTIVE T / rows). A frame whose writes show from more
   * than one pass was torn: some pass showed part of it over part of the
   * frame before (takeTear). */
  scanWrite(r) {
    const g = r - this.mod.memY, rows = this.mod.gh;
    if (g < 0 || g >= rows) return;
    const T = this.scanNs, n = Math.ceil((this.now - g * SCAN_ACTIVE * T / rows) / T);
    if (n < this.tearLo) this.tearLo = n;
    if (n > this.tearHi) this.tearHi = n;
  }

  /* The scan passes the writes since the last call show from: { lo, hi }
   * (hi > lo: the frame they made was torn; none written: lo > hi); starts
   * over. */
  takeTear() {
    const r = { lo: this.tearLo, hi: this.tearHi };
    this.tearLo = Infinity; this.tearHi = -Infinity;
    return r;
  }

  /* The TE output at time t (ns): high in the scan's vertical blank once
   * TEON turned it on (TEOFF, a reset: low). */
  te(t) {
    if (!this.teOn || !this.reset) return false;
    const T = this.scanNs;
    return t - Math.floor(t / T) * T >= SCAN_ACTIVE * T;
  }

  pixel(v) {
    if (!this.model.dcs) { this.ssdPixel(v); return; }
    let c = this.cx, r = this.cy;
    if (this.madctl & 0x20) { c = this.cy; r = this.cx; }
    if (this.madctl & 0x40) c = this.model.memW - 1 - c;
    if (this.madctl & 0x80) r = this.model.memH - 1 - r;
    this.mem[r * MEM_W + c] = v;
    this.scanWrite(r);
    this.pixelsWritten++;
    if (this.cx < this.xe) {
      this.cx++;
    } else {
      this.cx = this.xs;
      this.cy = this.cy < this.ye ? this.cy + 1 : this.ys;
      /* the window's last pixel: its end and its size in pixels */
      if (this.cy === this.ys && this.onWrap)
        this.onWrap(this.xe, this.ye, (this.xe - this.xs + 1) * (this.ye - this.ys + 1));
    }
  }

  data(b) {
    if (this.cur < 0) { this.violate('DATA', -1, this.offset, `data byte 0x${hex2(b)} without a command`); return; }
    const c = this.lookup(this.cur);
    if (c.flags & F_PIXELS) {
      if (this.model.rgb666) {   /* R, G, B in bits 7..2; kept as RGB565 */
        if (this.half === 2) { this.half = 0; this.pixel(((this.hi >> 3) << 11) | ((this.mid >> 2) << 5) | (b >> 3)); }
        else { if (this.half) this.mid = b; else this.hi = b; this.half++; }
      } else if (this.half) { this.half = 0; this.pixel((this.hi << 8) | b); } else { this.half = 1; this.hi = b; }
      return;
    }
    if (this.nparam >= c.max) { this.vcmd(this.cur, `too many parameter bytes (takes ${c.max})`); return; }
    if (this.nparam < 16) this.param[this.nparam] = b;
    this.nparam++;
    if (this.nparam === c.max) this.execute();
  }

  /* One SPI byte at time t (ns). */
  spiByte(b, t) {
    this.now = t;
    if (!this.violation) {
      if (!this.reset) this.violate('RESET', -1, this.offset, 'byte sent while RESET is low');
      else if (this.cs && !this.csTiedLow) this.violate('CS', -1, this.offset, 'byte sent while CS is high (controller deselected)');
      else if (this.dc === 0) this.command(b, t);
      else this.data(b);
    }
    this.offset++;
  }

  spi(bytes, t, nsPerByte) {
    for (let i = 0; i < bytes.length; i++) this.spiByte(bytes[i], t + i * nsPerByte);
  }

  /* line: 0 DC, 1 RESET, 2 CS, 3 BL */
  line(line, level, t) {
    if (this.violation) return;
    level = level ? 1 : 0;
    switch (line) {
      case 0: this.dc = level; break;
      case 1:
        if (this.reset && !level) {
          this.resetLowNs = t;
          /* a reset aborts the command in progress: one that had not got
           * all its bytes was cut short */
          if (this.cur >= 0) {
            const c = this.lookup(this.cur);
            if ((c.flags & F_PIXELS) && this.half) this.partialPixel('cut short by a hardware reset with');
            else if (!(c.flags & F_PIXELS) && this.nparam < c.min)
              this.vcmd(this.cur, `cut short by a hardware reset: ${this.nparam} parameter bytes, needs ${c.min}`);
          }
          this.cur = -1;
          this.half = 0;
        }
        else if (!this.reset && level) {
          if (t - this.resetLowNs < this.model.resetPulseNs) {
            this.violate('RESET', -1, this.offset, `pulse of ${t - this.resetLowNs} ns, needs ${Math.floor(this.model.resetPulseNs / 1000)} us`);
          }
          else this.hwResetDone(t);
        }
        this.reset = level;
        break;
      case 2: this.cs = level; break;
      case 3: this.bl = level; break;
      default: break;
    }
  }

  finish() {
    /* Checked as if the command ended, but it stays current (with its
     * parameter count and half pixel): more data may still follow. */
    if (!this.violation && this.cur >= 0) {
      const c = this.lookup(this.cur);
      if (c.flags & F_PIXELS) {
        if (this.half) this.partialPixel('ended with');
      } else if (this.nparam < c.min) {
        this.vcmd(this.cur, `${this.nparam} parameter bytes, needs ${c.min}`);
      }
    }
    return this.violation ? -1 : 0;
  }

  /* Damage as a glitch on the wire would leave it (rp2040sim
   * --corrupt-at-frame): one pixel in every 16 rows of the module's memory
   * (its first column, rows 3, 19, ...) flipped. */
  corrupt() {
    const m = this.mod;
    for (let y = 3; y < m.gh; y += 16) this.mem[(m.memY + y) * MEM_W + m.memX] ^= 0x0841;
  }

  /* Viewed pixel (ox, oy) -> glass pixel (this.gx, this.gy): the glass
   * turned view*90 degrees. */
  viewToGlass(ox, oy) {
    const gw = this.mod.gw, gh = this.mod.gh;
    switch (this.view) {
      case 1: this.gx = gw - 1 - oy; this.gy = ox; break;
      case 2: this.gx = gw - 1 - ox; this.gy = gh - 1 - oy; break;
      case 3: this.gx = oy; this.gy = gh - 1 - ox; break;
      default: this.gx = ox; this.gy = oy; break;
    }
  }

  glassWidth() { return (this.view & 1) ? this.mod.gh : this.mod.gw; }
  glassHeight() { return (this.view & 1) ? this.mod.gw : this.mod.gh; }

  /* What the glass shows: Uint16Array of w*h RGB565 values, true RGB order. */
  glass() {
    const m = this.mod, w = this.glassWidth(), h = this.glassHeight();
    const out = new Uint16Array(w * h);
    if (!this.model.dcs) { this.ssdGlass(out, w, h); return out; }
    const dark = this.asleep || !this.displayOn || !this.bl || !this.reset;
    const off = (m.normallyBlack || !this.bl) ? 0x0000 : 0xFFFF;
    const invert = this.inverted !== m.inverted;
    const swap = ((this.madctl & 0x08) !== 0) !== (m.bgr !== 0);
    const gw = m.gw, gh = m.gh;
    for (let oy = 0; oy < h; oy++) {
      for (let ox = 0; ox < w; ox++) {
        this.viewToGlass(ox, oy);
        const gx = this.gx, gy = this.gy;
        const col = m.memX + (m.mirrorX ? gw - 1 - gx : gx);
        const row = m.memY + gy;
        let v = this.mem[row * MEM_W + col];
        const dx = 2 * gx + 1 - gw, dy = 2 * gy + 1 - gh;
        if (this.model.round && dx * dx + dy * dy > gw * gw) {
          v = 0;   /* no glass there */
        } else if (dark) {
          v = off;
        } else {
          if (invert) v = (~v) & 0xffff;
          if (this.idle) v = ((v & 0x8000) ? 0xF800 : 0) | ((v & 0x0400) ? 0x07E0 : 0) | ((v & 0x0010) ? 0x001F : 0);
          if (swap) v = (v & 0x07E0) | (v >> 11) | ((v & 0x1F) << 11);
        }
        out[oy * w + ox] = v;
      }
    }
    return out;
  }

  /* ---- SSD1351 (ssd_* in hal/sim/emu_panel.c) ---- */

  ssdCommand(code, c) {
    if (this.locked && code !== 0xFD) { this.vcmd(code, 'ignored: the command lock is on (FDh 16h)'); return; }
    if ((c.flags & F_LOCKB) && this.protect) {
      this.vcmd(code, 'refused: locked until the command lock is given B1h (FDh B1h)');
      return;
    }
    this.cur = code; this.nparam = 0;
    switch (code) {
      case 0xAE: this.asleep = 1; break;
      case 0xAF: this.asleep = 0; break;
      case 0xA4: case 0xA5: case 0xA6: case 0xA7: this.mode = code; break;
      case 0x5C:
        if ((this.remap & 0xC0) !== 0x40) {
          this.vcmd(code, `memory write with re-map 0x${hex2(this.remap)}: ${(this.remap & 0x80) ? '262k' : '256'} colours (only 65k, A0h bits 7:6 01b, emulated)`);
        }
        break;
      default: break;
    }
  }

  ssdExecute() {
    const a = this.param;
    switch (this.cur) {
      case 0x15: case 0x75: {
        const col = this.cur === 0x15;
        const lim = col ? this.model.memW : this.model.memH;
        if (a[0] > a[1]) this.vcmd(this.cur, `start ${a[0]} after end ${a[1]}`);
        else if (a[1] >= lim) this.vcmd(this.cur, `${col ? 'columns' : 'rows'} ${a[0]}..${a[1]} outside the memory (0..${lim - 1})`);
        else if (col) { this.xs = a[0]; this.xe = a[1]; this.cx = a[0]; }
        else { this.ys = a[0]; this.ye = a[1]; this.cy = a[0]; }
        break;
      }
      case 0xA0:
        if (a[0] & 0x08) this.vcmd(this.cur, 'reserved bit 3 set');
        else this.remap = a[0];
        break;
      case 0xA1: case 0xA2:
        if (a[0]) {
          this.vcmd(this.cur, this.cur === 0xA1 ? 'not emulated (a start line other than 0)'
            : 'not emulated (a display offset other than 0)');
        }
        break;
      case 0xCA:
        if (a[0] !== 127) this.vcmd(this.cur, 'not emulated (a multiplex ratio other than 127: 128 rows)');
        break;
      case 0xFD:
        switch (a[0]) {
          case 0x12: this.locked = 0; break;
          case 0x16: this.locked = 1; break;
          case 0xB0: this.protect = 1; break;
          case 0xB1: this.protect = 0; break;
          default: this.vcmd(this.cur, `parameter 0x${hex2(a[0])} (12h, 16h, B0h or B1h)`); break;
        }
        break;
      default: break;
    }
  }

  ssdPixel(v) {
    this.mem[this.cy * MEM_W + this.cx] = v;
    this.scanWrite(this.cy);
    this.pixelsWritten++;
    if (this.remap & 1) {
      if (this.cy < this.ye) { this.cy++; return; }
      this.cy = this.ys;
      this.cx = this.cx < this.xe ? this.cx + 1 : this.xs;
    } else {
      if (this.cx < this.xe) { this.cx++; return; }
      this.cx = this.xs;
      this.cy = this.cy < this.ye ? this.cy + 1 : this.ys;
    }
    /* the window's last pixel: its end and its size in pixels */
    if (this.cx === this.xs && this.cy === this.ys && this.onWrap) {
      this.onWrap(this.xe, this.ye, (this.xe - this.xs + 1) * (this.ye - this.ys + 1));
    }
  }

  ssdGlass(out, w, h) {
    const m = this.mod, mw = this.model.memW, mh = this.model.memH;
    const dark = this.asleep || !this.reset || this.mode === 0xA4;
    const invert = (this.mode === 0xA7) !== (m.inverted !== 0);
    const swap = ((this.remap & 0x04) !== 0) !== (m.bgr !== 0);
    const gw = m.gw;
    for (let oy = 0; oy < h; oy++) {
      for (let ox = 0; ox < w; ox++) {
        this.viewToGlass(ox, oy);
        const gx = this.gx, gy = this.gy;
        const seg = m.memX + (m.mirrorX ? gw - 1 - gx : gx);
        const line = m.memY + gy;
        const col = (this.remap & 0x02) ? mw - 1 - seg : seg;
        let row = (this.remap & 0x10) ? line : mh - 1 - line;
        if (!(this.remap & 0x20)) row = (row & 1) ? (mh >> 1) + (row >> 1) : row >> 1;
        let v = this.mem[row * MEM_W + col];
        if (dark) v = 0;
        else if (this.mode === 0xA5) v = 0xFFFF;
        else {
          if (invert) v = (~v) & 0xffff;
          if (swap) v = (v & 0x07E0) | (v >> 11) | ((v & 0x1F) << 11);
        }
        out[oy * w + ox] = v;
      }
    }
  }

  memAt(col, row) { return (col < this.model.memW && row < this.model.memH) ? this.mem[row * MEM_W + col] : 0; }
}

module.exports = { EmuPanel, MEM_W, MEM_H };
