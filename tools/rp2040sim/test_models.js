#!/usr/bin/env node
// SPDX-License-Identifier: MIT
'use strict';
/* test_models.js — the emulator driver's hardware models through the bus.
 * dualcore.js as each core's firmware sees it: CPUID, the FIFOs and their
 * status flags, per-core dividers, shared GPIO and spinlocks, SEV, and the
 * launch handshake (with a wrong start, stale words and restarts).
 * xip.js: hits, misses, the two ways and LRU replacement, the uncached and
 * non-allocating aliases, the line-fill cost of the 03h and EBh read modes,
 * and the boot ROM's boot2 CRC. uart.js: the transmit FIFO's fill (TXFF,
 * TXFE, BUSY), its drain at the baud rate, the transmit interrupt at its
 * trigger level, and the time counted as waiting. vreg.js: VREG's reset value,
 * ROK, the atomic aliases, and a clk_sys raised above what the voltage is for.
 * The SPI clock from CPSDVSR and SCR, and a miss's cost after BAUDR changes.
 * Prints PASS/FAIL lines (tests/support/run.sh). */
const { RP2040 } = require('rp2040js');
const { DualCore } = require('./dualcore.js');
const { XipCache, lineFillCycles, crc32BootRom, boot2Problem } = require('./xip.js');
const { UartTx } = require('./uart.js');

const SIO = 0xd0000000;
const CPUID = SIO, FIFO_ST = SIO + 0x50, FIFO_WR = SIO + 0x54, FIFO_RD = SIO + 0x58;
const GPIO_OUT_SET = SIO + 0x14, GPIO_OUT = SIO + 0x10, SPINLOCK0 = SIO + 0x100;
const DIV_UDIVIDEND = SIO + 0x60, DIV_UDIVISOR = SIO + 0x64, DIV_QUOTIENT = SIO + 0x70;
let failed = 0;

function check(name, ok, why) {
  if (ok) process.stdout.write(`PASS dualcore_${name}\n`);
  else { failed++; process.stdout.write(`FAIL dualcore_${name}: ${why}\n`); }
}

function fresh() {
  const mcu = new RP2040();
  mcu.logger = { debug() {}, info() {}, warn() {}, error() {} };
  const dc = new DualCore(mcu);
  /* accesses as core i */
  const as = (i, f) => { const prev = dc.cur; dc.cur = i; mcu.core = dc.cores[i]; try { return f(); } finally { dc.cur = prev; mcu.core = dc.cores[prev]; } };
  const rd = (i, a) => as(i, () => mcu.readUint32(a) >>> 0);
  const wr = (i, a, v) => as(i, () => mcu.writeUint32(a, v));
  return { mcu, dc, rd, wr };
}

/* core 0's side of the launch as the datasheet gives it; returns the echoes */
function launch(t, seq) {
  const echoes = [];
  let i = 0, guard = 0;
  while (i < seq.length && guard++ < 100) {
    if (seq[i] === 0) while (t.rd(0, FIFO_ST) & 1) t.rd(0, FIFO_RD);
    t.wr(0, FIFO_WR, seq[i]);
    const e = t.rd(0, FIFO_RD);
    echoes.push(e);
    i = e === seq[i] ? i + 1 : 0;
  }
  return echoes;
}

{
  const t = fresh();
  check('cpuid_per_core', t.rd(0, CPUID) === 0 && t.rd(1, CPUID) === 1, `${t.rd(0, CPUID)} ${t.rd(1, CPUID)}`);
}

{
  /* launch, with garbage first: every word echoed; 0 0 1 V S P starts core 1 */
  const t = fresh();
  t.wr(0, FIFO_WR, 0x1234);
  const stale = t.rd(0, FIFO_RD);
  const seq = [0, 0, 1, 0x10000100, 0x20041000, 0x10000201];
  const echoes = launch(t, seq);
  const c1 = t.dc.cores[1];
  check('bootrom_echoes_garbage', stale === 0x1234, `echo ${stale}`);
  check('bootrom_echoes_sequence', echoes.join() === seq.join(), echoes.join());
  check('bootrom_launches_core1', t.dc.launched[1] && c1.VTOR === 0x10000100 && c1.SP === 0x20041000 &&
        c1.PC === 0x10000200, `launched ${t.dc.launched[1]} VTOR ${c1.VTOR.toString(16)} SP ${c1.SP.toString(16)} PC ${c1.PC.toString(16)}`);
}

