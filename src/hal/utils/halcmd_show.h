/* halcmd_show.h: listing sections shared by show, list and save. */
#ifndef HALCMD_SHOW_H
#define HALCMD_SHOW_H

#include <stddef.h>

const char *hc_dir_name(int dir);
const char *hc_sig_arrow(int dir);
void hc_show_value(int type, const void *cell, char *buf, size_t size);
void hc_show_comps(char *pat[], int npat);
void hc_show_pins(int type, char *pat[], int npat);
void hc_show_params(int type, char *pat[], int npat);
void hc_show_sigs(int type, char *pat[], int npat);
void hc_show_pin_aliases(char *pat[], int npat);
void hc_show_param_aliases(char *pat[], int npat);
void hc_show_functs(char *pat[], int npat);
void hc_show_threads(char *pat[], int npat);

#endif
