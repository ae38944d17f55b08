#!/bin/bash
# Drive lcd with the fake-HAL harness; runs of traced bytes are printed as text (<HH> for
# bytes outside ASCII 32..126) so expected shows the exact byte stream.
"$EMC2_HOME/objects/unit/comptest" < script | awk '
/^[0-9]+$/ { v = $1 + 0; s = s ((v >= 32 && v < 127) ? sprintf("%c", v) : sprintf("<%02X>", v)); next }
{ if (s != "") { print s; s = "" } print }
END { if (s != "") print s }'
