/* halcmd_complete.h: completion candidate lists. */
#ifndef HALCMD_COMPLETE_H
#define HALCMD_COMPLETE_H

typedef struct {
    char **names;
    int count, cap;
} hc_cands_t;

void hc_complete_word(hc_cands_t *c, int index, const char *cmd, const char *prefix);
void hc_cands_free(hc_cands_t *c);

#endif
