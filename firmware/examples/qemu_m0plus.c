/* SPDX-License-Identifier: MIT */
/* qemu_m0plus.c — runs panel_demo on qemu's mps2-an385 board, Cortex-M0+
 * code: tools/bench's start-up code (vector table, .data and .bss) calls
 * bench_main, and newlib's rdimon sends stdout and stderr to the host by
 * semihosting (mk/examples.mk builds panel_demo.c with -Dmain=panel_demo_main).
 * On a real board this file is the board's start-up and its main. */
void initialise_monitor_handles(void);
int panel_demo_main(void);
int bench_main(void);

int bench_main(void)
{
    initialise_monitor_handles();
    return panel_demo_main();
}
