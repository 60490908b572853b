// SPDX-License-Identifier: MIT
'use strict';
/* dualcore.js — the RP2040's second Cortex-M0+ for the rp2040js emulator,
 * added from outside the package (rp2040js 1.4.1 models one core).
 *
 * - Core 1 is a second object of the package's core class
 *   (mcu.core.constructor) on the same bus; mcu.core is switched to the core
 *   that executes, so its private peripheral block (NVIC, VTOR) and the
 *   divider's cycle charge follow it.
 * - SIO per core: CPUID, the two 8-word inter-core FIFOs (FIFO_ST with VLD,
 *   RDY and the sticky WOF/ROE flags, FIFO_WR, FIFO_RD), a divider and two
 *   interpolators each; GPIO and spinlocks are shared, and the GPIO
 *   value/output-enable state stays where the pin model reads it.
 * - SEV sets the event register of both cores and wakes a core in WFE.
 * - Interrupt lines reach both NVICs (each core takes the ones it enables);
 *   SIO_IRQ_PROC0/1 (15, 16) are each core's own FIFO interrupt.
 * - Core 1 starts in the boot ROM's wait for the launch sequence (its side
 *   is modelled here, not executed: the emulator has no boot ROM image):
 *   every word received is echoed back (with SEV); a 0 drains core 1's
 *   receive FIFO first and restarts the sequence; 0, 0, 1, VTOR, SP, PC
 *   starts core 1 with that vector table, stack and entry point.
 * - The cores are interleaved by their local time: the core that is behind
 *   runs the next instruction, and the shared clock (timers, SPI, DMA)
 *   follows the earlier of the two, so peripheral timing stays within one
 *   instruction. `core1Speed` scales core 1's time per cycle (tests: a
 *   slower or faster core 1 must not change any frame).
 * - PSM FRCE_OFF.proc1 (bit 16) holds core 1 in reset; released, it is back
 *   in the boot ROM's wait for the launch sequence (a fresh core). The SIO
 *   FIFOs are not reset with it (another power domain).
 * - resetCore0(): core 0 alone reset, as by a debug probe or SYSRESETREQ:
 *   a fresh core 0 (registers, NVIC, VTOR), its start left to the caller;
 *   core 1 and the peripherals go on.
 * What is not modelled: SysTick is one timer (the firmware uses the
 * TIMER peripheral on both cores).
 */

const FIFO_DEPTH = 8;
const SIO_CPUID = 0x000, SIO_FIFO_ST = 0x050, SIO_FIFO_WR = 0x054, SIO_FIFO_RD = 0x058;
const FIFO_VLD = 1, FIFO_RDY = 2, FIFO_WOF = 4, FIFO_ROE = 8;
const IRQ_SIO_PROC = [15, 16];
const PSM_FRCE_OFF = 0x4, PSM_PROC1 = 1 << 16;

