#!/usr/bin/env node
// SPDX-License-Identifier: MIT
'use strict';
/* rp2040sim.js — runs a firmware image on the rp2040js emulator with an
 * emulated ST7789 on SPI0 and the DC/CS/RST/BL pins, and writes the frames
 * the glass shows.
 *
 * usage: node rp2040sim.js --image FILE.elf|FILE.bin [options]
 *   --frames N          stop after N frames announced by the firmware (default 1)
 *   --max-cycles N      stop with an error after N emulated cycles (default 4e9)
 *   --out-dir DIR       write DIR/frame-<i>.raw (RGB565 little-endian, as
 *                       host_sim --out-raw) and DIR/frame-<i>.ppm
 *   --out-raw FILE      the last frame as raw RGB565 little-endian
 *   --panel NAME        emulated module (default st7789)
 *   --pins dc=16,cs=17,rst=20,bl=21   the firmware's pin options
 *   --uart              echo the firmware's UART output to stderr
 *   --json              one JSON object per frame on stdout (scene, frame,
 *                       cycles and us: from the frame's "begin" line to its
 *                       last pixel, cycles at the firmware's clk_sys;
 *                       period_us: from its "begin" line to the next one's,
 *                       fps: 1 / period (the rate the board shows frames at;
 *                       the run goes on until the frame after the last one
 *                       begins); uart_stall_cycles: the cycles the firmware
 *                       waited for room in the UART's transmit FIFO in that
 *                       period (uart.js); spi_bytes; torn, scan_passes:
 *                       whether the frame's writes showed over more than
 *                       one pass of the panel's scan (emu_panel.js: the
 *                       glass scanned top to bottom at the controller's
 *                       frame rate, 60 Hz on the ST7789, 70 Hz on the
 *                       ILI9341), so that one pass showed part of it over
 *                       part of the frame before; shown: not torn, and a
 *                       pass shows it before the next frame's writes do
 *                       (--average: torn_frames, and shown_fps, the frames
 *                       shown whole a second);
 *                       cores, spi_hz: from the firmware's boot line; a two-core
 *                       image runs on both emulated cores, dualcore.js)
 *                       first_image_us: for a progressive (ray-traced) frame,
 *                       when its whole-screen preview was on the glass;
 *                       xip_misses, xip_stall_cycles: XIP cache misses in the
 *                       frame and the cycles they cost (xip.js), at
 *                       xip_fill_cycles per miss in boot2's read mode;
 *                       stack_bytes: [core 0, core 1], the deepest each
 *                       core's stack has been (the lowest SP an instruction
 *                       ran with, below the SP the core started its
 *                       application with) from the start to the end of the
 *                       frame's period (--average: the deepest of the run;
 *                       0 for a core that never started);
 *                       frame_checksum: FNV-1a of the frame on the glass at
 *                       its last pixel, RGB565 as little-endian bytes (as
 *                       the benchmark images and host_sim --stats sum theirs)
 *   --average           with --json: one object per run of consecutive frames
 *                       of a scene instead, their mean (frame = the first,
 *                       frames = how many, cycles_min, cycles_max;
 *                       frame_checksum of the first, the one drawn without
 *                       the fps overlay)
 *   --numeric MODE      the image's numeric mode, for --json (default fixed)
 *   --variant TEXT      the image's method choices, for --json (default single-core)
 *   --core1-speed F     core 1 runs F times as fast as core 0 (default 1; tests:
 *                       the frames must not depend on how the cores interleave)
 *   --inject-nmi N      raise an NMI on core 0 after N cycles (tests: the
 *                       firmware's fault report, a "fault ..." UART line)
 *   --watchdog-reset-at-frame N   once N frames are on the glass, a watchdog
 *                       reset of both processors (as the boot ROM's reboot,
 *                       which selects every domain but the oscillators):
 *                       core 1 back to the boot ROM, UART0 emptied, core 0
 *                       booted again through boot2 (the other peripherals
 *                       keep their state in rp2040js: the firmware's start-up
 *                       resets the ones it uses)
 *   --te-pin N          the panel's TE output wired to GPIO N (the firmware's
 *                       RP2040_PIN_TE): high in the scan's vertical blank
 *                       once the firmware sent TEON (emu_panel.js)
 *   --corrupt-at-frame N   once N frames are on the glass, damage the panel's
 *                       memory as a glitch on the wire would: one pixel in
 *                       every 16 rows (column 0, rows 3, 19, ...) flipped
 *                       (tests: the firmware's repair strips mend it)
 *   --core1-absent      core 1 never answers the launch handshake (tests:
 *                       the firmware's timeout and its error line)
 *   --reset-core0-at-frame N   once N frames are on the glass, reset core 0
 *                       alone (as a debug probe's reset or SYSRESETREQ do:
 *                       core 1 and the peripherals go on) and boot it again
 *                       through boot2; the firmware must recover (tests: the
 *                       frames after it; the "boot" line is then seen twice)
 *
 * Boot without a boot ROM image (rp2040js 1.4.1 has none): the image is
 * copied into the flash array, its boot2 checked and run from SRAM as the
 * boot ROM would (xip.js), and boot2 enters the application; and the XIP cache is modelled with the miss cost of the
 * read mode boot2 sets up. Core 1 waits in a model of the boot ROM's launch
 * handshake (dualcore.js). UART0's transmit FIFO drains at the configured
 * baud rate (uart.js): a firmware that writes more than the line carries
 * waits, as on the board. Time: each instruction advances the clock
 * by its cycles at the current clk_sys (rp2040js derives it from the PLL
 * and CLOCKS registers; the firmware's boot line must state the same
 * cpu_hz); SPI words complete after their bit count at the configured SPI
 * clock (clk_peri / (CPSDVSR * (1 + SCR))), so frame times include transfer
 * time. The core voltage regulator is modelled (vreg.js: the voltage must be
 * raised before clk_sys is), and a change of the XIP SSI's divider after
 * boot2 changes the cost of a cache miss from then on.
 *
 * Exit status: 0 done; 1 emulator or internal error (cycle limit, firmware
 * error or fault line, any emulator warning); 2 usage; 3 panel protocol violation (one line). */
