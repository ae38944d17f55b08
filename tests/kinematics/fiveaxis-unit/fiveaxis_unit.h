/* fiveaxis_unit.h: shared declarations of the 5-axis kinematics unit test. */
#ifndef FIVEAXIS_UNIT_H
#define FIVEAXIS_UNIT_H

/* Round trips over grids of poses for every machine; prints one line per machine. */
void roundtrip_all(void);

#endif
