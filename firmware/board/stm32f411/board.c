/* SPDX-License-Identifier: MIT */
/* board.c — STM32F411 clocks, pins, USART1 and the microsecond timer. */
#include "board.h"
#include <stddef.h>
#include "stm32f411_regs.h"

#if STM32_HSE_MHZ < 2 || STM32_HSE_MHZ > 63
#error "STM32_HSE_MHZ must be 2..63 (PLLM = HSE MHz gives a 1 MHz PLL input)"
#endif

uint32_t board_sys_hz = STM32_HSI_HZ, board_apb2_hz = STM32_HSI_HZ;

/* Polls until (REG(addr) & mask) == want, at most STM32_CLOCK_WAIT times:
 * 1 when it came, 0 on timeout. */
static int wait_bits(uint32_t addr, uint32_t mask, uint32_t want)
{
    for (uint32_t n = STM32_CLOCK_WAIT; n; n--)
        if ((REG(addr) & mask) == want) return 1;
    return 0;
}

/* 100 MHz from the PLL; returns NULL, or the UART line that says what went
 * wrong (the clock is then as the line says). */
static const char *clocks_init(void)
{
    const char *note = NULL;
    REG(RCC_APB1ENR) |= RCC_APB1ENR_PWR;
    /* Scale 1 is needed above 84 MHz; VOS may change only with the PLL off. */
    REG(PWR_CR) = (REG(PWR_CR) & ~PWR_CR_VOS_MASK) | PWR_CR_VOS_SCALE1;
    REG(RCC_CR) |= RCC_CR_HSEON;
    /* 1 MHz PLL input, VCO 200 MHz, P = 2 → 100 MHz; Q = 4 (USB clock unused). */
    uint32_t src = RCC_PLLCFGR_SRC_HSE, m = STM32_HSE_MHZ;
    if (!wait_bits(RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY)) {
        REG(RCC_CR) &= ~RCC_CR_HSEON;
        src = 0;                                   /* HSI */
        m = STM32_HSI_HZ / 1000000u;
        note = "clock HSE not ready: PLL from HSI\r\n";
    }
    REG(RCC_PLLCFGR) = m | (200u << 6) | (0u << 16) | src | (4u << 24);
    REG(RCC_CR) |= RCC_CR_PLLON;
    if (!wait_bits(RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY))
        return "error clock: PLL lock timed out: HSI at 16 MHz\r\n";
    if (!wait_bits(PWR_CSR, PWR_CSR_VOSRDY, PWR_CSR_VOSRDY))
        return "error clock: VOSRDY timed out: HSI at 16 MHz\r\n";
    /* 3 wait states at 100 MHz and 2.7-3.6 V, set before the clock rises. */
    REG(FLASH_ACR) = 3u | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    if (!wait_bits(FLASH_ACR, 0xFu, 3u)) return "error clock: flash wait states not set: HSI at 16 MHz\r\n";
    REG(RCC_CFGR) = RCC_CFGR_PPRE1_DIV2 | RCC_CFGR_SW_PLL;   /* APB1 at most 50 MHz */
    if (!wait_bits(RCC_CFGR, RCC_CFGR_SWS_MASK, RCC_CFGR_SWS_PLL)) {
        REG(RCC_CFGR) = 0;                                      /* back to the HSI */
        return "error clock: switch to the PLL timed out: HSI at 16 MHz\r\n";
    }
    board_sys_hz = STM32_SYS_HZ;
    board_apb2_hz = STM32_APB2_HZ;
    return note;
}

void board_init(void)
{
    const char *note = clocks_init();
    REG(RCC_AHB1ENR) |= RCC_AHB1ENR_GPIOA | RCC_AHB1ENR_GPIOB | RCC_AHB1ENR_GPIOC | RCC_AHB1ENR_DMA2;
    REG(RCC_APB1ENR) |= RCC_APB1ENR_TIM2;
    REG(RCC_APB2ENR) |= RCC_APB2ENR_USART1 | RCC_APB2ENR_SPI1;
    (void)REG(RCC_APB2ENR);   /* the enables take effect before the first access */

    /* TIM2: APB1 timers run at 2 x 50 MHz; /100 → 1 MHz, free-running 32 bits. */
    REG(TIM_PSC) = board_sys_hz / 1000000u - 1u;   /* on the HSI: APB1 and its timers at 16 MHz */
    REG(TIM_ARR) = 0xFFFFFFFFu;
    REG(TIM_EGR) = 1u;   /* load the prescaler */
    REG(TIM_CR1) = 1u;

    /* USART1 TX on PA9 (AF7), 115200 baud: 100 MHz / 115200 = 868.06 (16x oversampling). */
    stm32_pin_af(STM32_PA(9), 7u);
    REG(USART_BRR) = (board_apb2_hz + 57600u) / 115200u;
    REG(USART_CR1) = USART_CR1_UE | USART_CR1_TE;
    if (note) board_puts(note);
}

uint64_t board_now_us(void)
{
    static uint32_t last, high;
    uint32_t now = REG(TIM_CNT);
    if (now < last) high++;
    last = now;
    return ((uint64_t)high << 32) | now;
}

void board_delay_us(uint32_t us)
{
    uint64_t end = board_now_us() + us + 1u;   /* at least us whole microseconds */
    while (board_now_us() < end) {}
}

void board_puts(const char *s)
{
    for (; *s; s++) {
        while (!(REG(USART_SR) & USART_SR_TXE)) {}
        REG(USART_DR) = (uint8_t)*s;
    }
    while (!(REG(USART_SR) & USART_SR_TC)) {}
}