const fs = require('fs');
const path = require('path');
const { RP2040, GPIOPinState } = require('rp2040js');
const { EmuPanel } = require('./emu_panel.js');
const { DualCore } = require('./dualcore.js');
const { XipCache, bootThroughBoot2 } = require('./xip.js');
const { UartTx } = require('./uart.js');
const { installVreg } = require('./vreg.js');
const { Profile } = require('./profile.js');

const FLASH_BASE = 0x10000000;

function usage(msg) {
  process.stderr.write(`rp2040sim: ${msg}\n`);
  process.exit(2);
}

function parseArgs(argv) {
  const o = { frames: 1, maxCycles: 4e9, panel: 'st7789', pins: { dc: 16, cs: 17, rst: 20, bl: 21 }, uart: false, json: false, average: false, numeric: 'fixed', variant: 'single-core', core1Speed: 1, injectNmi: 0, resetCore0At: 0, watchdogAt: 0, corruptAt: 0, tePin: -1, core1Absent: false };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const val = () => { if (i + 1 >= argv.length) usage(`${a} needs a value`); return argv[++i]; };
    switch (a) {
      case '--image': o.image = val(); break;
      case '--frames': o.frames = Number(val()); if (!(o.frames >= 1)) usage('--frames must be >= 1'); break;
      case '--max-cycles': o.maxCycles = Number(val()); if (!(o.maxCycles > 0)) usage('bad --max-cycles'); break;
      case '--out-dir': o.outDir = val(); break;
      case '--out-raw': o.outRaw = val(); break;
      case '--panel': o.panel = val(); break;
      case '--pins':
        for (const kv of val().split(',')) {
          const [k, v] = kv.split('=');
          if (!(k in o.pins) || !/^\d+$/.test(v || '') || Number(v) > 29) usage(`bad pin '${kv}'`);
          o.pins[k] = Number(v);
        }
        break;
      case '--uart': o.uart = true; break;
      case '--json': o.json = true; break;
      case '--average': o.average = true; break;
      case '--numeric': o.numeric = val(); break;
      case '--variant': o.variant = val(); break;
      case '--profile': o.profile = val(); break;
      case '--core1-absent': o.core1Absent = true; break;
      case '--watchdog-reset-at-frame': o.watchdogAt = Number(val()); if (!(o.watchdogAt >= 1)) usage('bad --watchdog-reset-at-frame'); break;
      case '--reset-core0-at-frame': o.resetCore0At = Number(val()); if (!(o.resetCore0At >= 1)) usage('bad --reset-core0-at-frame'); break;
      case '--te-pin': o.tePin = Number(val()); if (!(Number.isInteger(o.tePin) && o.tePin >= 0 && o.tePin < 30)) usage('bad --te-pin'); break;
      case '--corrupt-at-frame': o.corruptAt = Number(val()); if (!(o.corruptAt >= 1)) usage('bad --corrupt-at-frame'); break;
      case '--inject-nmi': o.injectNmi = Number(val()); if (!(o.injectNmi > 0)) usage('bad --inject-nmi'); break;
      case '--core1-speed': o.core1Speed = Number(val()); if (!(o.core1Speed >= 0.01 && o.core1Speed <= 100)) usage('--core1-speed must be in 0.01..100'); break;
      default: usage(`unknown option '${a}'`);
    }
  }
  if (!o.image) usage('--image FILE is required');
  if (o.average && !o.json) usage('--average needs --json');
  if (o.profile && !/\.elf$/.test(o.image)) usage('--profile needs an ELF image');
  return o;
}

