#!/bin/bash
# Lathe cycle geometry: line/arc intersections, monotonic split, level crossings, offset envelope.
"$EMC2_HOME/objects/unit/lathe_geom_unit"
