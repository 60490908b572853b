/* SPDX-License-Identifier: MIT */
/* fw_start.h — what every app does first: the boot line on the UART and
 * the panel brought up at the image's size. */
#ifndef FW_START_H
#define FW_START_H

#include <stdint.h>
#include "fw_board.h"
#include "fw_text.h"
#include "panel.h"

/* "boot board=B cores=C cpu_hz=H spi_hz=S size=WxH strip_rows=R scenes=N". */
static inline void fw_boot_line(unsigned cores, uint32_t w, uint32_t h, uint32_t strip_rows, uint32_t scenes)
{
    char line[160], *p;
    p = put_str(put_str(line, "boot board="), fw_board_name);
    p = put_str(put_u32(put_str(p, " cores="), cores), " cpu_hz=");
    p = put_u32(p, fw_board_cpu_hz());
    p = put_u32(put_str(p, " spi_hz="), fw_board_spi_hz());
    p = put_str(put_u32(put_str(p, " size="), w), "x");
    p = put_u32(p, h);
    p = put_u32(put_str(p, " strip_rows="), strip_rows);
    p = put_str(put_u32(put_str(p, " scenes="), scenes), "\r\n");
    *p = 0;
    fw_board_puts(line);
}

/* panel_init, and the panel at w x h in that rotation: 0, or -1 after an
 * error line on the UART. */
static inline int fw_panel_start(struct panel *pn, const struct panel_desc *d, const struct hal *h, uint8_t rotation,
                                 uint16_t w, uint16_t ht)
{
    if (panel_init(pn, d, h, rotation) != 0) {
        fw_board_puts("error panel_init failed\r\n");
        return -1;
    }
    if (pn->width != w || pn->height != ht) {
        fw_board_puts("error the panel in this rotation is not FW_WIDTH x FW_HEIGHT\r\n");
        return -1;
    }
    return 0;
}

#endif