/* Flash contents from an ELF (PT_LOAD segments at flash addresses) or a flat
 * binary at 0x10000000. */
function loadImage(file, flash) {
  let buf;
  try { buf = fs.readFileSync(file); } catch (e) { usage(`${file}: ${e.code === 'ENOENT' ? 'no such file' : e.message}`); }
  if (buf.length >= 52 && buf.readUInt32BE(0) === 0x7f454c46) {
    if (buf[4] !== 1 || buf[5] !== 1) usage(`${file}: not a 32-bit little-endian ELF`);
    const phoff = buf.readUInt32LE(28), phentsize = buf.readUInt16LE(42), phnum = buf.readUInt16LE(44);
    let n = 0;
    for (let i = 0; i < phnum; i++) {
      const ph = phoff + i * phentsize;
      const type = buf.readUInt32LE(ph), off = buf.readUInt32LE(ph + 4), paddr = buf.readUInt32LE(ph + 12);
      const filesz = buf.readUInt32LE(ph + 16);
      if (type !== 1 || filesz === 0) continue;
      if (paddr < FLASH_BASE || paddr + filesz > FLASH_BASE + flash.length) continue;
      flash.set(buf.subarray(off, off + filesz), paddr - FLASH_BASE);
      n++;
    }
    if (!n) usage(`${file}: no loadable segment in flash`);
  } else {
    if (buf.length > flash.length) usage(`${file}: larger than the flash`);
    flash.set(buf, 0);
  }
}

function writePpm(file, px, w, h) {
  const head = Buffer.from(`P6\n${w} ${h}\n255\n`);
  const body = Buffer.alloc(w * h * 3);
  for (let i = 0; i < w * h; i++) {
    const v = px[i], r = v >> 11, g = (v >> 5) & 63, b = v & 31;
    body[3 * i] = (r << 3) | (r >> 2);
    body[3 * i + 1] = (g << 2) | (g >> 4);
    body[3 * i + 2] = (b << 3) | (b >> 2);
  }
  fs.writeFileSync(file, Buffer.concat([head, body]));
}

/* FNV-1a of a frame's RGB565 pixels as little-endian bytes (the sum the
 * benchmark images print, tools/bench/startup.c bench_fnv565, and host_sim
 * --stats gives). */
function fnv565(px) {
  let h = 2166136261;
  for (let i = 0; i < px.length; i++) {
    h = Math.imul(h ^ (px[i] & 0xff), 16777619);
    h = Math.imul(h ^ (px[i] >>> 8), 16777619);
  }
  return h >>> 0;
}

function rawLE(px) {
  const b = Buffer.alloc(px.length * 2);
  for (let i = 0; i < px.length; i++) b.writeUInt16LE(px[i], 2 * i);
  return b;
}

