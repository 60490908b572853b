// SPDX-License-Identifier: MIT
'use strict';
/* uart.js — the transmit side of a PL011 UART (UART0 of the RP2040) for the
 * rp2040js emulator, which reports its transmit FIFO always empty, so a
 * firmware that writes more than the line carries never waits.
 *
 * - The TX FIFO holds 32 characters (1 with the FIFOs off, UARTLCR_H.FEN
 *   clear); a character leaves it for the shift register, which sends it in
 *   (1 start + data bits + parity + stop bits) * 16 * (IBRD + FBRD / 64)
 *   periods of clk_peri. A write to a full FIFO is lost (as on the chip) and
 *   counted (lost).
 * - UARTFR: TXFF (bit 5) the FIFO full, TXFE (bit 7) empty, BUSY (bit 3) a
 *   character in the FIFO or the shift register; the receive flags are the
 *   package's.
 * - The transmit interrupt (UARTRIS.TXRIS, bit 5): set when the FIFO's level
 *   drops to the trigger level of UARTIFLS.TXIFLSEL (1/8, 1/4, 1/2, 3/4, 7/8
 *   of 32; with the FIFOs off, when the holding register empties), cleared by
 *   writing the FIFO above that level or through UARTICR; masked by UARTIMSC,
 *   raised on the UART's interrupt line.
 * - Waiting: a run of reads of UARTFR that find TXFF set, each within 2 us
 *   of the one before (a loop polling the flag), is a wait for room, from
 *   its first read to the read that finds room (or to its last read): the
 *   time the firmware spends waiting (stallNs, ns of emulated time;
 *   stallAt(ns): the total of the waits that ended by then). A single look
 *   at the flag that finds the FIFO full and goes on is no wait.
 * onByte(b) is called when the firmware writes a character (the firmware's
 * time: the lines the driver parses carry the moment they were written),
 * onWire(b) when it has left the shift register; reset() (the block reset
 * through RESETS, which the driver calls) empties the FIFO, then onReset(). */

const UARTDR = 0x00, UARTFR = 0x18, UARTIFLS = 0x34, UARTICR = 0x44;
const FR_BUSY = 1 << 3, FR_TXFF = 1 << 5, FR_TXFE = 1 << 7;
const TXINT = 1 << 5;
const DEPTH = 32;
/* reads of UARTFR closer than this are one loop waiting on TXFF */
const WAIT_GAP_NS = 2000;

class UartTx {
  /* uart: the package's RPUART; now(): the time of the access being made
   * (the local time of the core that makes it), ns */
  constructor(mcu, uart, now) {
    this.mcu = mcu;
    this.uart = uart;
    this.now = now || (() => mcu.clock.nanos);
    this.fifo = [];
    this.shifting = false;
    this.txris = false;
    this.ifls = 0x12;            /* reset value: both trigger levels at 1/2 */
    this.lost = 0;
    this.stallNs = 0;
    this.runStart = null;        /* the reads of a wait: its first, its latest */
    this.runLast = null;
    this.stallLog = [];          /* [end of a wait, stallNs after it] */
    this.written = 0;
    this.onByte = null;
    this.onWire = null;
    this.alarm = mcu.clock.createAlarm(() => this.shifted());
    const readBase = uart.readUint32.bind(uart), writeBase = uart.writeUint32.bind(uart);
    uart.readUint32 = (off) => this.read(off, readBase);
    uart.writeUint32 = (off, v) => this.write(off, v, writeBase);
    /* the package raises its transmit interrupt whenever it looks at its
     * interrupts: the model's state instead */
    uart.checkInterrupts = () => this.updateIrq();
  }

  get depth() { return this.uart.lineCtrlRegister & (1 << 4) ? DEPTH : 1; }

  /* the level at or below which the transmit interrupt is raised */
  get trigger() {
    if (this.depth === 1) return 0;
    return [4, 8, 16, 24, 28][Math.min(this.ifls & 7, 4)];
  }

  /* ns a character takes on the line */
  get charNs() {
    const u = this.uart, lcr = u.lineCtrlRegister;
    const bits = 1 + u.wordLength + (lcr & (1 << 1) ? 1 : 0) + (lcr & (1 << 3) ? 2 : 1);
    const div = u.baudDivider || 1;
    return bits * 16 * div * 1e9 / (this.mcu.clkPeri || 125e6);
  }

  endWait(at) {
    if (at > this.runStart) {
      this.stallNs += at - this.runStart;
      this.stallLog.push([at, this.stallNs]);
    }
    this.runStart = this.runLast = null;
  }

  /* the block reset (RESETS): what the FIFO and the shift register held is
   * lost */
  reset() {
    this.fifo = [];
    this.shifting = false;
    this.alarm.cancel();
    this.txris = false;
    this.ifls = 0x12;
    if (this.onReset) this.onReset();
  }

  /* the waits ended at or before ns, their total (ns) */
  stallAt(ns) {
    const q = this.stallLog;
    let lo = 0, hi = q.length;
    while (lo < hi) { const m = (lo + hi) >> 1; if (q[m][0] <= ns) lo = m + 1; else hi = m; }
    return lo ? q[lo - 1][1] : 0;
  }

  flags() {
    const n = this.fifo.length;
    return (n >= this.depth ? FR_TXFF : 0) | (n === 0 ? FR_TXFE : 0) | (n || this.shifting ? FR_BUSY : 0);
  }

  updateIrq() {
    const u = this.uart;
    u.interruptStatus = (u.interruptStatus & ~TXINT) | (this.txris ? TXINT : 0);
    this.mcu.setInterrupt(u.irq, !!(u.interruptStatus & u.interruptMask));
  }

  startNext() {
    if (this.shifting || !this.fifo.length) return;
    const before = this.fifo.length;
    this.current = this.fifo.shift();
    this.shifting = true;
    if (before > this.trigger && this.fifo.length <= this.trigger) { this.txris = true; this.updateIrq(); }
    this.alarm.schedule(Math.max(1, Math.round(this.charNs)));
  }

  shifted() {
    this.shifting = false;
    if (this.onWire) this.onWire(this.current);
    this.startNext();
  }

  read(off, base) {
    switch (off) {
      case UARTFR: {
        const f = this.flags(), now = this.now();
        if (this.runLast !== null && now - this.runLast > WAIT_GAP_NS) this.endWait(this.runLast);
        if (f & FR_TXFF) {
          if (this.runStart === null) this.runStart = now;
          this.runLast = now;
        } else if (this.runStart !== null) {
          this.endWait(now);
        }
        return (base(off) & ~(FR_TXFF | FR_TXFE | FR_BUSY)) | f;
      }
      case UARTIFLS: return this.ifls;
      default: return base(off);
    }
  }

  write(off, v, base) {
    switch (off) {
      case UARTDR: {
        if (this.runStart !== null) this.endWait(this.runLast);
        if (this.fifo.length >= this.depth) { this.lost++; return; }
        const b = v & 0xff;
        this.fifo.push(b);
        this.written++;
        if (this.onByte) this.onByte(b);
        if (this.fifo.length > this.trigger && this.txris) { this.txris = false; this.updateIrq(); }
        this.startNext();
        return;
      }
      case UARTIFLS: this.ifls = v & 0x3f; return;
      case UARTICR:
        if (v & TXINT) this.txris = false;
        base(off, v);
        return;
      default: base(off, v);
    }
  }
}

module.exports = { UartTx };
