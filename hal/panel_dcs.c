/* SPDX-License-Identifier: MIT */
/* panel_dcs.c — the MIPI DCS command set, the one the generic driver
 * (panel.c) sends unless a descriptor names another. */
#include "panel.h"

/* SLPIN/SLPOUT: 5 ms before the next command, and 120 ms between SLPOUT and
 * a following SLPIN (and back) on the controllers here. Waiting 120 ms after
 * either covers all cases. */
const struct panel_ctl panel_ctl_dcs = {
    .name = "MIPI DCS",
    PANEL_CTL_DCS_FIELDS,
};
