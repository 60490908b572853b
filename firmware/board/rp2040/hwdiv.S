/* SPDX-License-Identifier: MIT */
/* hwdiv.S — 32-bit division through the SIO hardware divider.
 *
 * The Cortex-M0+ has no divide instruction; GCC calls these helpers for
 * every / and % on 32-bit integers. The SIO divider (one per core) gives
 * quotient and remainder in 8 cycles, against ~40-100 for libgcc's shift-
 * and-subtract loop. The divider's state is not saved: no interrupt handler
 * in this firmware divides (none is enabled). 64-bit division (fixed-point
 * num_div) stays in libgcc.
 * Division by zero returns what the hardware gives (C leaves it undefined). */
    .syntax unified
    .cpu cortex-m0plus
    .thumb

    .equ SIO_BASE,     0xd0000000
    .equ DIV_UDIVIDEND, 0x60
    .equ DIV_UDIVISOR,  0x64
    .equ DIV_SDIVIDEND, 0x68
    .equ DIV_SDIVISOR,  0x6c
    .equ DIV_QUOTIENT,  0x70
    .equ DIV_REMAINDER, 0x74
    .equ DIV_CSR,       0x78

    .section .text.hwdiv, "ax"

/* r0 = r0 / r1, r1 = r0 % r1 (unsigned) */
    .global __aeabi_uidiv
    .global __aeabi_uidivmod
    .type __aeabi_uidiv, %function
    .type __aeabi_uidivmod, %function
    .thumb_func
__aeabi_uidiv:
    .thumb_func
__aeabi_uidivmod:
    ldr  r2, =SIO_BASE
    str  r0, [r2, #DIV_UDIVIDEND]
    str  r1, [r2, #DIV_UDIVISOR]
    b    wait_result

/* r0 = r0 / r1, r1 = r0 % r1 (signed, truncating) */
    .global __aeabi_idiv
    .global __aeabi_idivmod
    .type __aeabi_idiv, %function
    .type __aeabi_idivmod, %function
    .thumb_func
__aeabi_idiv:
    .thumb_func
__aeabi_idivmod:
    ldr  r2, =SIO_BASE
    str  r0, [r2, #DIV_SDIVIDEND]
    str  r1, [r2, #DIV_SDIVISOR]
wait_result:
    ldr  r3, [r2, #DIV_CSR]
    lsrs r3, r3, #1                 /* READY (bit 0) into carry */
    bcc  wait_result
    ldr  r1, [r2, #DIV_REMAINDER]   /* remainder first: reading the quotient ends the operation */
    ldr  r0, [r2, #DIV_QUOTIENT]
    bx   lr
    .ltorg
