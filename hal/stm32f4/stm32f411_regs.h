/* SPDX-License-Identifier: MIT */
/* stm32f411_regs.h — the STM32F411 registers this firmware touches
 * (addresses and bits from the reference manual, RM0383). */
#ifndef STM32F411_REGS_H
#define STM32F411_REGS_H

#include <stdint.h>

#define REG(a) (*(volatile uint32_t *)(uintptr_t)(a))

/* RCC */
#define RCC_BASE        0x40023800u
#define RCC_CR          (RCC_BASE + 0x00u)
#define RCC_CR_HSEON    (1u << 16)
#define RCC_CR_HSERDY   (1u << 17)
#define RCC_CR_PLLON    (1u << 24)
#define RCC_CR_PLLRDY   (1u << 25)
#define RCC_PLLCFGR     (RCC_BASE + 0x04u)
#define RCC_PLLCFGR_SRC_HSE (1u << 22)
#define RCC_CFGR        (RCC_BASE + 0x08u)
#define RCC_CFGR_SW_PLL 2u
#define RCC_CFGR_SWS_MASK (3u << 2)
#define RCC_CFGR_SWS_PLL (2u << 2)
#define RCC_CFGR_PPRE1_DIV2 (4u << 10)
#define RCC_AHB1ENR     (RCC_BASE + 0x30u)
#define RCC_AHB1ENR_GPIOA (1u << 0)
#define RCC_AHB1ENR_GPIOB (1u << 1)
#define RCC_AHB1ENR_GPIOC (1u << 2)
#define RCC_AHB1ENR_DMA2 (1u << 22)
#define RCC_APB1ENR     (RCC_BASE + 0x40u)
#define RCC_APB1ENR_TIM2 (1u << 0)
#define RCC_APB1ENR_PWR (1u << 28)
#define RCC_APB2ENR     (RCC_BASE + 0x44u)
#define RCC_APB2ENR_USART1 (1u << 4)
#define RCC_APB2ENR_SPI1 (1u << 12)

/* PWR: regulator scale 1 (VOS = 11) allows 100 MHz */
#define PWR_CR          0x40007000u
#define PWR_CR_VOS_SCALE1 (3u << 14)
#define PWR_CR_VOS_MASK (3u << 14)
#define PWR_CSR         0x40007004u
#define PWR_CSR_VOSRDY  (1u << 14)    /* valid once the PLL runs */

/* Flash interface */
#define FLASH_ACR       0x40023C00u
#define FLASH_ACR_PRFTEN (1u << 8)
#define FLASH_ACR_ICEN  (1u << 9)
#define FLASH_ACR_DCEN  (1u << 10)

/* GPIO ports A..C; a pin is port * 16 + index (STM32_PA(n), STM32_PB(n)) */
#define GPIO_BASE(port) (0x40020000u + 0x400u * (uint32_t)(port))
#define GPIO_MODER(p)   (GPIO_BASE(p) + 0x00u)
#define GPIO_OTYPER(p)  (GPIO_BASE(p) + 0x04u)
#define GPIO_OSPEEDR(p) (GPIO_BASE(p) + 0x08u)
#define GPIO_PUPDR(p)   (GPIO_BASE(p) + 0x0Cu)
#define GPIO_BSRR(p)    (GPIO_BASE(p) + 0x18u)
#define GPIO_AFR(p, n)  (GPIO_BASE(p) + 0x20u + 4u * ((uint32_t)(n) >> 3))
#define GPIO_MODE_OUT   1u
#define GPIO_MODE_AF    2u
#define GPIO_SPEED_VHIGH 3u

/* Pins numbered port * 16 + index (PA5 = 5, PB0 = 16). */
static inline void stm32_pin_mode(unsigned pin, uint32_t mode)
{
    unsigned port = pin >> 4, i = pin & 15u;
    REG(GPIO_OSPEEDR(port)) |= GPIO_SPEED_VHIGH << (2u * i);
    REG(GPIO_OTYPER(port)) &= ~(1u << i);
    REG(GPIO_MODER(port)) = (REG(GPIO_MODER(port)) & ~(3u << (2u * i))) | (mode << (2u * i));
}

static inline void stm32_pin_set(unsigned pin, int level)
{
    unsigned i = pin & 15u;
    REG(GPIO_BSRR(pin >> 4)) = level ? (1u << i) : (1u << (i + 16u));
}

/* A push-pull output at level (set first: no glitch when the driver turns on). */
static inline void stm32_pin_output(unsigned pin, int level)
{
    stm32_pin_set(pin, level);
    stm32_pin_mode(pin, GPIO_MODE_OUT);
}

