// SPDX-License-Identifier: MIT
'use strict';
/* vreg.js — the RP2040's core voltage regulator (VREG_AND_CHIP_RESET, at
 * 0x40064000) for the rp2040js emulator, which has none (an access to it is
 * an emulator warning, and ends the run).
 *
 * Registers: VREG (0x0; EN bit 0, HIZ bit 1, VSEL bits 7:4, ROK bit 12,
 * reset 0xb1: enabled at 1.10 V), BOD (0x4, reset 0x91) and CHIP_RESET (0x8,
 * read as 0: no reset cause recorded). ROK reads 1 while the regulator is
 * enabled (the emulator has no settling time: the firmware's own wait after
 * a change is what the board needs).
 *
 * Check: clk_sys must not run above the clock the voltage is set for when it
 * changes (a firmware that raises the clock before the voltage would run a
 * board out of its rating): 133 MHz at 1.10 V, 200 MHz at 1.15 V, 250 MHz at
 * 1.20 V, 300 MHz at 1.25 V and above (firmware/board/rp2040/board.h). A
 * violation is an emulator warning, which ends the run with an error.
 */

const VREG_RESET = 0xb1, BOD_RESET = 0x91;
const VSEL_MV = (vsel) => (vsel <= 5 ? 800 : 800 + (vsel - 5) * 50);

/* the highest clk_sys (Hz) the firmware may run at with the voltage vsel */
function maxClkSys(vsel) {
  const mv = VSEL_MV(vsel);
  return mv >= 1250 ? 300e6 : mv >= 1200 ? 250e6 : mv >= 1150 ? 200e6 : mv >= 1100 ? 133e6 : 0;
}

/* Installs the model in place of rp2040js's unimplemented block. */
function installVreg(mcu) {
  let vreg = VREG_RESET, bod = BOD_RESET;
  const check = (clkSys) => {
    const vsel = (vreg >>> 4) & 15, max = maxClkSys(vsel);
    if (clkSys > max)
      mcu.logger.warn('VREG', `clk_sys ${clkSys / 1e6} MHz with the core at ${(VSEL_MV(vsel) / 1000).toFixed(2)} V ` +
        `(VSEL ${vsel}): above the ${max / 1e6} MHz that voltage is for`);
  };
  const block = {
    readUint32(off) {
      switch (off) {
        case 0x0: return (vreg & 0xf3) | (vreg & 1 ? 1 << 12 : 0);
        case 0x4: return bod;
        case 0x8: return 0;
        default: mcu.logger.warn('VREG', `read from unmodelled register 0x${off.toString(16)}`); return 0;
      }
    },
    writeUint32(off, v) {
      switch (off) {
        case 0x0: vreg = v & 0xf3; break;
        case 0x4: bod = v & 0xf1; break;
        case 0x8: break;
        default: mcu.logger.warn('VREG', `write to unmodelled register 0x${off.toString(16)}`);
      }
    },
    writeUint32Atomic(off, v, type) {
      const cur = this.readUint32(off);
      /* 0 normal, 1 XOR, 2 set, 3 clear (the APB atomic aliases) */
      this.writeUint32(off, type === 1 ? cur ^ v : type === 2 ? cur | v : type === 3 ? cur & ~v : v);
    },
  };
  mcu.peripherals[0x40064] = block;
  mcu.addClockListener((clkSys) => check(clkSys));
  return { get vsel() { return (vreg >>> 4) & 15; }, maxClkSys };
}

module.exports = { installVreg, maxClkSys };