class DualCore {
  constructor(mcu, opts = {}) {
    this.mcu = mcu;
    const core0 = mcu.core;
    const Core = core0.constructor;
    const core1 = new Core(mcu);
    this.cores = [core0, core1];
    this.speed = [1, opts.core1Speed || 1];
    this.core1Absent = !!opts.core1Absent;   /* tests: core 1 never answers the launch */
    /* flash stalls (xip.js): charged to the core whose instruction made them */
    this.xip = opts.xip || { charging: false, take() { return 0; } };
    /* rp2040sim --profile (profile.js): each instruction's address and cycles */
    this.prof = opts.prof || null;
    this.local = [0, 0];              /* each core's time, ns */
    this.launched = [true, false];
    this.fifo = [[], []];             /* fifo[i]: words for core i */
    this.sticky = [0, 0];             /* WOF / ROE of each core */
    this.boot = { seq: 0, words: [] }; /* core 1's boot ROM state */
    this.cur = 0;
    this.launchCount = 0;
    /* each core's stack: its top (the SP it started the application with)
     * and the lowest SP an instruction ran with since (stackPeak) */
    this.spTop = [0, 0];
    this.spLow = [0, 0];

    /* SIO: one RPSIO per core for its divider and interpolators; the
     * shared one (core 0's, the package's own) keeps GPIO and spinlocks */
    const shared = mcu.sio;
    const own = [shared, new shared.constructor(mcu)];
    const dc = this;
    const isOwn = (off) => off >= 0x060 && off < 0x100;
    mcu.sio = {
      get gpioValue() { return shared.gpioValue; },
      get gpioOutputEnable() { return shared.gpioOutputEnable; },
      get qspiGpioValue() { return shared.qspiGpioValue; },
      get qspiGpioOutputEnable() { return shared.qspiGpioOutputEnable; },
      readUint32(off) {
        const c = dc.cur;
        switch (off) {
          case SIO_CPUID: return c;
          case SIO_FIFO_ST: return dc.fifoStatus(c);
          case SIO_FIFO_WR: return 0;
          case SIO_FIFO_RD: return dc.fifoRead(c);
          default: return (isOwn(off) ? own[c] : shared).readUint32(off);
        }
      },
      writeUint32(off, value) {
        const c = dc.cur;
        switch (off) {
          case SIO_CPUID: return;
          case SIO_FIFO_ST: dc.sticky[c] = 0; dc.updateFifoIrq(); return;
          case SIO_FIFO_WR: dc.fifoWrite(c, value >>> 0); return;
          case SIO_FIFO_RD: return;
          default: (isOwn(off) ? own[c] : shared).writeUint32(off, value);
        }
      },
    };

    /* PSM: FRCE_OFF.proc1 holds core 1 in reset */
    const psm = mcu.peripherals[0x40010];
    const psmWrite = psm.writeUint32.bind(psm);
    psm.writeUint32 = (off, value) => {
      psmWrite(off, value);
      if (off === PSM_FRCE_OFF) dc.holdCore1(((value >>> 0) & PSM_PROC1) !== 0);
    };
    this.held1 = false;
    this.core1Resets = 0;

    /* interrupt lines to both cores (core 1 once it runs) */
    mcu.setInterrupt = (irq, value) => {
      for (let i = 0; i < 2; i++) if (dc.launched[i]) dc.wakeBy(i, () => dc.cores[i].setInterrupt(irq, value));
    };
  }

  get core() { return this.cores[this.cur]; }

  /* core 1 into reset (hold) or out of it: back in the boot ROM */
  holdCore1(hold) {
    if (hold && !this.held1) {
      this.cores[1] = new this.cores[0].constructor(this.mcu);
      this.launched[1] = false;
      this.boot = { seq: 0, words: [] };
      this.core1Resets++;
    }
    this.held1 = hold;
  }

  /* core 0 alone reset: a fresh core 0 (the caller sets where it starts) */
  resetCore0() {
    const c = new this.cores[0].constructor(this.mcu);
    this.cores[0] = c;
    this.mcu.core = c;
    this.cur = 0;
    return c;
  }

  fifoStatus(c) {
    return (this.fifo[c].length ? FIFO_VLD : 0) | (this.fifo[1 - c].length < FIFO_DEPTH ? FIFO_RDY : 0) |
      this.sticky[c];
  }

  fifoRead(c) {
    const q = this.fifo[c];
    if (!q.length) { this.sticky[c] |= FIFO_ROE; this.updateFifoIrq(); return 0; }
    const v = q.shift();
    this.updateFifoIrq();
    return v;
  }

  fifoWrite(c, v) {
    const q = this.fifo[1 - c];
    if (q.length >= FIFO_DEPTH) { this.sticky[c] |= FIFO_WOF; this.updateFifoIrq(); return; }
    q.push(v);
    this.updateFifoIrq();
    if (c === 0 && !this.launched[1] && !this.held1 && !this.core1Absent) this.bootRom();
  }

  /* SIO_IRQ_PROCn: core n's receive FIFO holds data, or a sticky flag */
  updateFifoIrq() {
    for (let i = 0; i < 2; i++) {
      if (!this.launched[i]) continue;
      const on = this.fifo[i].length > 0 || this.sticky[i] !== 0;
      this.wakeBy(i, () => this.cores[i].setInterrupt(IRQ_SIO_PROC[i], on));
    }
  }

  /* core 1's boot ROM: consume what core 0 sent, echo it, launch on the
   * full sequence */
  bootRom() {
    const q = this.fifo[1];
    while (q.length && !this.launched[1]) {
      const w = q.shift();
      const b = this.boot;
      if (w === 0) {
        q.length = 0;                  /* drain, then restart the sequence */
        b.seq = b.seq === 1 ? 2 : 1;
        b.words = [];
      } else if (b.seq === 2 && w === 1) {
        b.seq = 3;
      } else if (b.seq >= 3) {
        b.words.push(w);
        b.seq++;
      } else {
        b.seq = 0;
      }
      if (this.fifo[0].length < FIFO_DEPTH) this.fifo[0].push(w);   /* the echo */
      this.sev();
      if (b.seq === 6) this.launch(b.words[0], b.words[1], b.words[2]);
    }
  }