{
  /* a restart in the middle (0 after VTOR) and stale words queued for
   * core 1: the 0 drains them, and the full sequence still launches */
  const t = fresh();
  t.wr(0, FIFO_WR, 0); t.rd(0, FIFO_RD);
  t.wr(0, FIFO_WR, 0); t.rd(0, FIFO_RD);
  t.wr(0, FIFO_WR, 1); t.rd(0, FIFO_RD);
  t.wr(0, FIFO_WR, 0x10000100); t.rd(0, FIFO_RD);
  check('bootrom_not_launched_on_partial_sequence', !t.dc.launched[1], 'launched early');
  const echoes = launch(t, [0, 0, 1, 0x10000100, 0x20041000, 0x10000201]);
  check('bootrom_restart_then_launch', t.dc.launched[1] && t.dc.launchCount === 1 && echoes.length === 6,
        `launched ${t.dc.launched[1]} count ${t.dc.launchCount} echoes ${echoes.join()}`);
  check('bootrom_needs_one_after_zeros', (() => {
    const u = fresh();
    for (const w of [0, 0, 2, 0x10000100, 0x20041000, 0x10000201]) { u.wr(0, FIFO_WR, w); u.rd(0, FIFO_RD); }
    return !u.dc.launched[1];
  })(), 'launched without the 1');
}

{
  /* FIFOs once core 1 runs: 8 words each way, VLD/RDY, sticky WOF/ROE
   * cleared by a write to FIFO_ST */
  const t = fresh();
  launch(t, [0, 0, 1, 0x10000100, 0x20041000, 0x10000201]);
  check('fifo_empty_status', t.rd(0, FIFO_ST) === 2 && t.rd(1, FIFO_ST) === 2,
        `${t.rd(0, FIFO_ST)} ${t.rd(1, FIFO_ST)}`);
  for (let i = 0; i < 8; i++) t.wr(0, FIFO_WR, 100 + i);
  check('fifo_full_not_ready', (t.rd(0, FIFO_ST) & 2) === 0 && (t.rd(1, FIFO_ST) & 1) === 1,
        `${t.rd(0, FIFO_ST)} ${t.rd(1, FIFO_ST)}`);
  t.wr(0, FIFO_WR, 999);
  check('fifo_overflow_sticky', (t.rd(0, FIFO_ST) & 4) !== 0, `${t.rd(0, FIFO_ST)}`);
  const got = [];
  for (let i = 0; i < 8; i++) got.push(t.rd(1, FIFO_RD));
  check('fifo_order_and_drop', got.join() === '100,101,102,103,104,105,106,107', got.join());
  t.rd(1, FIFO_RD);
  check('fifo_read_empty_sticky', (t.rd(1, FIFO_ST) & 8) !== 0, `${t.rd(1, FIFO_ST)}`);
  t.wr(0, FIFO_ST, 0); t.wr(1, FIFO_ST, 0);
  check('fifo_flags_cleared_by_write', t.rd(0, FIFO_ST) === 2 && t.rd(1, FIFO_ST) === 2,
        `${t.rd(0, FIFO_ST)} ${t.rd(1, FIFO_ST)}`);
  t.wr(1, FIFO_WR, 77);
  check('fifo_core1_to_core0', (t.rd(0, FIFO_ST) & 1) === 1 && t.rd(0, FIFO_RD) === 77, 'word lost');
}

{
  /* divider per core; GPIO and spinlocks shared */
  const t = fresh();
  t.wr(0, DIV_UDIVIDEND, 100); t.wr(0, DIV_UDIVISOR, 7);
  t.wr(1, DIV_UDIVIDEND, 1000); t.wr(1, DIV_UDIVISOR, 10);
  check('divider_per_core', t.rd(0, DIV_QUOTIENT) === 14 && t.rd(1, DIV_QUOTIENT) === 100,
        `${t.rd(0, DIV_QUOTIENT)} ${t.rd(1, DIV_QUOTIENT)}`);
  t.wr(1, GPIO_OUT_SET, 1 << 16);
  check('gpio_shared', t.rd(0, GPIO_OUT) === 1 << 16 && t.mcu.sio.gpioValue === 1 << 16, `${t.rd(0, GPIO_OUT)}`);
  const a = t.rd(0, SPINLOCK0), b = t.rd(1, SPINLOCK0);
  t.wr(0, SPINLOCK0, 0);
  const c = t.rd(1, SPINLOCK0);
  check('spinlock_shared', a !== 0 && b === 0 && c !== 0, `${a} ${b} ${c}`);
}

