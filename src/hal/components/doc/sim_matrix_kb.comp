component sim_matrix_kb "Turn 64 simulated key buttons into matrix-keypad scan codes";
modparam dummy count "Number of instances (default 1)";
modparam dummy names "Names of the instances (instead of count)";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Simulates a keypad that scans itself (such as a Mesa 7i73), as LinuxCNC's
sim_matrix_kb: each instance P watches 64 bit inputs P.button.cCC.rRR (column and row
00 to 07), typically driven by on-screen buttons, and emits on the u32 output P.out the
scan codes a matrix_kb decoder expects. The key number of button.cCC.rRR is
8 * row + column. The funct is named P.

Each period the keys are scanned row by row (row 0 first, columns 0 to 7 within a row).
The first key whose button differs from its last reported state is reported: out is its
number | 0xC0 for a press or | 0x80 for a release, and "row: R column: C code: N" is
printed. Only one change is reported per period; the others follow in the next periods.
In a period without a change out is 0 when all keys are up and 0x40 (64) otherwise.""";
