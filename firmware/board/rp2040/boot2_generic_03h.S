/* SPDX-License-Identifier: MIT */
/* boot2_generic_03h.S — second-stage boot for any QSPI flash that answers the
 * plain 03h READ command (RP2040_BOOT2=generic_03h; the Pico's own flash
 * gets the faster boot2_w25q16jv.S by default).
 *
 * The boot ROM copies these 256 bytes from flash offset 0 to SRAM at
 * 0x20041f00, checks the CRC32 stored in the last 4 bytes (computed at build
 * time by tools/uf2/boot2crc.py) and runs the code. This code sets the XIP
 * SSI to translate bus reads into 03h commands (serial, 24-bit address,
 * 32-bit frames), then enters the application through its vector table at
 * 0x10000100.
 *
 * Why 03h at clk_sys/4: it needs no flash status-register write (quad mode
 * would), and 03h is specified up to 50 MHz; at 133 MHz clk_sys the flash
 * clock is 33 MHz. A cache miss then costs about 388 cycles (96 flash
 * clocks for 8 bytes); the hot code runs from SRAM (RP2040_RAM_TEXT).
 */
    .syntax unified
    .cpu cortex-m0plus
    .thumb
    .include "boot2_common.inc"

    /* CTRLR0: DFS_32 = 31 (32-bit frames, bits 20:16), TMOD = 3 (EEPROM read, bits 9:8) */
    .equ CTRLR0_XIP,      (31 << 16) | (3 << 8)
    /* SPI_CTRLR0: XIP_CMD = 0x03 (bits 31:24), INST_L = 2 (8-bit instruction, bits 9:8),
     * ADDR_L = 6 (24-bit address in 4-bit units, bits 5:2), TRANS_TYPE = 0 (all serial) */
    .equ SPI_CTRLR0_XIP,  (0x03 << 24) | (2 << 8) | (6 << 2)
    .equ FLASH_DIV,       4

    .section .text.boot2, "ax"
    .global boot2_entry
    .type boot2_entry, %function
    .thumb_func
boot2_entry:
    ldr  r3, =SSI_BASE
    movs r0, #0
    str  r0, [r3, #SSI_SSIENR]      /* registers below are writable only while disabled */
    movs r1, #FLASH_DIV
    str  r1, [r3, #SSI_BAUDR]
    ldr  r1, =CTRLR0_XIP
    str  r1, [r3, #SSI_CTRLR0]
    str  r0, [r3, #SSI_CTRLR1]      /* NDF = 0: one frame per bus read */
    ldr  r1, =SPI_CTRLR0_XIP
    movs r2, #SSI_SPI_CTRLR0
    str  r1, [r3, r2]
    movs r0, #1
    str  r0, [r3, #SSI_SSIENR]

    boot2_enter_app
    .ltorg
