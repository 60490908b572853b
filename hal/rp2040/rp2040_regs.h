/* SPDX-License-Identifier: MIT */
/* rp2040_regs.h — the RP2040 registers this firmware touches (addresses and
 * bit positions from the RP2040 datasheet). Only what is used is listed.
 *
 * Every APB/AHB peripheral register has atomic aliases: +0x1000 XOR,
 * +0x2000 SET bits, +0x3000 CLEAR bits (not for SIO). */
#ifndef RP2040_REGS_H
#define RP2040_REGS_H

#include <stdint.h>

#define REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))
#define REG_XOR(addr) REG((addr) + 0x1000u)
#define REG_SET(addr) REG((addr) + 0x2000u)
#define REG_CLR(addr) REG((addr) + 0x3000u)

/* ---- resets ---------------------------------------------------------- */
#define RESETS_BASE        0x4000c000u
#define RESETS_RESET       (RESETS_BASE + 0x0)
#define RESETS_DONE        (RESETS_BASE + 0x8)
#define RESET_DMA          (1u << 2)
#define RESET_IO_BANK0     (1u << 5)
#define RESET_PADS_BANK0   (1u << 8)
#define RESET_PLL_SYS      (1u << 12)
#define RESET_PLL_USB      (1u << 13)
#define RESET_SPI0         (1u << 16)
#define RESET_TIMER        (1u << 21)
#define RESET_UART0        (1u << 22)

#define RESET_IO_RESETS    (RESET_DMA | RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_SPI0 | RESET_TIMER | RESET_UART0)

/* ---- power-on state machine ------------------------------------------------ */
#define PSM_BASE           0x40010000u
#define PSM_FRCE_OFF       (PSM_BASE + 0x4)
#define PSM_PROC1          (1u << 16)

/* ---- clocks ---------------------------------------------------------- */
#define CLOCKS_BASE        0x40008000u
#define CLK_REF_CTRL       (CLOCKS_BASE + 0x30)
#define CLK_REF_DIV        (CLOCKS_BASE + 0x34)
#define CLK_REF_SELECTED   (CLOCKS_BASE + 0x38)
#define CLK_SYS_CTRL       (CLOCKS_BASE + 0x3c)
#define CLK_SYS_DIV        (CLOCKS_BASE + 0x40)
#define CLK_SYS_SELECTED   (CLOCKS_BASE + 0x44)
#define CLK_PERI_CTRL      (CLOCKS_BASE + 0x48)
#define CLK_SYS_RESUS_CTRL (CLOCKS_BASE + 0x78)
#define CLK_REF_SRC_XOSC   0x2u
#define CLK_SYS_SRC_AUX    0x1u          /* AUXSRC field selects; 0 = clk_ref */
#define CLK_SYS_AUX_PLL_SYS (0x0u << 5)
#define CLK_PERI_ENABLE    (1u << 11)
#define CLK_PERI_AUX_PLL_USB (0x2u << 5)

#define XOSC_BASE          0x40024000u
#define XOSC_CTRL          (XOSC_BASE + 0x00)
#define XOSC_STATUS        (XOSC_BASE + 0x04)
#define XOSC_STARTUP       (XOSC_BASE + 0x0c)
#define XOSC_RANGE_1_15MHZ 0xaa0u
#define XOSC_ENABLE        (0xfabu << 12)
#define XOSC_STABLE        (1u << 31)

#define PLL_SYS_BASE       0x40028000u
#define PLL_USB_BASE       0x4002c000u
#define PLL_CS(b)          ((b) + 0x0)
#define PLL_PWR(b)         ((b) + 0x4)
#define PLL_FBDIV(b)       ((b) + 0x8)
#define PLL_PRIM(b)        ((b) + 0xc)
#define PLL_LOCK           (1u << 31)
#define PLL_PWR_PD         (1u << 0)
#define PLL_PWR_POSTDIVPD  (1u << 3)
#define PLL_PWR_VCOPD      (1u << 5)

/* ---- the core's voltage regulator and the XIP SSI (flash clock) ------------ */
#define VREG_BASE          0x40064000u
#define VREG_CTRL          (VREG_BASE + 0x0)   /* EN bit 0, HIZ bit 1, VSEL 7:4, ROK bit 12 */
#define VREG_EN            (1u << 0)
#define VREG_VSEL(v)       ((uint32_t)(v) << 4)
#define VREG_ROK           (1u << 12)
#define XIP_SSI_BASE       0x18000000u
#define XIP_SSI_SSIENR     (XIP_SSI_BASE + 0x08)
#define XIP_SSI_BAUDR      (XIP_SSI_BASE + 0x14)
#define XIP_SSI_SR         (XIP_SSI_BASE + 0x28)
#define XIP_SSI_SR_BUSY    (1u << 0)

#define WATCHDOG_BASE      0x40058000u
#define WATCHDOG_TICK      (WATCHDOG_BASE + 0x2c)
#define WATCHDOG_TICK_EN   (1u << 9)

