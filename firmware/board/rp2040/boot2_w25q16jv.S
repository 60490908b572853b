/* SPDX-License-Identifier: MIT */
/* boot2_w25q16jv.S — second-stage boot for the Raspberry Pi Pico's flash, a
 * Winbond W25Q16JV (2 MB): quad I/O fast read (EBh) in continuous-read mode
 * at clk_sys/2 (RP2040_BOOT2=w25q16jv, the default).
 *
 * The boot ROM copies these 256 bytes from flash offset 0 to SRAM at
 * 0x20041f00, checks the CRC32 in the last 4 bytes (tools/uf2/boot2crc.py)
 * and runs them. This code
 * 1. sets the QSPI pads: SCLK 8 mA with fast slew, SD0..SD3 without the
 *    Schmitt trigger (the pads' settings for a 66 MHz flash clock);
 * 2. sets the Quad Enable bit (QE, status register 2 bit 1) when it is clear:
 *    write enable (06h), write status register 2 (31h), then poll the BUSY
 *    bit of status register 1 (05h) — non-volatile, so only the first boot
 *    of a new chip writes it;
 * 3. sends one EBh read with the mode bits A0h, which leaves the flash in
 *    continuous-read mode: from then on a read is only address and mode on
 *    four lines (8 clocks), 4 dummy clocks and the data (16 clocks for the
 *    8 bytes of a cache line), no instruction;
 * 4. programs the XIP SSI for exactly that and enters the application
 *    through its vector table at 0x10000100.
 * At 133 MHz clk_sys the flash clock is 66.5 MHz (the W25Q16JV's EBh is
 * specified to 133 MHz); RX_SAMPLE_DLY = 1 samples the data half a system
 * clock later, as the round trip at that clock needs. A cache miss costs
 * about 60 cycles instead of 03h's 388.
 */
    .syntax unified
    .cpu cortex-m0plus
    .thumb
    .include "boot2_common.inc"

    .equ SR_BUSY,           1
    .equ SR_TFE,            4

    .equ PADS_QSPI_BASE,    0x40020000
    .equ PADS_SCLK,         0x04
    .equ PADS_SD0,          0x08
    .equ PAD_SCHMITT,       (1 << 1)
    .equ PAD_SCLK_FAST_8MA, (2 << 4) | 1         /* DRIVE = 8 mA, SLEWFAST */

    .equ FLASH_DIV,         2
    .equ CMD_WRITE_ENABLE,  0x06
    .equ CMD_READ_STATUS,   0x05
    .equ CMD_READ_STATUS2,  0x35
    .equ CMD_WRITE_STATUS2, 0x31
    .equ CMD_READ_QUAD_IO,  0xeb
    .equ SR2_QE,            0x02
    .equ MODE_CONTINUOUS,   0xa0

    /* direct mode: standard SPI, 8-bit frames, transmit and receive */
    .equ CTRLR0_DIRECT,     (7 << 16)
    /* XIP: quad frames (SPI_FRF = 2), 32-bit frames, EEPROM read (TMOD = 3) */
    .equ CTRLR0_QUAD,       (2 << 21) | (31 << 16) | (3 << 8)
    /* the first EBh: 8-bit instruction on one line, address (24 bits) and mode
     * (8 bits) on four (TRANS_TYPE = 1, ADDR_L = 8 nibbles), 4 wait cycles */
    .equ SPI_CTRLR0_ENTER,  (4 << 11) | (2 << 8) | (8 << 2) | 1
    /* then: no instruction, address and mode on four lines (TRANS_TYPE = 2),
     * XIP_CMD = the mode bits sent after the address */
    .equ SPI_CTRLR0_XIP,    (MODE_CONTINUOUS << 24) | (4 << 11) | (0 << 8) | (8 << 2) | 2

    .section .text.boot2, "ax"
    .global boot2_entry
    .type boot2_entry, %function
    .thumb_func
boot2_entry:
    ldr  r3, =PADS_QSPI_BASE
    movs r0, #PAD_SCLK_FAST_8MA
    str  r0, [r3, #PADS_SCLK]
    movs r2, #PAD_SCHMITT
    movs r1, #PADS_SD0
1:  ldr  r0, [r3, r1]
    bics r0, r2
    str  r0, [r3, r1]
    adds r1, #4
    cmp  r1, #PADS_SD0 + 16
    bne  1b

    ldr  r3, =SSI_BASE
    movs r0, #0
    str  r0, [r3, #SSI_SSIENR]      /* registers below are writable only while disabled */
    movs r0, #FLASH_DIV
    str  r0, [r3, #SSI_BAUDR]
    movs r0, #1
    movs r1, #SSI_RX_SAMPLE_DLY
    str  r0, [r3, r1]
    ldr  r0, =CTRLR0_DIRECT
    str  r0, [r3, #SSI_CTRLR0]
    movs r0, #1
    str  r0, [r3, #SSI_SSIENR]

    movs r0, #CMD_READ_STATUS2
    bl   read_status
    movs r2, #SR2_QE
    tst  r0, r2
    bne  quad_enabled
    movs r0, #CMD_WRITE_ENABLE
    str  r0, [r3, #SSI_DR0]
    bl   wait_ssi
    ldr  r0, [r3, #SSI_DR0]         /* the byte clocked in meanwhile */
    movs r0, #CMD_WRITE_STATUS2
    str  r0, [r3, #SSI_DR0]
    str  r2, [r3, #SSI_DR0]
    bl   wait_ssi
    ldr  r0, [r3, #SSI_DR0]
    ldr  r0, [r3, #SSI_DR0]
2:  movs r0, #CMD_READ_STATUS
    bl   read_status
    movs r2, #SR_BUSY
    tst  r0, r2
    bne  2b

quad_enabled:
    movs r0, #0
    str  r0, [r3, #SSI_SSIENR]
    ldr  r0, =CTRLR0_QUAD
    str  r0, [r3, #SSI_CTRLR0]
    movs r0, #0
    str  r0, [r3, #SSI_CTRLR1]      /* NDF = 0: one frame per read */
    ldr  r0, =SPI_CTRLR0_ENTER
    movs r1, #SSI_SPI_CTRLR0
    str  r0, [r3, r1]
    movs r0, #1
    str  r0, [r3, #SSI_SSIENR]
    movs r0, #CMD_READ_QUAD_IO
    str  r0, [r3, #SSI_DR0]
    movs r0, #MODE_CONTINUOUS       /* address 0, then the mode bits */
    str  r0, [r3, #SSI_DR0]
    bl   wait_ssi

    movs r0, #0
    str  r0, [r3, #SSI_SSIENR]
    ldr  r0, =SPI_CTRLR0_XIP
    str  r0, [r3, r1]
    movs r0, #1
    str  r0, [r3, #SSI_SSIENR]

    boot2_enter_app

/* until the transmit FIFO is empty and the SSI idle (r3 = SSI_BASE) */
wait_ssi:
    push {r0, r1}
3:  ldr  r1, [r3, #SSI_SR]
    movs r0, #SR_TFE
    tst  r1, r0
    beq  3b
    movs r0, #SR_BUSY
    tst  r1, r0
    bne  3b
    pop  {r0, r1}
    bx   lr

/* the status register command r0 answers, in r0 (two bytes clocked: the
 * command, then one that carries the status back) */
read_status:
    push {lr}
    str  r0, [r3, #SSI_DR0]
    str  r0, [r3, #SSI_DR0]
    bl   wait_ssi
    ldr  r0, [r3, #SSI_DR0]
    ldr  r0, [r3, #SSI_DR0]
    pop  {pc}
    .ltorg
