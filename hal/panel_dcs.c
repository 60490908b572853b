/* SPDX-License-Identifier: MIT */
/* panel_dcs.c — the MIPI DCS command set, the one the generic driver
 * (panel.c) sends unless a descriptor names another. */
#include "panel.h"

/* SLPIN/SLPOUT: 5 ms before the next command, and 120 ms between SLPOUT and
 * a following SLPIN (and back) on the controllers here. Waiting 120 ms after
 * either covers all cases. */
const struct panel_ctl panel_ctl_dcs = {
    .name = "MIPI DCS",
    .set_cols = DCS_CASET,
    .set_rows = DCS_RASET,
    .addr_bytes = 2,
    .write_mem = DCS_RAMWR,
    .orient = DCS_MADCTL,
    .inv_on = DCS_INVON,
    .te_on = DCS_TEON,
    .inv_off = DCS_INVOFF,
    .disp_on = DCS_DISPON,
    .disp_off = DCS_DISPOFF,
    .sleep_in = DCS_SLPIN,
    .sleep_out = DCS_SLPOUT,
    .sleep_wait_ms = 120,
};