/* ---- GPIO ------------------------------------------------------------ */
#define IO_BANK0_BASE      0x40014000u
#define GPIO_CTRL(n)       (IO_BANK0_BASE + 0x04u + 8u * (n))
#define GPIO_FUNC_SPI      1u
#define GPIO_FUNC_UART     2u
#define GPIO_FUNC_SIO      5u
#define PADS_BANK0_BASE    0x4001c000u
#define PADS_GPIO(n)       (PADS_BANK0_BASE + 0x04u + 4u * (n))
#define PADS_DRIVE_12MA    (3u << 4)
#define PADS_SLEWFAST      (1u << 0)
#define PADS_IE            (1u << 6)
#define PADS_PDE           (1u << 2)

/* ---- SIO (single-cycle I/O, per core) ---------------------------------- */
#define SIO_BASE           0xd0000000u
#define SIO_CPUID          (SIO_BASE + 0x000)
#define SIO_GPIO_IN        (SIO_BASE + 0x004)
#define SIO_GPIO_OUT_SET   (SIO_BASE + 0x014)
#define SIO_GPIO_OUT_CLR   (SIO_BASE + 0x018)
#define SIO_GPIO_OE_SET    (SIO_BASE + 0x024)
#define SIO_SPINLOCK(n)    (SIO_BASE + 0x100 + 4u * (n))
#define SIO_FIFO_ST        (SIO_BASE + 0x050)
#define SIO_FIFO_WR        (SIO_BASE + 0x054)
#define SIO_FIFO_RD        (SIO_BASE + 0x058)
#define SIO_FIFO_VLD       (1u << 0)
#define SIO_FIFO_RDY       (1u << 1)
#define SIO_DIV_UDIVIDEND  (SIO_BASE + 0x060)
#define SIO_DIV_UDIVISOR   (SIO_BASE + 0x064)
#define SIO_DIV_SDIVIDEND  (SIO_BASE + 0x068)
#define SIO_DIV_SDIVISOR   (SIO_BASE + 0x06c)
#define SIO_DIV_QUOTIENT   (SIO_BASE + 0x070)
#define SIO_DIV_REMAINDER  (SIO_BASE + 0x074)
#define SIO_DIV_CSR        (SIO_BASE + 0x078)

/* ---- SPI0 (ARM PrimeCell PL022) ----------------------------------------- */
#define SPI0_BASE          0x4003c000u
#define SSPCR0             (SPI0_BASE + 0x000)
#define SSPCR1             (SPI0_BASE + 0x004)
#define SSPDR              (SPI0_BASE + 0x008)
#define SSPSR              (SPI0_BASE + 0x00c)
#define SSPCPSR            (SPI0_BASE + 0x010)
#define SSPDMACR           (SPI0_BASE + 0x024)
#define SSPCR1_SSE         (1u << 1)
#define SSPSR_TNF          (1u << 1)
#define SSPSR_RNE          (1u << 2)
#define SSPSR_BSY          (1u << 4)
#define SSPDMACR_TXDMAE    (1u << 1)

/* ---- UART0 (ARM PrimeCell PL011) ---------------------------------------- */
#define UART0_BASE         0x40034000u
#define UARTDR             (UART0_BASE + 0x00)
#define UARTFR             (UART0_BASE + 0x18)
#define UARTIBRD           (UART0_BASE + 0x24)
#define UARTFBRD           (UART0_BASE + 0x28)
#define UARTLCR_H          (UART0_BASE + 0x2c)
#define UARTCR             (UART0_BASE + 0x30)
#define UARTIFLS           (UART0_BASE + 0x34)
#define UARTIMSC           (UART0_BASE + 0x38)
#define UARTICR            (UART0_BASE + 0x44)
#define UARTFR_TXFF        (1u << 5)
#define UARTFR_BUSY        (1u << 3)
#define UART_TXIM          (1u << 5)     /* UARTIMSC/UARTICR: transmit interrupt */
#define UART0_IRQ          20u

/* ---- DMA -------------------------------------------------------------- */
#define DMA_BASE           0x50000000u
#define DMA_READ_ADDR(c)   (DMA_BASE + 0x40u * (c) + 0x0)
#define DMA_WRITE_ADDR(c)  (DMA_BASE + 0x40u * (c) + 0x4)
#define DMA_TRANS_COUNT(c) (DMA_BASE + 0x40u * (c) + 0x8)
#define DMA_CTRL_TRIG(c)   (DMA_BASE + 0x40u * (c) + 0xc)
#define DMA_CTRL_EN        (1u << 0)
#define DMA_SIZE_BYTE      (0u << 2)
#define DMA_SIZE_HALF      (1u << 2)
#define DMA_INCR_READ      (1u << 4)
#define DMA_CHAIN_TO(c)    ((uint32_t)(c) << 11)
#define DMA_TREQ(t)        ((uint32_t)(t) << 15)
#define DMA_BUSY           (1u << 24)
#define DREQ_SPI0_TX       16u

/* ---- timer ------------------------------------------------------------ */
#define TIMER_BASE         0x40054000u
#define TIMER_RAWH         (TIMER_BASE + 0x24)
#define TIMER_RAWL         (TIMER_BASE + 0x28)

/* ---- Cortex-M0+ private peripherals ----------------------------------- */
#define PPB_VTOR           0xe000ed08u
#define NVIC_ISER          0xe000e100u
#define NVIC_ICER          0xe000e180u
#define NVIC_ICPR          0xe000e280u

#endif