function main() {
  const o = parseArgs(process.argv.slice(2));
  const mcu = new RP2040();
  /* an emulator warning (an unimplemented instruction or register, a stray
   * access) means the run no longer shows what the board would do: it ends
   * the run with an error */
  let emuWarning = null, dual = null;
  mcu.logger = {
    debug() {},
    info(tag, msg) { if (msg === 'SEV' && dual) dual.sev(); },
    warn(tag, msg) { if (!emuWarning) emuWarning = `emulator warning: ${tag}: ${msg}`; },
    error(tag, msg) { process.stderr.write(`rp2040js: ${msg}\n`); },
  };
  /* some parts of the package (SIO) warn on the console instead */
  console.warn = (...a) => { if (!emuWarning) emuWarning = `emulator warning: ${a.join(' ')}`; };
  loadImage(o.image, mcu.flash);
  installVreg(mcu);
  const xip = new XipCache(mcu);
  const prof = o.profile ? new Profile(mcu, mcu.flash.length, mcu.sram.length) : null;
  const bootProblem = bootThroughBoot2(mcu);
  if (bootProblem) { process.stderr.write(`rp2040sim: ${o.image}: ${bootProblem}\n`); process.exit(1); }
  dual = new DualCore(mcu, { core1Speed: o.core1Speed, xip, core1Absent: o.core1Absent, prof });
  /* UART0's transmit FIFO drains at the baud rate (uart.js); the time of an
   * access is the local time of the core making it */
  const uartTx = new UartTx(mcu, mcu.uart[0], () => dual.local[dual.cur]);
  /* RESETS: UART0 (bit 22) held in reset loses what it was sending */
  const resetsBlock = mcu.peripherals[0x4000c], resetsWrite = resetsBlock.writeUint32.bind(resetsBlock);
  resetsBlock.writeUint32 = (off, v) => {
    resetsWrite(off, v);
    if (off === 0 && (v & (1 << 22))) uartTx.reset();
  };

  let panel;
  try { panel = new EmuPanel(o.panel); } catch (e) { usage(e.message); }
  const clock = mcu.clock;
  const gpio = mcu.gpio;
  /* Undriven pins read high: the module pulls its control inputs up. */
  const level = (pin) => gpio[pin].value !== GPIOPinState.Low;
  let spiBytes = 0, cmdLog = [];

  /* Lines: sampled on change (line events carry the emulated time). */
  const lines = [[0, o.pins.dc], [1, o.pins.rst], [2, o.pins.cs], [3, o.pins.bl]];
  for (const [line, pin] of lines) {
    let last = 1;
    gpio[pin].addListener(() => {
      const v = level(pin) ? 1 : 0;
      if (v !== last) { last = v; panel.line(line, v, clock.nanos); }
    });
  }

  /* SPI0: each word reaches the panel when it leaves the FIFO and completes
   * after bits / f_spi; 16-bit frames go high byte first. */
  const spi = mcu.spi[0];
  const spiAlarm = clock.createAlarm(() => spi.completeTransmit(0));
  spi.onTransmit = (value) => {
    const t = clock.nanos, bits = spi.dataBits, f = spi.clockFrequency || 1e6;
    /* until the first frame has ended: the counters at each command (the
     * first frame's figures count from its first command) */
    if (cmdLog && !level(o.pins.dc)) cmdLog.push({ ns: t, spi: spiBytes, miss: xip.misses, stall: xip.stallTotal });
    if (bits > 8) { panel.spiByte((value >> 8) & 0xff, t); panel.spiByte(value & 0xff, t); spiBytes += 2; }
    else { panel.spiByte(value & 0xff, t); spiBytes += 1; }
    spiAlarm.schedule(Math.max(1, Math.round(bits * 1e9 / f)));
  };

  /* UART lines: "begin scene=... frame=... t=T" labels the next frame, which
   * began at T (the board's microsecond timer, low 32 bits; rp2040js's timer
   * counts the emulated time): the line itself may leave the board later
   * (the firmware queues its lines for the UART's interrupt), even after the
   * frame's last pixel. Frames are matched in order with the ends of frames
   * on the glass. Per frame: cycles from T to its last pixel; the period
   * from T to the next frame's T; spi_bytes and the XIP figures from the
   * previous frame's last pixel (the first frame: from its first command to
   * the panel after T) to its last; uart_stall over the period. */
  let uartLine = '', fwError = null, cpuHz = 133e6, cores = 1, spiHz = 0;
  const frames = [];
  const begins = [];     /* frames begun, waiting for their last pixel */
  const ends = [];       /* frames ended before their line arrived */
  let lastBegin = null, lastEnd = null;
  const snap = () => ({ spi: spiBytes, miss: xip.misses, stall: xip.stallTotal });
  /* each core's deepest stack since it started its application */
  const stackNow = () => [dual.stackPeak(0), dual.launched[1] ? dual.stackPeak(1) : 0];
  /* T (32 bits of us) as emulated ns: the latest time at or before now */
  const beginNs = (t) => {
    const nowUs = Math.floor(clock.nanos / 1000);
    return t === undefined || !/^\d+$/.test(t) ? clock.nanos : (nowUs - ((nowUs - Number(t)) >>> 0)) * 1000;
  };
  const finish = (b, endNs, end) => {
    const from = end.prev || b.snap0;
    frames.push(Object.assign(b, { ns: endNs - b.t_ns, spi_bytes: end.snap.spi - from.spi, passes: end.passes, scan: end.scan,
      xip_misses: end.snap.miss - from.miss, xip_stall_cycles: end.snap.stall - from.stall, px: end.px }));
  };
  /* a line cut by the UART's reset is dropped */
  uartTx.onReset = () => { if (o.uart && uartLine) process.stderr.write('\n'); uartLine = ''; };
  uartTx.onByte = (b) => {
    const ch = String.fromCharCode(b);
    if (o.uart) process.stderr.write(ch);
    if (ch === '\n') {
      const l = uartLine.replace(/\r$/, '');
      uartLine = '';
      const kv = Object.fromEntries(l.split(' ').slice(1).map((s) => s.split('=')));
      if (l.startsWith('boot ')) {
        cpuHz = Number(kv.cpu_hz) || cpuHz; cores = Number(kv.cores) || cores; spiHz = Number(kv.spi_hz) || spiHz;
        if (cpuHz !== mcu.clkSys) fwError = `the boot line's cpu_hz=${cpuHz} is not the clk_sys the registers set (${mcu.clkSys} Hz)`;
      }
      if (l.startsWith('begin ')) {
        const t = beginNs(kv.t);
        /* the previous frame's period, and the firmware's waits for room
         * in the UART's FIFO in it */
        if (lastBegin) {
          lastBegin.period_ns = t - lastBegin.t_ns;
          lastBegin.stack = stackNow();
          lastBegin.uart_stall_ns = uartTx.stallAt(t) - uartTx.stallAt(lastBegin.t_ns);
        }
        /* the first frame's tearing counts its own writes, not the start-up's */
        if (!lastBegin && !lastEnd) panel.takeTear();
        lastBegin = { scene: kv.scene, frame: Number(kv.frame), t_ns: t, snap0: snap() };
        const e = ends.shift();
        if (e) finish(lastBegin, e.ns, e); else begins.push(lastBegin);
      }
      /* a progressive frame: its first full-screen image is the preview */
      if (l.startsWith('coarse ') && begins.length) begins[begins.length - 1].coarse = true;
      if (l.startsWith('fps ') && frames.length) frames[frames.length - 1].fw_us = Number(kv.us);
      if (l.startsWith('error') || l.startsWith('fault ')) fwError = l;
    } else {
      uartLine += ch;
    }
  };
  /* A frame ends with the last pixel of the screen: the write reaching the
   * end of a window that ends where the largest window so far ends (the
   * firmware's first frame is one whole-screen window; later frames may send
   * only the columns that changed, strip by strip, the last one always to
   * the screen's last pixel). */
  let endX = -1, endY = -1, endArea = 0;
  panel.onWrap = (xe, ye, area) => {
    if (area > endArea) { endArea = area; endX = xe; endY = ye; }
    if (xe !== endX || ye !== endY) return;
    if (!lastBegin) return;          /* before the first frame */
    const now = clock.nanos, b = begins[0];
    if (b && b.coarse && b.first_ns === undefined) { b.first_ns = now - b.t_ns; return; }
    if (!lastEnd) {
      /* the first frame: from its first command */
      const t0 = (b || lastBegin).t_ns;
      lastEnd = cmdLog.find((c) => c.ns >= t0) || (b || lastBegin).snap0;
      cmdLog = null;
    }
    const scan = panel.takeTear();
    const end = { ns: now, prev: lastEnd, snap: snap(), px: panel.glass(), scan,
      passes: scan.hi >= scan.lo ? scan.hi - scan.lo + 1 : 0 };
    lastEnd = end.snap;
    if (b) finish(begins.shift(), now, end); else ends.push(end);
  };

  /* core 0 alone reset and booted again: the frame it was drawing never
   * ends; frames are counted again from the next begin line */
  const resetCore0 = () => {
    dual.resetCore0();
    bootThroughBoot2(mcu);
    begins.length = 0;
    ends.length = 0;
    lastBegin = null;
    lastEnd = null;
    cmdLog = [];
    resets++;
  };
  let resets = 0;

  /* boot2 from SRAM until it enters the application in flash */
  for (let i = 0; !(mcu.core.PC >= FLASH_BASE && mcu.core.PC < FLASH_BASE + 0x4000000); i++) {
    if (i > 100000 || !dual.run(1) || emuWarning) {
      process.stderr.write(`rp2040sim: ${emuWarning || 'boot2 did not enter the application'}\n`);
      process.exit(1);
    }
  }
  xip.configure();
  dual.stackMark(0);
  if (prof) prof.on = true;

  const t0 = Date.now();
  const maxNs = o.maxCycles / cpuHz * 1e9;
  /* until the frame after the last one begins (the last one's period) */
  const done = () => frames.length >= o.frames && frames[o.frames - 1].period_ns !== undefined;
  while (!done() && !fwError && !panel.violation) {
    /* with TE wired, steps of 2000 cycles (15 us) so that the firmware
     * sees each blank (0.8 ms at 60 Hz) */
    if (o.tePin >= 0) gpio[o.tePin].setInputValue(panel.te(clock.nanos));
    const awake = dual.run(o.injectNmi ? 1000 : o.tePin >= 0 ? 2000 : 100000);
    if (o.injectNmi && clock.nanos * cpuHz / 1e9 >= o.injectNmi) {
      dual.cores[0].pendingNMI = true;
      dual.cores[0].interruptsUpdated = true;
      o.injectNmi = 0;
    }
    if (o.corruptAt && frames.length >= o.corruptAt) {
      o.corruptAt = 0;
      panel.corrupt();
    }
    if (o.resetCore0At && frames.length >= o.resetCore0At) {
      o.resetCore0At = 0;
      resetCore0();
    }
    if (o.watchdogAt && frames.length >= o.watchdogAt) {
      o.watchdogAt = 0;
      dual.holdCore1(true);
      dual.holdCore1(false);
      uartTx.reset();
      resetCore0();
    }
    if (fwError) break;
    if (emuWarning) { fwError = emuWarning; break; }
    if (!awake) { fwError = 'firmware sleeps with nothing to wake it'; break; }
    if (clock.nanos > maxNs) { fwError = `no frame after ${o.maxCycles} cycles`; break; }
  }
  if (!fwError && cores === 2 && !dual.launched[1]) fwError = 'a two-core image that never started core 1';
  if (!fwError && uartTx.lost) fwError = `${uartTx.lost} character(s) written to a full UART FIFO were lost`;
  frames.length = Math.min(frames.length, o.frames);
  for (const f of frames) if (!f.stack) f.stack = stackNow();
  if (panel.violation) { process.stderr.write(`rp2040sim: panel protocol violation: ${panel.violation}\n`); process.exit(3); }
  if (fwError) { process.stderr.write(`rp2040sim: ${fwError}\n`); process.exit(1); }

  /* A frame the glass shows whole: not torn, and some pass shows it before
   * the next frame's writes do (frames faster than the scan overwrite one
   * another before it reaches them). The last one: shown if not torn. */
  frames.forEach((f, i) => {
    const nx = frames[i + 1];
    f.shown = f.passes === 1 && (!nx || !(nx.scan.lo <= f.scan.hi));
  });
  const w = panel.glassWidth(), h = panel.glassHeight();
  if (o.outDir) fs.mkdirSync(o.outDir, { recursive: true });
  frames.forEach((f, i) => {
    const cycles = Math.round(f.ns * cpuHz / 1e9);
    if (o.outDir) {
      fs.writeFileSync(path.join(o.outDir, `frame-${i}.raw`), rawLE(f.px));
      writePpm(path.join(o.outDir, `frame-${i}.ppm`), f.px, w, h);
    }
    if (o.json && !o.average) {
      process.stdout.write(JSON.stringify({
        target: 'rp2040-sim', what: `scene:${f.scene}`, numeric: o.numeric, variant: o.variant, cores,
        frame: f.frame, width: w, height: h,
        cycles, per: 'frame', cpu_hz: cpuHz, ...(spiHz ? { spi_hz: spiHz } : {}), us: Math.round(f.ns / 1000),
        period_us: Math.round(f.period_ns / 1000), fps: Number((1e9 / f.period_ns).toFixed(3)),
        uart_stall_cycles: Math.round(f.uart_stall_ns * cpuHz / 1e9), spi_bytes: f.spi_bytes,
        torn: f.passes > 1, scan_passes: f.passes, shown: f.shown, xip_misses: f.xip_misses, xip_stall_cycles: f.xip_stall_cycles, xip_fill_cycles: xip.fill.cycles,
        ...(f.first_ns !== undefined ? { first_image_us: Math.round(f.first_ns / 1000) } : {}),
        stack_bytes: f.stack, frame_checksum: fnv565(f.px),
      }) + '\n');
    }
  });
  if (o.json && o.average) {
    /* runs of consecutive frames of one scene: the mean frame */
    const runs = [];
    for (const f of frames) {
      const r = runs[runs.length - 1];
      if (r && r.scene === f.scene) r.list.push(f); else runs.push({ scene: f.scene, list: [f] });
    }
    for (const r of runs) {
      const n = r.list.length, cyc = r.list.map((f) => f.ns * cpuHz / 1e9);
      const ns = r.list.reduce((a, f) => a + f.ns, 0) / n;
      const period = r.list.reduce((a, f) => a + f.period_ns, 0) / n;
      const stall = r.list.reduce((a, f) => a + f.uart_stall_ns, 0) / n;
      process.stdout.write(JSON.stringify({
        target: 'rp2040-sim', what: `scene:${r.scene}`, numeric: o.numeric, variant: o.variant, cores,
        frame: r.list[0].frame, frames: n, width: w, height: h, frame_checksum: fnv565(r.list[0].px),
        cycles: Math.round(ns * cpuHz / 1e9), per: 'frame',
        cycles_min: Math.round(Math.min(...cyc)), cycles_max: Math.round(Math.max(...cyc)),
        cpu_hz: cpuHz, ...(spiHz ? { spi_hz: spiHz } : {}), us: Math.round(ns / 1000), period_us: Math.round(period / 1000),
        fps: Number((1e9 / period).toFixed(3)), uart_stall_cycles: Math.round(stall * cpuHz / 1e9),
        spi_bytes: Math.round(r.list.reduce((a, f) => a + f.spi_bytes, 0) / n),
        torn_frames: r.list.filter((f) => f.passes > 1).length,
        shown_fps: Number((r.list.filter((f) => f.shown).length * 1e9 / (period * n)).toFixed(3)),
        xip_misses: Math.round(r.list.reduce((a, f) => a + f.xip_misses, 0) / n),
        xip_stall_cycles: Math.round(r.list.reduce((a, f) => a + f.xip_stall_cycles, 0) / n),
        xip_fill_cycles: xip.fill.cycles,
        stack_bytes: [0, 1].map((i) => Math.max(...r.list.map((f) => f.stack[i]))),
        ...(r.list[0].first_ns !== undefined
          ? { first_image_us: Math.round(r.list.reduce((a, f) => a + f.first_ns, 0) / n / 1000) } : {}),
      }) + '\n');
    }
  }
  if (prof) prof.write(o.profile, path.basename(o.image), fs.readFileSync(o.image), frames.length,
    frames.reduce((a, f) => a + f.ns * cpuHz / 1e9, 0));
  if (o.outRaw) fs.writeFileSync(o.outRaw, rawLE(frames[frames.length - 1].px));
  const simS = (Date.now() - t0) / 1000;
  const torn = frames.filter((f) => f.passes > 1).length;
  process.stderr.write(`rp2040sim: ${frames.length} frame(s), ${Math.round(clock.nanos * cpuHz / 1e9)} cycles emulated in ${simS.toFixed(1)} s` +
    `, ${torn} torn (shown over more than one scan of the glass)` +
    (resets ? `, core 0 reset ${resets} time(s), core 1 ${dual.core1Resets}` : '') + '\n');
}

main();