{
  /* SEV: wakes a core in WFE, or leaves the event for its next WFE */
  const t = fresh();
  launch(t, [0, 0, 1, 0x10000100, 0x20041000, 0x10000201]);
  const [c0, c1] = t.dc.cores;
  c1.waiting = true; c1.eventRegistered = false; c0.eventRegistered = false;
  t.dc.cur = 0;
  t.dc.sev();
  check('sev_wakes_waiting_core', !c1.waiting && !c1.eventRegistered, `waiting ${c1.waiting}`);
  check('sev_sets_own_event', c0.eventRegistered, 'event not set');
}

{
  /* the cache: 1024 sets of two 8-byte ways; addresses 16 KB apart share a set */
  const mcu = new RP2040();
  mcu.logger = { debug() {}, info() {}, warn() {}, error() {} };
  const x = new XipCache(mcu);
  mcu.peripherals[0x18000].crtlr0 = (31 << 16) | (3 << 8);
  mcu.peripherals[0x18000].spictlr0 = (0x03 << 24) | (2 << 8) | (6 << 2);
  mcu.peripherals[0x18000].baudr = 4;
  x.configure();
  x.charging = true;
  const A = 0x10001000, B = A + 0x4000, C = A + 0x8000;
  mcu.readUint32(A); mcu.readUint16(A + 6);
  check('xip_line_fill_once', x.misses === 1, `${x.misses} misses`);
  mcu.readUint32(A + 8);
  check('xip_next_line_misses', x.misses === 2, `${x.misses} misses`);
  mcu.readUint32(B); mcu.readUint32(B); mcu.readUint32(A);
  check('xip_two_ways', x.misses === 3, `${x.misses} misses`);
  mcu.readUint32(C);            /* evicts B, the least recently used */
  mcu.readUint32(A);
  const before = x.misses;
  mcu.readUint32(B);
  check('xip_lru_replacement', before === 4 && x.misses === 5, `${before} then ${x.misses}`);
  const m0 = x.misses;
  mcu.readUint32(0x12000000 + 0x1000); mcu.readUint32(0x12000000 + 0x1000);
  check('xip_nocache_alias_always_reads_flash', x.misses === m0 + 2, `${x.misses - m0}`);
  const m1 = x.misses;
  mcu.readUint32(0x11000000 + 0x2000); mcu.readUint32(0x11000000 + 0x2000);
  mcu.readUint32(0x11000000 + 0x1000);   /* A is cached: a hit through the alias */
  check('xip_noalloc_alias', x.misses === m1 + 2, `${x.misses - m1}`);
  check('xip_stall_charged', x.take() === x.misses * 388 && x.take() === 0, 'stall not as counted');
  x.charging = false;
  mcu.readUint32(0x10009000);
  check('xip_dma_not_charged', x.take() === 0, 'charged outside an instruction');
  /* the firmware's divider for a faster clk_sys: SSIENR 0, BAUDR 6, SSIENR 1 */
  mcu.writeUint32(0x18000008, 0); mcu.writeUint32(0x18000014, 6); mcu.writeUint32(0x18000008, 1);
  check('xip_fill_follows_baudr_after_boot', x.fill.cycles === 96 * 6 + 4, `${x.fill.cycles}`);
}

{
  /* line fill: 03h serial at clk_sys/4, EBh quad continuous at clk_sys/2 */
  const serial = lineFillCycles({ crtlr0: (31 << 16) | (3 << 8), spictlr0: (0x03 << 24) | (2 << 8) | (6 << 2), baudr: 4 });
  const quad = lineFillCycles({ crtlr0: (2 << 21) | (31 << 16) | (3 << 8),
                                spictlr0: (0xa0 << 24) | (4 << 11) | (0 << 8) | (8 << 2) | 2, baudr: 2 });
  check('xip_fill_serial_03h', serial.cycles === 388, `${serial.cycles}`);
  check('xip_fill_quad_ebh', quad.cycles === 60, `${quad.cycles}`);
}

{
  /* boot2 CRC as the boot ROM checks it (check value of "123456789": 0x0376e6e7) */
  check('boot2_crc32_check_value', crc32BootRom(Buffer.from('123456789')) === 0x0376e6e7,
        crc32BootRom(Buffer.from('123456789')).toString(16));
  const flash = new Uint8Array(256);
  const crc = crc32BootRom(flash.subarray(0, 252));
  flash[252] = crc & 255; flash[253] = (crc >>> 8) & 255; flash[254] = (crc >>> 16) & 255; flash[255] = crc >>> 24;
  const ok = boot2Problem(flash) === null;
  flash[3] ^= 1;
  check('boot2_crc_accepts_and_refuses', ok && boot2Problem(flash) !== null, 'CRC check wrong');
}