/* Alternate function af. */
static inline void stm32_pin_af(unsigned pin, unsigned af)
{
    unsigned port = pin >> 4, i = pin & 15u, sh = 4u * (i & 7u);
    REG(GPIO_AFR(port, i)) = (REG(GPIO_AFR(port, i)) & ~(0xFu << sh)) | ((uint32_t)af << sh);
    stm32_pin_mode(pin, GPIO_MODE_AF);
}

/* SPI1 (APB2) */
#define SPI1_BASE       0x40013000u
#define SPI_CR1         (SPI1_BASE + 0x00u)
#define SPI_CR1_CPHA    (1u << 0)
#define SPI_CR1_CPOL    (1u << 1)
#define SPI_CR1_MSTR    (1u << 2)
#define SPI_CR1_BR(x)   ((uint32_t)(x) << 3)   /* f_PCLK2 / 2^(x+1) */
#define SPI_CR1_SPE     (1u << 6)
#define SPI_CR1_SSI     (1u << 8)
#define SPI_CR1_SSM     (1u << 9)
#define SPI_CR1_DFF     (1u << 11)             /* 16-bit frames */
#define SPI_CR2         (SPI1_BASE + 0x04u)
#define SPI_CR2_TXDMAEN (1u << 1)
#define SPI_SR          (SPI1_BASE + 0x08u)
#define SPI_SR_RXNE     (1u << 0)
#define SPI_SR_TXE      (1u << 1)
#define SPI_SR_BSY      (1u << 7)
#define SPI_DR          (SPI1_BASE + 0x0Cu)

/* DMA2: SPI1_TX is stream 3, channel 3 */
#define DMA2_BASE       0x40026400u
#define DMA_LISR        (DMA2_BASE + 0x00u)
#define DMA_LIFCR       (DMA2_BASE + 0x08u)
#define DMA_S3_FLAGS    (0x3Du << 22)          /* FEIF3, DMEIF3, TEIF3, HTIF3, TCIF3 */
#define DMA_S3_TCIF     (1u << 27)
#define DMA_S3_TEIF     (1u << 25)
#define DMA_SCR(s)      (DMA2_BASE + 0x10u + 0x18u * (s))
#define DMA_SNDTR(s)    (DMA2_BASE + 0x14u + 0x18u * (s))
#define DMA_SPAR(s)     (DMA2_BASE + 0x18u + 0x18u * (s))
#define DMA_SM0AR(s)    (DMA2_BASE + 0x1Cu + 0x18u * (s))
#define DMA_SFCR(s)     (DMA2_BASE + 0x24u + 0x18u * (s))
#define DMA_SCR_EN      (1u << 0)
#define DMA_SCR_DIR_M2P (1u << 6)
#define DMA_SCR_MINC    (1u << 10)
#define DMA_SCR_PSIZE_16 (1u << 11)
#define DMA_SCR_MSIZE_16 (1u << 13)
#define DMA_SCR_PL_HIGH (2u << 16)
#define DMA_SCR_CHSEL(c) ((uint32_t)(c) << 25)

/* USART1 (APB2), TX on PA9 */
#define USART1_BASE     0x40011000u
#define USART_SR        (USART1_BASE + 0x00u)
#define USART_SR_TXE    (1u << 7)
#define USART_SR_TC     (1u << 6)
#define USART_DR        (USART1_BASE + 0x04u)
#define USART_BRR       (USART1_BASE + 0x08u)
#define USART_CR1       (USART1_BASE + 0x0Cu)
#define USART_CR1_TE    (1u << 3)
#define USART_CR1_UE    (1u << 13)

/* TIM2 (APB1, 32-bit counter) */
#define TIM2_BASE       0x40000000u
#define TIM_CR1         (TIM2_BASE + 0x00u)
#define TIM_EGR         (TIM2_BASE + 0x14u)
#define TIM_CNT         (TIM2_BASE + 0x24u)
#define TIM_PSC         (TIM2_BASE + 0x28u)
#define TIM_ARR         (TIM2_BASE + 0x2Cu)

/* System control block: coprocessor access (CP10/CP11 = the FPU) */
#define SCB_CPACR       0xE000ED88u
#define SCB_AIRCR       0xE000ED0Cu
#define SCB_AIRCR_SYSRESETREQ (0x05FAu << 16 | 1u << 2)   /* VECTKEY and the request */
#define SCB_VTOR        0xE000ED08u

#endif
