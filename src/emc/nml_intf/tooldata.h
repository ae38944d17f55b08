/* tooldata.h: the tool table task publishes for user interfaces, in an instance-keyed shared segment. */
#ifndef TOOLDATA_H
#define TOOLDATA_H

#include <stddef.h>
#include <stdint.h>

#include "emc_enums.h"
#include "emcpos.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SysV base key of the segment; the key used is rtapi_instance_key(TOOLDATA_BASE_KEY). */
#define TOOLDATA_BASE_KEY 0x00544F4C
/* Entries the segment holds: index 0 is the tool in the spindle (CANON_POCKETS_MAX). */
#define TOOLDATA_MAX_ENTRIES CANON_POCKETS_MAX
/* Bytes of a comment, NUL included (the text after ';' in the tool table, stripped). */
#define TOOLDATA_COMMENT_LEN 128

/* One tool-table entry; toolno -1 = empty. Units: machine units, angles in degrees. */
typedef struct tooldata_entry {
    int32_t toolno;
    int32_t pocketno;
    EmcPose offset;
    double diameter;
    double frontangle;
    double backangle;
    int32_t orientation;
    char comment[TOOLDATA_COMMENT_LEN];
} tooldata_entry_t;

typedef struct tooldata tooldata_t;

/* An empty entry (toolno -1, everything else 0). */
tooldata_entry_t tooldata_empty_entry(void);

/* Attach to this instance's segment, or create it when create != 0 (the creator removes it
 * again in tooldata_close). NULL on failure with errno set (ENOENT: not created yet) and
 * err filled. linuxcncsvr creates it; task and UIs attach. */
tooldata_t *tooldata_open(int create, char *err, size_t errlen);
/* Detach (and remove the segment when this handle created it). NULL is fine. */
void tooldata_close(tooldata_t *td);

/* Writer (task): replace the table with entries[0..count-1]. 0 or -EINVAL (count out of
 * 1..TOOLDATA_MAX_ENTRIES). Readers never see a half-written table. */
int tooldata_publish(tooldata_t *td, const tooldata_entry_t *entries, int count);
/* Writer: set entry idx (the table grows to idx + 1 entries when needed). 0 or -EINVAL. */
int tooldata_put(tooldata_t *td, int idx, const tooldata_entry_t *entry);

/* Reader: copy up to max entries; returns the number of entries in the table (may be more
 * than max) or -errno. *generation (may be NULL) gets the table's generation, which changes
 * with every publish/put, so readers can keep a copy until it changes. */
int tooldata_read(tooldata_t *td, tooldata_entry_t *out, int max, uint64_t *generation);
/* Reader: entry idx into *out; 0, or -ENOENT when idx is past the table. */
int tooldata_get(tooldata_t *td, int idx, tooldata_entry_t *out);
/* Reader: the entry of tool number toolno (index > 0); its index, or -ENOENT. */
int tooldata_find(tooldata_t *td, int toolno, tooldata_entry_t *out);
/* Current generation (0 = never published). */
uint64_t tooldata_generation(const tooldata_t *td);
/* 1 while the segment is current, 0 once its creator removed it (reopen to reattach). */
int tooldata_alive(const tooldata_t *td);

#ifdef __cplusplus
}
#endif

#endif