{
  /* UART0 at 115200 8N1 from clk_peri 125 MHz (IBRD 67, FBRD 52): 10 bits a
   * character, 86.8 us */
  const UART = 0x40034000, DR = UART, FR = UART + 0x18, IBRD = UART + 0x24, FBRD = UART + 0x28,
    LCR_H = UART + 0x2c, IFLS = UART + 0x34, IMSC = UART + 0x38, RIS = UART + 0x3c;
  const mcu = new RP2040();
  mcu.logger = { debug() {}, info() {}, warn() {}, error() {} };
  mcu.clkPeri = 125e6;
  const u = new UartTx(mcu, mcu.uart[0]);
  let irq = false;
  mcu.setInterrupt = (n, v) => { if (n === 20) irq = v; };
  const wire = [];
  u.onWire = (b) => wire.push([b, mcu.clock.nanos]);
  mcu.writeUint32(IBRD, 67); mcu.writeUint32(FBRD, 52); mcu.writeUint32(LCR_H, (3 << 5) | (1 << 4));
  mcu.writeUint32(IFLS, 0); mcu.writeUint32(IMSC, 1 << 5);
  const fr0 = mcu.readUint32(FR);
  for (let i = 0; i < 33; i++) mcu.writeUint32(DR, 65 + i);
  const fr1 = mcu.readUint32(FR);
  check('uart_fifo_empty_then_full', (fr0 & 0xa8) === 0x80 && (fr1 & 0xa8) === 0x28,
        `FR ${fr0.toString(16)} then ${fr1.toString(16)}`);
  /* the first character went to the shift register at once: 33 fit */
  check('uart_33_fit_none_lost', u.lost === 0 && u.written === 33, `lost ${u.lost} written ${u.written}`);
  /* one character on the line (it left the FIFO at once), 32 in the FIFO */
  const charNs = 10 * 16 * (67 + 52 / 64) * 1e9 / 125e6;
  const run = (ns) => mcu.clock.tick(ns);
  run(charNs * 1.5);
  check('uart_drains_at_baud_rate', wire.length === 1 && Math.abs(wire[0][1] - charNs) < 2 &&
        !(mcu.readUint32(FR) & 0x20), `${wire.length} out, first at ${wire.length && wire[0][1]} ns (${charNs})`);
  check('uart_tx_irq_not_yet', !irq && !(mcu.readUint32(RIS) & 0x20), `irq ${irq}`);
  run(charNs * 28);   /* 28 more out, 4 left: the trigger level, 1/8 */
  check('uart_tx_irq_at_trigger', irq && (mcu.readUint32(RIS) & 0x20) !== 0, `${wire.length} out, irq ${irq}`);
  mcu.writeUint32(DR, 1); mcu.writeUint32(DR, 2);
  check('uart_tx_irq_cleared_above_trigger', !irq, `irq ${irq}`);
  run(charNs * 40);
  check('uart_all_sent_in_order', wire.length === 35 && wire[32][0] === 97 && wire[34][0] === 2 &&
        (mcu.readUint32(FR) & 0xa8) === 0x80, `${wire.length} out, FR ${mcu.readUint32(FR).toString(16)}`);
  /* a loop polling TXFF is a wait; one look that goes on is not */
  for (let i = 0; i < 32; i++) mcu.writeUint32(DR, 48);
  mcu.readUint32(FR);
  run(1e6);
  const before = u.stallNs;
  for (let i = 0; i < 32; i++) mcu.writeUint32(DR, 48);
  const t0 = mcu.clock.nanos;
  for (let i = 0; i < 1e5 && (mcu.readUint32(FR) & 0x20); i++) mcu.clock.tick(50);
  const waited = mcu.clock.nanos - t0;
  check('uart_stall_counts_waits_only', before === 0 && Math.abs(u.stallNs - waited) < 1 && waited > 0,
        `stall ${before} then ${u.stallNs} for a wait of ${waited} ns`);
}

