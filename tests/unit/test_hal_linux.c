/* SPDX-License-Identifier: MIT */
/* What the Linux backend does without hardware: clear one-line errors. */
#include <string.h>
#include "check.h"
#include "linux/hal_linux.h"

int main(void)
{
    struct hal_linux l;
    struct hal h;
    struct hal_linux_config cfg;
    hal_linux_default_config(&cfg);
    check(strcmp(cfg.spi_dev, "/dev/spidev0.0") == 0 && cfg.dc == 25 && cfg.cs == -1,
          "hal_linux_default_config_is_raspberry_pi", "%s dc %d", cfg.spi_dev, cfg.dc);
    cfg.spi_dev = "/nonexistent/spidev9.9";
    int rc = hal_linux_open(&l, &h, &cfg);
    check(rc == -1 && strcmp(hal_linux_error(&l),
          "hal_linux: cannot open /nonexistent/spidev9.9: No such file or directory") == 0,
          "hal_linux_missing_spidev_is_one_line_error", "rc %d: %s", rc, hal_linux_error(&l));
    check(l.fd == -1 && l.chip == NULL, "hal_linux_failed_open_leaves_nothing_open", "fd %d", l.fd);
    cfg.spi_dev = "/dev/null";  /* opens, but is no spidev */
    rc = hal_linux_open(&l, &h, &cfg);
    check(rc == -1 && strncmp(hal_linux_error(&l), "hal_linux: cannot configure /dev/null: ", 39) == 0,
          "hal_linux_not_a_spidev_is_one_line_error", "rc %d: %s", rc, hal_linux_error(&l));
    check(l.fd == -1, "hal_linux_closes_after_configure_failure", "fd %d", l.fd);
    cfg.spi_mode = 4;
    rc = hal_linux_open(&l, &h, &cfg);
    check(rc == -1 && strcmp(hal_linux_error(&l), "hal_linux: SPI mode 4 out of range 0..3") == 0,
          "hal_linux_rejects_bad_spi_mode", "rc %d: %s", rc, hal_linux_error(&l));
#ifdef WITH_GPIOD
#if GPIOD_API_MAJOR >= 2
    check(1, "hal_linux_libgpiod_api_2", "");
#else
    check(1, "hal_linux_libgpiod_api_1", "");
#endif
#endif
    return check_exit();
}
