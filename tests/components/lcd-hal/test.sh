#!/bin/bash
# Run lcd.hal under halrun; the sampled bytes are printed as text (<HH> outside ASCII 32..126).
halrun -f lcd.hal | awk '{ v = $1 + 0; s = s ((v >= 32 && v < 127) ? sprintf("%c", v) : sprintf("<%02X>", v)) }
END { print s }'