{
  /* the core voltage regulator (vreg.js) and the clocks that follow the
   * registers: PLL_SYS at 250 MHz (1500/6/1) needs 1.20 V (VSEL 13) first */
  const { installVreg } = require('./vreg.js');
  const VREG = 0x40064000, PLL_SYS = 0x40028000, CLK_SYS_CTRL = 0x4000803c;
  const warns = [];
  const mcu = new RP2040();
  mcu.logger = { debug() {}, info() {}, warn(t, m) { warns.push(m); }, error() {} };
  installVreg(mcu);
  const v0 = mcu.readUint32(VREG) >>> 0;
  check('vreg_reset_1v10_enabled_in_regulation', v0 === (0xb1 | 1 << 12), `VREG ${v0.toString(16)}`);
  const pll250 = () => {
    mcu.writeUint32(PLL_SYS + 8, 125); mcu.writeUint32(PLL_SYS + 0xc, (6 << 16) | (1 << 12));
    mcu.writeUint32(PLL_SYS + 4, 0);
    mcu.writeUint32(CLK_SYS_CTRL, 0); mcu.writeUint32(CLK_SYS_CTRL, 1);
  };
  mcu.writeUint32(VREG, 1 | (12 << 4));             /* 1.15 V: too low for 250 MHz */
  pll250();
  check('vreg_clock_above_voltage_warns', mcu.clkSys === 250e6 && warns.length === 1 && /250 MHz.*1\.15 V/.test(warns[0]),
        `clk_sys ${mcu.clkSys}, ${warns.join('; ')}`);
  mcu.writeUint32(CLK_SYS_CTRL, 0);                 /* back to clk_ref */
  warns.length = 0;
  mcu.writeUint32(VREG + 0x2000, 1 << 4);           /* atomic set: VSEL 12 -> 13, 1.20 V */
  const v1 = mcu.readUint32(VREG) >>> 0;
  pll250();
  check('vreg_atomic_set_and_clock_within_voltage', ((v1 >>> 4) & 15) === 13 && (v1 & (1 << 12)) !== 0 &&
        mcu.clkSys === 250e6 && warns.length === 0, `VREG ${v1.toString(16)}, clk_sys ${mcu.clkSys}, ${warns.join('; ')}`);
  /* SPI0: clk_peri / (CPSDVSR * (1 + SCR)); 125 MHz / (2 * 7) for the ILI9341's 10 MHz */
  const SPI0 = 0x4003c000;
  mcu.clkPeri = 125e6;
  mcu.writeUint32(SPI0 + 0x10, 2); mcu.writeUint32(SPI0, (6 << 8) | (3 << 6) | 7);
  check('spi_clock_from_cpsdvsr_and_scr', Math.abs(mcu.spi[0].clockFrequency - 125e6 / 14) < 1,
        `${mcu.spi[0].clockFrequency} Hz`);
}

/* The panel's scan (emu_panel.js): a frame written within one pass's blank
 * shows whole from the next pass; one written while the scan runs through
 * it shows over two passes (torn). */
{
  const { EmuPanel } = require('./emu_panel.js');
  const p = new EmuPanel('st7789');
  const T = p.scanNs, rows = p.mod.gh;
  const write = (t0, dt) => { for (let g = 0; g < rows; g++) { p.now = t0 + g * dt; p.scanWrite(p.mod.memY + g); } };
  write(10 * T + 0.96 * T, 0.0001 * T / rows);   /* inside the blank, quickly */
  const w0 = p.takeTear(), whole = w0.hi - w0.lo + 1;
  write(20 * T + 0.5 * T, 0.1 * T / rows);       /* from the top while the scan is past the middle: it
                                                    overtakes the scan, whose pass shows the rows below
                                                    and the next pass the rows above */
  const t0 = p.takeTear(), torn = t0.hi - t0.lo + 1;
  write(30 * T + 0.96 * T, 0.9 * T / rows);      /* from the blank, ahead of the scan */
  const a0 = p.takeTear(), ahead = a0.hi - a0.lo + 1;
  check('scan_frame_in_blank_shows_whole', whole === 1, `${whole} passes`);
  check('scan_frame_across_the_scan_is_torn', torn === 2, `${torn} passes`);
  check('scan_frame_ahead_of_the_scan_shows_whole', ahead === 1, `${ahead} passes`);
  check('scan_rates', Math.abs(1e9 / T - 60) < 1e-9 && Math.abs(1e9 / new EmuPanel('ili9341').scanNs - 70) < 1e-9,
        `${1e9 / T} Hz`);
}

process.exit(failed ? 1 : 0);
