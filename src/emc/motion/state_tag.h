/* state_tag.h: the interpreter state carried with each queued motion segment, reported while it runs. */
#ifndef STATE_TAG_H
#define STATE_TAG_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Array sizes of EMC_TASK_STAT activeGCodes / activeMCodes / activeSettings (nml.md sec. 5). */
#define STATE_TAG_GCODES 17
#define STATE_TAG_MCODES 10
#define STATE_TAG_SETTINGS 5

/* Set in state_tag_t.flags when the tag was filled in by task (an empty tag is all zero). */
#define STATE_TAG_VALID 0x1u

/* What the interpreter had in force when it emitted the segment: task shows these
 * (instead of the interpreter's read-ahead state) while the segment executes. */
typedef struct state_tag {
    uint32_t flags;                        /* STATE_TAG_* bits */
    int32_t line_number;                   /* source line of the block */
    int32_t gcodes[STATE_TAG_GCODES];      /* G code x10 per slot, -1 none (nml.md layout) */
    int32_t mcodes[STATE_TAG_MCODES];      /* M code per slot, -1 none */
    double settings[STATE_TAG_SETTINGS];   /* sequence, F, S, G64 P, G64 Q */
} state_tag_t;

#ifdef __cplusplus
}
#endif

#endif