  launch(vtor, sp, pc) {
    const c1 = this.cores[1];
    c1.VTOR = vtor >>> 0;
    c1.SP = sp >>> 0;
    c1.PC = (pc & ~1) >>> 0;
    c1.waiting = false;
    this.launched[1] = true;
    this.stackMark(1);
    this.local[1] = Math.max(this.local[1], this.local[0]);
    this.launchCount++;
  }

  /* SEV: the event register of both cores; a core waiting in WFE wakes (and
   * consumes the event) */
  sev() {
    for (let i = 0; i < 2; i++) {
      if (!this.launched[i]) continue;
      const c = this.cores[i];
      if (c.waiting) { c.waiting = false; this.local[i] = Math.max(this.local[i], this.local[this.cur]); }
      else c.eventRegistered = true;
    }
  }

  /* f may wake core i: its local time then catches up with the waker's */
  wakeBy(i, f) {
    const c = this.cores[i];
    const was = c.waiting;
    f();
    if (was && !c.waiting) this.local[i] = Math.max(this.local[i], this.mcu.clock.nanos);
  }

  /* core i starts its application now: its SP is the stack's top */
  stackMark(i) {
    this.spTop[i] = this.spLow[i] = this.cores[i].SP >>> 0;
  }

  /* the deepest core i's stack has been since stackMark, in bytes */
  stackPeak(i) {
    return this.spTop[i] - this.spLow[i];
  }

  /* one instruction of core c: its cycles, flash stalls included */
  step(c) {
    const sp = c.SP >>> 0;
    if (sp < this.spLow[this.cur]) this.spLow[this.cur] = sp;
    const prof = this.prof;
    this.xip.charging = true;
    if (!prof) {
      const cycles = c.executeInstruction();
      this.xip.charging = false;
      return cycles + this.xip.take();
    }
    const pc = c.PC;
    prof.executing = prof.on;
    const cycles = c.executeInstruction() + this.xip.take();
    prof.executing = false;
    this.xip.charging = false;
    prof.exec(pc, cycles);
    return cycles;
  }

  /* Runs up to n instructions (or idle periods); returns false when both
   * cores sleep with nothing to wake them. */
  run(n) {
    const { mcu } = this;
    const clock = mcu.clock;
    for (let k = 0; k < n; k++) {
      /* (either core may be replaced by a reset) */
      const c0 = this.cores[0], c1 = this.cores[1];
      if (!this.launched[1]) {
        /* core 0 alone (core 1 in the boot ROM): the package's own loop */
        this.cur = 0;
        mcu.core = c0;
        if (c0.waiting) {
          const dt = clock.nanosToNextAlarm;
          if (dt <= 0) return false;
          clock.tick(dt);
        } else {
          const cycles = this.step(c0);
          clock.tick(cycles * 1e9 / mcu.clkSys);
        }
        this.local[0] = clock.nanos;
        continue;
      }
      const r0 = !c0.waiting, r1 = !c1.waiting;
      if (!r0 && !r1) {
        const dt = clock.nanosToNextAlarm;
        if (dt <= 0) return false;
        this.cur = 0;
        mcu.core = c0;
        clock.tick(dt);
        const t = clock.nanos;
        if (this.local[0] < t) this.local[0] = t;
        if (this.local[1] < t) this.local[1] = t;
        continue;
      }
      const i = r0 && (!r1 || this.local[0] <= this.local[1]) ? 0 : 1;
      const c = this.cores[i];
      this.cur = i;
      mcu.core = c;
      const cycles = this.step(c);
      this.local[i] += cycles * 1e9 / mcu.clkSys / this.speed[i];
      /* the shared clock follows the earlier of the running cores */
      let t = Infinity;
      if (!c0.waiting) t = this.local[0];
      if (!c1.waiting && this.local[1] < t) t = this.local[1];
      if (t === Infinity) t = this.local[i];
      this.cur = 0;
      mcu.core = c0;
      if (t > clock.nanos) clock.tick(t - clock.nanos);
    }
    return true;
  }
}

module.exports = { DualCore };
