component matrix_kb "Decode keypad key codes into one pin per key, or scan a key matrix itself";
modparam dummy config "config=RxC[s],... one entry per instance: R rows and C columns (1 to 8 each); a trailing s makes the instance scan the matrix itself.";
modparam dummy names "names=name1,... instance names (default matrix_kb.0, matrix_kb.1, ...); as many names as config entries.";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Turns key events of a matrix keypad into one HAL bit per key. Each instance is
either a decoder, fed with key codes by hardware that scans the keypad itself (such as a
Mesa 7i73), or a scanner (config entry ending in s) that drives the rows and reads the
columns of a keypad wired to plain I/O pins and produces the same key codes.

Key codes: a key's number is (row << B) + column, where B is the number of bits needed
for a column number (0 for 1 column, 1 for 2, 2 for 3 or 4, 3 for 5 to 8). A key-down event
is 0xC0 + number, a key-up event is 0x80 + number, and 0x40 means all keys are up.
Other codes, and numbers outside the configured matrix, are ignored.

Pins and params of an instance named P with R rows and C columns:
  P.key.rRcC   bit out  TRUE while the key at row R, column C is down (one per key)
  P.keycode    u32 in   (decoder) key code to decode; it is applied every period
  P.keycode    u32 out  (scanner) the latest key event, 0 until the first event
  P.row-NN-out bit out  (scanner) row drive outputs, NN = 00 .. R-1 (all FALSE until the
                        first period)
  P.col-NN-in  bit in   (scanner) column inputs, NN = 00 .. C-1
  P.negative-logic bit rw (param, default TRUE) scanner: the selected row is driven FALSE
                        (others TRUE) and a FALSE column input means a pressed key
  P.key_rollover u32 rw (param, with an underscore as in LinuxCNC, default 2) scanner: most
                        keys held down at once; further presses are ignored until a key is
                        released (values below 1 act as 1)
The funct is named P.

Scanning: each period the scanner reads the columns of the row it drove in the previous
period (so the read function must run before it and the write function after it in the
thread), reports at most one change of that row (the first changed column) as a key
event, then selects the next row. Other changes of that row are reported on its next
visit, so no event is lost. A full scan takes R periods. When negative-logic is changed
the scanner re-drives the rows and skips reading for one period.""";
